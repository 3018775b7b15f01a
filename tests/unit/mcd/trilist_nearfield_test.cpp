// trilist_nearfield_test.cpp: models against a triangle list: a flat floor
// of two triangles (the square [-5, 5]^2 at z = 0 cut along its diagonal),
// the flags (smallest penetration, sharp edges, two-sided), a callback that
// returns too many triangles, and the other shapes on the floor.
#include "nearfield_support.h"

#include <random>

using namespace mcd_test;

namespace {

constexpr double kEps = 2e-4;

MeVector3 gCorner[4] = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
MeVector3 gUp = {0, 0, 1};
int gFlags[2] = {kMcdTriangleStandard, kMcdTriangleStandard};
int gTriangles = 2;  // how many the callback fills
int gClaim = 2;      // what it returns

// T0 = c0 c1 c2 (edges: c0c1 outer, c1c2 outer, c2c0 the diagonal),
// T1 = c0 c2 c3 (edges: c0c2 the diagonal, c2c3 outer, c3c0 outer).
int MEAPI Floor(McdModelPair *, McdUserTriangle *t, MeVector3, MeReal, int max) {
  const int idx[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int i = 0; i < gTriangles && i < max; ++i) {
    for (int k = 0; k < 3; ++k) t[i].vertices[k] = &gCorner[idx[i][k]];
    t[i].normal = &gUp;
    t[i].flags = gFlags[i];
  }
  return gClaim;
}

// The diagonal is a triangulation artefact: not sharp.
void SmoothDiagonal() {
  gFlags[0] = kMcdTriangleStandard & ~kMcdTriangleUseEdge2;
  gFlags[1] = kMcdTriangleStandard & ~kMcdTriangleUseEdge0;
  gTriangles = gClaim = 2;
}

struct FloorFixture : ::testing::Test {
  Framework fw{16, 64};
  McdGeometryID list = nullptr;
  std::unique_ptr<Placed> floor;
  void SetUp() override {
    MeVector3 mn = {-5, -5, -1}, mx = {5, 5, 0};
    list = McdTriangleListCreate(fw, mn, mx, 2, Floor);
    floor = std::make_unique<Placed>(list, 0, 0, 0);
    SmoothDiagonal();
  }
  void TearDown() override { floor.reset(); }
};

TEST_F(FloorFixture, SphereOneContactAcrossTheDiagonal) {
  Placed ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)0.9);  // right on the diagonal
  Hit h(ball.model, floor->model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.contacts[0].separation, -0.1, kEps);
  EXPECT_NEAR(h.contacts[0].normal[2], 1, kEps);
  EXPECT_NEAR(h.contacts[0].position[2], -0.05, kEps);
  for (MeReal off : {(MeReal)0.01, (MeReal)-0.01, (MeReal)0.3}) {  // either side of it
    ball.moveTo(off, -off, (MeReal)0.9);
    Hit o(ball.model, floor->model);
    ASSERT_EQ(o.count(), 1) << off;
    EXPECT_NEAR(o.contacts[0].normal[2], 1, kEps);
    EXPECT_NEAR(o.contacts[0].separation, -0.1, kEps);
  }
  expectMirrored(ball.model, floor->model, kEps);
  ball.moveTo(0, 0, (MeReal)1.1);
  EXPECT_EQ(Hit(ball.model, floor->model).touch, 0);
}

