// feature_id_test.cpp: McdContact::feature for every interaction family
// (nearfield/feature_id.h): nonzero and distinct within one result, and, for
// a touching pose moved by sub-millimetre shifts and small turns, the same
// set of ids with each contact moving no more than the motion does.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "nearfield_test_support.h"

using namespace mcd_test;

namespace {

// A model whose pose is set absolutely: position, then yaw about z and
// tilts about x and y (applied in that order).
struct Body {
  McdModelID model;
  std::unique_ptr<TM> tm{new TM};
  double x, y, z, yaw, tx, ty;
  Body(McdGeometryID g, double x0, double y0, double z0, double yaw0 = 0, double tx0 = 0, double ty0 = 0)
      : model(McdModelCreate(g)), x(x0), y(y0), z(z0), yaw(yaw0), tx(tx0), ty(ty0) {
    McdModelSetTransformPtr(model, *tm);
    place(0, 0, 0, 0, 0, 0);
  }
  ~Body() { McdModelDestroy(model); }
  Body(const Body &) = delete;
  Body &operator=(const Body &) = delete;
  // The base pose moved by (dx, dy, dz) and turned by (dyaw, dtx, dty).
  void place(double dx, double dy, double dz, double dyaw, double dtx, double dty) {
    MeMatrix3 a, b, c, ab, abc;
    const MeVector3 ez = {0, 0, 1}, ex = {1, 0, 0}, ey = {0, 1, 0};
    MeMatrix3FromAxisAngle(a, ez, (MeReal)(yaw + dyaw));
    MeMatrix3FromAxisAngle(b, ex, (MeReal)(tx + dtx));
    MeMatrix3FromAxisAngle(c, ey, (MeReal)(ty + dty));
    MeMatrix3Multiply(ab, a, b);
    MeMatrix3Multiply(abc, ab, c);
    MeMatrix4TMSetRotation(tm->m, abc);
    MeMatrix4TMSetPosition(tm->m, (MeReal)(x + dx), (MeReal)(y + dy), (MeReal)(z + dz));
    McdModelUpdate(model);
  }
};

struct Result {
  int touch = 0;
  std::vector<McdContact> c;
};

Result intersect(McdModelID a, McdModelID b) {
  McdContact buf[64];
  McdIntersectResult r{};
  r.contacts = buf;
  r.contactMaxCount = 64;
  McdModelPair *pair = McdModelPairCreate(a, b);
  McdHello(pair);
  Result out;
  out.touch = McdIntersect(pair, &r);
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  out.c.assign(buf, buf + r.contactCount);
  return out;
}

// Ids nonzero and distinct; returns id -> position.
std::map<MeU32, std::array<double, 3>> idsOf(const Result &r, const std::string &what) {
  std::map<MeU32, std::array<double, 3>> ids;
  for (const McdContact &c : r.c) {
    EXPECT_NE(c.feature, 0u) << what;
    EXPECT_TRUE(ids.emplace(c.feature, std::array<double, 3>{c.position[0], c.position[1], c.position[2]}).second)
        << what << ": id " << c.feature << " repeated";
  }
  return ids;
}

// The perturbations: shifts of 0.2 mm along each axis (up and down), turns
// of 0.01 degree about each axis, and a few combinations.
const double kShift = 2e-4, kTurn = 1.745e-4;
const double kMoves[][6] = {{kShift, 0, 0, 0, 0, 0},
                            {-kShift, 0, 0, 0, 0, 0},
                            {0, kShift, 0, 0, 0, 0},
                            {0, -kShift, 0, 0, 0, 0},
                            {0, 0, kShift, 0, 0, 0},
                            {0, 0, -kShift, 0, 0, 0},
                            {0, 0, 0, kTurn, 0, 0},
                            {0, 0, 0, -kTurn, 0, 0},
                            {0, 0, 0, 0, kTurn, 0},
                            {0, 0, 0, 0, -kTurn, 0},
                            {0, 0, 0, 0, 0, kTurn},
                            {0, 0, 0, 0, 0, -kTurn},
                            {kShift, -kShift, kShift, kTurn, -kTurn, kTurn},
                            {-kShift, kShift, -kShift, -kTurn, kTurn, -kTurn}};

// `moving` touches `fixed` at its base pose; every perturbation keeps the
// set of ids, and each contact moves by at most `travel`.
void expectStable(Body &moving, McdModelID fixed, int wantCount, const std::string &what, double travel = 2e-3) {
  moving.place(0, 0, 0, 0, 0, 0);
  const Result base = intersect(moving.model, fixed);
  ASSERT_EQ(base.touch, 1) << what;
  if (wantCount > 0) {
    EXPECT_EQ((int)base.c.size(), wantCount) << what;
  }
  const auto ids = idsOf(base, what);
  for (const auto &m : kMoves) {
    moving.place(m[0], m[1], m[2], m[3], m[4], m[5]);
    const Result r = intersect(moving.model, fixed);
    const auto moved = idsOf(r, what);
    ASSERT_EQ(moved.size(), ids.size()) << what << " move " << (&m - kMoves);
    for (const auto &[id, p] : ids) {
      const auto it = moved.find(id);
      ASSERT_NE(it, moved.end()) << what << " move " << (&m - kMoves) << " lost id " << id;
      const double d = std::hypot(it->second[0] - p[0], it->second[1] - p[1], it->second[2] - p[2]);
      EXPECT_LT(d, travel) << what << " move " << (&m - kMoves) << " id " << id;
    }
    // Reversed arguments: the same ids.
    const auto reversed = idsOf(intersect(fixed, moving.model), what + " reversed");
    EXPECT_EQ(reversed.size(), moved.size()) << what;
    for (const auto &kv : moved) EXPECT_EQ(reversed.count(kv.first), 1u) << what << " reversed";
  }
  moving.place(0, 0, 0, 0, 0, 0);
}

McdGeometryID cubeHull(McdFrameworkID fw, double h) {
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (MeReal)((i & 1) ? h : -h), (MeReal)((i & 2) ? h : -h), (MeReal)((i & 4) ? h : -h));
  return McdConvexMeshCreateHull(fw, c, 8, 0);
}