TEST_F(FloorFixture, BoxFourContactsAcrossTheDiagonal) {
  Placed box(McdBoxCreate(fw, 1, 1, 1), (MeReal)0.2, 0, (MeReal)0.45);
  Hit h(box.model, floor->model);
  ASSERT_EQ(h.count(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(h.contacts[i].separation, -0.05, kEps);
    EXPECT_NEAR(h.contacts[i].normal[2], 1, kEps);
    EXPECT_NEAR(std::fabs(h.contacts[i].position[0] - 0.2), 0.5, kEps);
  }
  expectMirrored(box.model, floor->model, kEps);
  // A hull cube, a standing cylinder and a lying sphyl on the same floor.
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f);
  Placed hull(McdConvexMeshCreateHull(fw, c, 8, 0), 0, 0, (MeReal)0.45);
  EXPECT_EQ(Hit(hull.model, floor->model).count(), 4);
  Placed can(McdCylinderCreate(fw, (MeReal)0.5, 1), 0, 0, (MeReal)0.45);
  Hit hc(can.model, floor->model);
  EXPECT_EQ(hc.count(), 4);  // four of the cap's rim samples
  EXPECT_NEAR(hc.deepest(), -0.05, kEps);
  Placed caps(McdSphylCreate(fw, (MeReal)0.5, 2), 0, 0, (MeReal)0.45);
  caps.rotate(0, 1, 0, (MeReal)(ME_PI / 2));
  Hit hs(caps.model, floor->model);
  EXPECT_EQ(hs.count(), 2);
  EXPECT_NEAR(hs.deepest(), -0.05, kEps);
}

TEST_F(FloorFixture, EdgeFlagsChangeTheNormalAtAnEdge) {
  gTriangles = gClaim = 1;                                            // T0 alone; its edge 0 runs along y = -5
  Placed ball(McdSphereCreate(fw, 1), 0, (MeReal)-5.6, (MeReal)0.6);  // over the edge, outside
  gFlags[0] = kMcdTriangleStandard;
  Hit sharp(ball.model, floor->model);
  ASSERT_EQ(sharp.count(), 1);
  const double r = std::sqrt(0.72);
  EXPECT_NEAR(sharp.contacts[0].separation, r - 1, kEps);
  EXPECT_NEAR(sharp.contacts[0].normal[1], -std::sqrt(0.5), kEps);  // the edge normal
  EXPECT_NEAR(sharp.contacts[0].normal[2], std::sqrt(0.5), kEps);
  gFlags[0] = kMcdTriangleStandard & ~kMcdTriangleUseSmallestPenetration;
  Hit face(ball.model, floor->model);
  ASSERT_EQ(face.count(), 1);
  EXPECT_NEAR(face.contacts[0].normal[2], 1, kEps);  // the face normal
  gFlags[0] = kMcdTriangleStandard & ~kMcdTriangleUseEdge0;
  EXPECT_EQ(Hit(ball.model, floor->model).count(), 0);  // a smooth edge: no edge contact
  // A box tipped over the sharp edge: the edge normal; smooth: the face normal.
  Placed box(McdBoxCreate(fw, 1, 1, 1), 0, (MeReal)-5.45, (MeReal)0.2);  // the edge 0.04 in
  box.rotate(1, 0, 0, (MeReal)(ME_PI / 4));
  gFlags[0] = kMcdTriangleStandard;
  Hit bs(box.model, floor->model);
  ASSERT_GE(bs.count(), 1);
  EXPECT_LT(bs.r.normal[2], 0.99);
  gFlags[0] = kMcdTriangleStandard & ~kMcdTriangleUseEdge0;
  Hit bf(box.model, floor->model);
  ASSERT_GE(bf.count(), 1);
  EXPECT_NEAR(bf.r.normal[2], 1, kEps);
  expectSane(bs);
  expectSane(bf);
}

TEST_F(FloorFixture, OneSidedPushesUpTwoSidedPushesAway) {
  Placed ball(McdSphereCreate(fw, 1), 1, -2, (MeReal)-0.5);  // under T0
  gFlags[0] = gFlags[1] = kMcdTriangleStandard & ~kMcdTriangleTwoSided;
  Hit one(ball.model, floor->model);
  ASSERT_EQ(one.count(), 1);
  EXPECT_NEAR(one.contacts[0].normal[2], 1, kEps);
  EXPECT_NEAR(one.contacts[0].separation, -1.5, kEps);
  gFlags[0] = gFlags[1] = kMcdTriangleStandard;
  Hit two(ball.model, floor->model);
  ASSERT_EQ(two.count(), 1);
  EXPECT_NEAR(two.contacts[0].normal[2], -1, kEps);
  EXPECT_NEAR(two.contacts[0].separation, -0.5, kEps);
  // A box under the floor likewise.
  Placed box(McdBoxCreate(fw, 1, 1, 1), 1, -2, (MeReal)-0.45);
  gFlags[0] = gFlags[1] = kMcdTriangleStandard & ~kMcdTriangleTwoSided;
  Hit b1(box.model, floor->model);
  ASSERT_GE(b1.count(), 1);
  EXPECT_NEAR(b1.r.normal[2], 1, kEps);
  EXPECT_NEAR(b1.deepest(), -0.95, kEps);
  gFlags[0] = gFlags[1] = kMcdTriangleStandard;
  Hit b2(box.model, floor->model);
  EXPECT_NEAR(b2.r.normal[2], -1, kEps);
  EXPECT_NEAR(b2.deepest(), -0.05, kEps);
}

TEST_F(FloorFixture, CallbackReturningTooManyIsClamped) {
  gClaim = 7;  // fills 2, claims 7 > triangleMaxCount 2
  Placed ball(McdSphereCreate(fw, 1), 1, -1, (MeReal)0.9);
  WarningCapture w;
  Hit h(ball.model, floor->model);
  EXPECT_GE(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("triangleMaxCount"));
  EXPECT_EQ(h.count(), 1);
  gClaim = -3;
  Hit none(ball.model, floor->model);
  EXPECT_EQ(none.count(), 0);
  // The program raises the limit directly, as the QuadBike code does.
  ((McdTriangleList *)list)->triangleMaxCount = 8;
  gClaim = 2;
  EXPECT_EQ(Hit(ball.model, floor->model).count(), 1);
}

TEST_F(FloorFixture, StoolOnTheTriangleFloor) {
  static TM legTM[4] = {TM(1, 1, 0), TM(1, -1, 0), TM(-1, 1, 0), TM(-1, -1, 0)};
  McdGeometryID agg = McdAggregateCreate(fw, 4);
  McdGeometryID leg = McdCylinderCreate(fw, (MeReal)0.1, 2);
  for (auto &tm : legTM) McdAggregateAddElement(agg, leg, tm);
  Placed stool(agg, 0, 0, (MeReal)0.99);
  Hit h(stool.model, floor->model);
  EXPECT_EQ(h.count(), 16);  // 4 rim samples under each leg
  EXPECT_NEAR(h.deepest(), -0.01, kEps);
  for (int i = 0; i < h.count(); ++i) EXPECT_NE(h.contacts[i].element1.ptr, nullptr);
}

TEST_F(FloorFixture, TurnedListAndRandomPoses) {
  // The list's model turned so its floor faces world +y: triangles go to world.
  floor->rotate(1, 0, 0, (MeReal)(-ME_PI / 2));
  floor->moveTo(0, 1, 0);
  Placed ball(McdSphereCreate(fw, 1), 2, (MeReal)1.8, -2);
  Hit h(ball.model, floor->model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.contacts[0].normal[1], 1, kEps);
  EXPECT_NEAR(h.contacts[0].separation, -0.2, kEps);
  // Random poses of every shape near the turned floor: sane and mirrored.
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (i & 1) ? 0.4f : -0.4f, (i & 2) ? 0.6f : -0.6f, (i & 4) ? 0.3f : -0.3f);
  McdGeometryID geoms[] = {McdSphereCreate(fw, (MeReal)0.5), McdBoxCreate(fw, 1, (MeReal)0.6, (MeReal)1.4),
                           McdCylinderCreate(fw, (MeReal)0.4, 1), McdSphylCreate(fw, (MeReal)0.3, 1),
                           McdConvexMeshCreateHull(fw, c, 8, 0)};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int touching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    gFlags[0] = gFlags[1] = (trial / 5) % 32;  // every flag combination
    Placed m(geoms[trial % 5], (MeReal)(5 * u(rng)), (MeReal)(1 + 0.8 * u(rng)), (MeReal)(5 * u(rng)));
    m.rotate((MeReal)u(rng), (MeReal)u(rng), (MeReal)u(rng) + 2, (MeReal)(3 * u(rng)));
    Hit t(m.model, floor->model);
    expectSane(t);
    touching += t.touch;
    expectMirrored(m.model, floor->model, 1e-5);
  }
  EXPECT_GT(touching, 40);
}

}  // namespace