// A hexagonal prism (radius r, half height h): 6 vertices on each face.
McdGeometryID prismHull(McdFrameworkID fw, double r, double h) {
  MeVector3 c[12];
  for (int i = 0; i < 12; ++i) {
    const double a = ME_PI / 3 * (i % 6);
    MeVector3Set(c[i], (MeReal)(r * std::cos(a)), (MeReal)(r * std::sin(a)), (MeReal)(i < 6 ? -h : h));
  }
  return McdConvexMeshCreateHull(fw, c, 12, 0);
}

// Overlap of the resting poses below: 1 mm.
const double kDepth = 1e-3;

TEST(McdFeatureId, BoxOnBoxFaceContactsKeepTheirIds) {
  Framework fw;
  Body base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Body small(McdBoxCreate(fw, 1, 1, 1), 0.3, -0.2, 1 + 0.5 - kDepth, 0.2);
  expectStable(small, base.model, 4, "small box on a big one");
  // Equal boxes turned by every yaw from 1 to 45 degrees: octagons reduced
  // to four. (At exactly 0 the corners coincide, and any turn splits each
  // into two points: the ids of that degenerate pose are not kept.)
  Body lower(McdBoxCreate(fw, 1, 1, 1), 0, 0, 5);
  for (int deg = 1; deg <= 45; ++deg) {
    Body upper(McdBoxCreate(fw, 1, 1, 1), 0.01, 0.02, 6 - kDepth, deg * ME_PI / 180);
    expectStable(upper, lower.model, 4, "equal boxes turned " + std::to_string(deg));
  }
}

TEST(McdFeatureId, EdgeEdgeContactNamesBothEdges) {
  Framework fw;
  // Two long bars crossed at right angles, each turned 45 degrees about its
  // own length so that an edge points at the other's: edge on edge.
  Body lower(McdBoxCreate(fw, 4, (MeReal)0.5, (MeReal)0.5), 0, 0, 0, 0, ME_PI / 4, 0);
  const double reach = 0.25 * std::sqrt(2.0);
  Body upper(McdBoxCreate(fw, (MeReal)0.5, 4, (MeReal)0.5), 0, 0, 2 * reach - kDepth, 0, 0, ME_PI / 4);
  expectStable(upper, lower.model, 1, "crossed edges");
  const Result r = intersect(upper.model, lower.model);
  ASSERT_EQ(r.c.size(), 1u);
  EXPECT_EQ(r.c[0].dims, (MeI16)(1 | (1 << 8)));
  EXPECT_EQ(r.c[0].feature >> 24, 4u);  // feature::kBoxEdge
}

TEST(McdFeatureId, PrimitivePairs) {
  Framework fw;
  Body plane(McdPlaneCreate(fw), 0, 0, 0);
  Body ground(McdBoxCreate(fw, 20, 20, 2), 0, 0, -1);
  {
    Body box(McdBoxCreate(fw, 1, 2, (MeReal)0.5), 0, 0, 0.25 - kDepth, 0.3);
    expectStable(box, plane.model, 4, "box on plane");
  }
  {
    Body ball(McdSphereCreate(fw, (MeReal)0.5), 0, 0, 0.5 - kDepth);
    expectStable(ball, plane.model, 1, "sphere on plane");
    expectStable(ball, ground.model, 1, "sphere on box");
    Body other(McdSphereCreate(fw, (MeReal)0.5), 0, 0, 1.5 - 2 * kDepth);
    expectStable(other, ball.model, 1, "sphere on sphere");
    Body rod(McdSphylCreate(fw, (MeReal)0.2, 1), 0, 0, 1.2 - 2 * kDepth, 0, ME_PI / 2, 0);
    expectStable(rod, ball.model, 1, "sphyl on sphere");
    Body can(McdCylinderCreate(fw, (MeReal)0.3, 1), 0, 0, 1.5 - 2 * kDepth);
    expectStable(can, ball.model, 1, "cylinder on sphere");
  }
  {
    Body rod(McdSphylCreate(fw, (MeReal)0.2, 1), 0, 0, 0.2 - kDepth, 0.4, ME_PI / 2, 0);
    expectStable(rod, plane.model, 2, "lying sphyl on plane");
    expectStable(rod, ground.model, 2, "lying sphyl on box");
    Body rod2(McdSphylCreate(fw, (MeReal)0.2, 1), 0, 0, 0.6 - 2 * kDepth, 0.4, ME_PI / 2, 0);
    expectStable(rod2, rod.model, 2, "parallel sphyls");
  }
  {
    Body can(McdCylinderCreate(fw, (MeReal)0.3, 1), 0, 0, 0.5 - kDepth, 0.1);
    expectStable(can, plane.model, 8, "standing cylinder on plane");
  }
}

TEST(McdFeatureId, ConvexPairs) {
  Framework fw;
  Body plane(McdPlaneCreate(fw), 0, 0, 0);
  Body ground(McdBoxCreate(fw, 20, 20, 2), 0, 0, -1);
  Body cube(cubeHull(fw, 0.5), 0, 0, 0.5 - kDepth, 0.3);
  expectStable(cube, plane.model, 4, "hull cube on plane");
  expectStable(cube, ground.model, 4, "hull cube on box");
  Body prism(prismHull(fw, 0.5, 0.3), 3, 0, 0.3 - kDepth, 0.1);
  expectStable(prism, plane.model, 4, "hexagonal prism on plane");
  expectStable(prism, ground.model, 4, "hexagonal prism on box");
  Body top(cubeHull(fw, 0.5), 0.05, 0.02, 1.5 - 2 * kDepth, 0.5);
  expectStable(top, cube.model, 4, "hull on hull turned");
  Body can(McdCylinderCreate(fw, (MeReal)0.3, 1), 6, 0, 0.5 - kDepth, 0.1);
  expectStable(can, ground.model, 4, "standing cylinder on box");
}

// Two triangles: the square [-5, 5]^2 at z = 0, the diagonal smooth.
MeVector3 gCorner[4] = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
MeVector3 gUp = {0, 0, 1};

int MEAPI Floor(McdModelPair *, McdUserTriangle *t, MeVector3, MeReal, int max) {
  const int idx[2][3] = {{0, 1, 2}, {0, 2, 3}};
  const int flags[2] = {kMcdTriangleStandard & ~kMcdTriangleUseEdge2, kMcdTriangleStandard & ~kMcdTriangleUseEdge0};
  for (int i = 0; i < 2 && i < max; ++i) {
    for (int k = 0; k < 3; ++k) t[i].vertices[k] = &gCorner[idx[i][k]];
    t[i].normal = &gUp;
    t[i].flags = flags[i];
  }
  return 2;
}

TEST(McdFeatureId, TriangleListAndAggregate) {
  Framework fw(16, 64);
  MeVector3 mn = {-5, -5, -1}, mx = {5, 5, 0};
  Body floor(McdTriangleListCreate(fw, mn, mx, 2, Floor), 0, 0, 0);
  Body box(McdBoxCreate(fw, 1, 1, 1), 0.2, 0.1, 0.5 - kDepth, 0.3);  // across the diagonal
  expectStable(box, floor.model, 4, "box on the triangle floor");
  Body ball(McdSphereCreate(fw, (MeReal)0.5), 2, -1, 0.5 - kDepth);
  expectStable(ball, floor.model, 1, "sphere on the triangle floor");
  // A stool: four cylinder legs (one geometry) and a seat.
  static TM legTM[4] = {TM(1, 1, 0), TM(1, -1, 0), TM(-1, 1, 0), TM(-1, -1, 0)};
  static TM seatTM(0, 0, 1);
  McdGeometryID stool = McdAggregateCreate(fw, 5);
  McdAggregateAddElement(stool, McdBoxCreate(fw, (MeReal)2.2, (MeReal)2.2, (MeReal)0.1), seatTM);
  McdGeometryID leg = McdCylinderCreate(fw, (MeReal)0.1, 2);
  for (auto &tm : legTM) McdAggregateAddElement(stool, leg, tm);
  Body s(stool, 0, 0, 1 - kDepth, 0.2);
  expectStable(s, floor.model, 16, "stool on the triangle floor");
  Body ground(McdBoxCreate(fw, 20, 20, 2), 20, 0, -1);
  Body s2(stool, 20, 0, 1 - kDepth, 0.2);
  expectStable(s2, ground.model, 16, "stool on a box");
}

}  // namespace
