// aggregate_nearfield_test.cpp: aggregates against other models child by
// child: the stool (four leg cylinders and a seat box, each element with
// its own relTM) standing on the ground, nesting, aggregate-aggregate, the
// element tags and contactMaxCount.
#include "nearfield_support.h"

#include <random>

using namespace mcd_test;

namespace {

constexpr double kEps = 2e-4;

// The guide's stool, with one relTM per element (the aggregate keeps the
// pointers): seat 2.2 x 2.2 x 0.1 at z = 1, legs r 0.1, h 2 at (+-1, +-1, 0).
struct Stool {
  TM seatTM{0, 0, 1};
  TM legTM[4] = {TM(1, 1, 0), TM(1, -1, 0), TM(-1, 1, 0), TM(-1, -1, 0)};
  McdGeometryID g;
  explicit Stool(McdFrameworkID fw) : g(McdAggregateCreate(fw, 5)) {
    McdAggregateAddElement(g, McdBoxCreate(fw, (MeReal)2.2, (MeReal)2.2, (MeReal)0.1), seatTM);
    McdGeometryID leg = McdCylinderCreate(fw, (MeReal)0.1, 2);
    for (auto &tm : legTM) McdAggregateAddElement(g, leg, tm);
  }
};

TEST(McdAggregateNearfield, StoolStandsOnEachLeg) {
  Framework fw(16, 64);
  Stool stool(fw);
  Placed s(stool.g, 3, 4, (MeReal)0.99);  // legs 0.01 into the ground (z = 0)
  Placed ground(McdBoxCreate(fw, 20, 20, 2), 0, 0, -1);
  Hit h(s.model, ground.model);
  ASSERT_EQ(h.touch, 1);
  ASSERT_EQ(h.count(), 16);  // 4 of the 8 rim samples under each of the 4 legs
  McdGeometryInstanceID top = McdModelGetGeometryInstance(s.model);
  int perLeg[5] = {};
  for (int i = 0; i < h.count(); ++i) {
    const McdContact &c = h.contacts[i];
    EXPECT_NEAR(c.separation, -0.01, kEps);
    EXPECT_NEAR(c.normal[2], 1, kEps);
    for (int k = 0; k < 5; ++k)
      if (c.element1.ptr == McdGeometryInstanceGetChild(top, k)) ++perLeg[k];
    // Under a leg: within 0.1 of (3 +- 1, 4 +- 1).
    EXPECT_NEAR(std::fabs(c.position[0] - 3), 1, 0.1 + kEps);
    EXPECT_NEAR(std::fabs(c.position[1] - 4), 1, 0.1 + kEps);
  }
  EXPECT_EQ(perLeg[0], 0);  // the seat is up in the air
  for (int k = 1; k < 5; ++k) EXPECT_EQ(perLeg[k], 4) << "leg " << k;
  expectMirrored(s.model, ground.model, kEps);
  // The buffer holds 6: the deepest 6 are kept.
  s.rotate(1, 0, 0, (MeReal)0.001);
  Hit few(s.model, ground.model, 6);
  EXPECT_EQ(few.count(), 6);
  // On a plane: the legs' cylinder-plane interaction (when built) does the same.
  Placed floor(McdPlaneCreate(fw), 0, 0, 0);
  if (McdFrameworkGetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypePlane)) {
    Hit p(s.model, floor.model);
    EXPECT_GE(p.count(), 4);
  }
  // Upside down, seat 0.02 into the plane (box-plane): the seat's corners.
  s.rotate(1, 0, 0, (MeReal)ME_PI);
  s.moveTo(3, 4, (MeReal)1.03);  // seat top at 1.03 - 1.05 = -0.02
  Hit seat(s.model, floor.model);
  ASSERT_EQ(seat.count(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(seat.contacts[i].element1.ptr, McdGeometryInstanceGetChild(top, 0));
    EXPECT_NEAR(seat.contacts[i].separation, -0.02, kEps);
  }
}

TEST(McdAggregateNearfield, NestedAndAggregateAgainstAggregate) {
  Framework fw(16, 64);
  Stool stool(fw);
  static TM inner(0, 0, 0), lifted(0, 0, 0);
  McdGeometryID outer = McdAggregateCreate(fw, 1);
  ASSERT_EQ(McdAggregateAddElement(outer, stool.g, inner), 0);  // a stool inside an aggregate
  Placed nested(outer, 0, 0, (MeReal)0.99);
  Placed ground(McdBoxCreate(fw, 20, 20, 2), 0, 0, -1);
  Hit h(nested.model, ground.model);
  ASSERT_EQ(h.count(), 16);  // 4 rim samples under each leg
  McdGeometryInstanceID mid = McdGeometryInstanceGetChild(McdModelGetGeometryInstance(nested.model), 0);
  for (int i = 0; i < h.count(); ++i) {  // the leaf instance, two levels down
    bool leg = false;
    for (int k = 1; k < 5; ++k) leg |= h.contacts[i].element1.ptr == McdGeometryInstanceGetChild(mid, k);
    EXPECT_TRUE(leg);
  }
  // Aggregate against aggregate: a one-hull aggregate (a unit cube) resting
  // on the stool's seat (convex mesh against box).
  McdGeometryID block = McdAggregateCreate(fw, 1);
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f);
  McdGeometryID cube = McdConvexMeshCreateHull(fw, c, 8, 0);
  McdAggregateAddElement(block, cube, lifted);
  Placed b(block, 0, 0, (MeReal)(0.99 + 1.05 + 0.5 - 0.01));  // 0.01 into the seat top
  Placed st(stool.g, 0, 0, (MeReal)0.99);
  Hit ab(b.model, st.model);
  ASSERT_EQ(ab.touch, 1);
  EXPECT_EQ(ab.count(), 4);
  EXPECT_NEAR(ab.deepest(), -0.01, kEps);
  McdGeometryInstanceID stTop = McdModelGetGeometryInstance(st.model);
  McdGeometryInstanceID bTop = McdModelGetGeometryInstance(b.model);
  for (int i = 0; i < ab.count(); ++i) {
    EXPECT_EQ(ab.contacts[i].element1.ptr, McdGeometryInstanceGetChild(bTop, 0));
    EXPECT_EQ(ab.contacts[i].element2.ptr, McdGeometryInstanceGetChild(stTop, 0));
    EXPECT_NEAR(ab.contacts[i].normal[2], 1, kEps);
  }
  expectMirrored(b.model, st.model, kEps);
  // Apart: nothing.
  b.moveTo(0, 0, 5);
  EXPECT_EQ(Hit(b.model, st.model).touch, 0);
}

TEST(McdAggregateNearfield, RandomPosesSaneAndMirrored) {
  Framework fw(16, 64);
  Stool stool(fw);
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.3f : -0.3f, (i & 4) ? 0.4f : -0.4f);
  McdGeometryID others[] = {McdSphereCreate(fw, (MeReal)0.5),     McdBoxCreate(fw, 1, 1, 1),
                            McdConvexMeshCreateHull(fw, c, 8, 0), McdCylinderCreate(fw, (MeReal)0.3, 1),
                            McdSphylCreate(fw, (MeReal)0.2, 1),   stool.g};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int touching = 0;
  for (int trial = 0; trial < 120; ++trial) {
    Placed a(stool.g, 0, 0, 0),
        b(others[trial % 6], (MeReal)(1.3 * u(rng)), (MeReal)(1.3 * u(rng)), (MeReal)(1.2 * u(rng)));
    a.rotate((MeReal)u(rng), (MeReal)u(rng), (MeReal)u(rng) + 2, (MeReal)(3 * u(rng)));
    b.rotate((MeReal)u(rng) + 2, (MeReal)u(rng), (MeReal)u(rng), (MeReal)(3 * u(rng)));
    Hit h(a.model, b.model);
    expectSane(h);
    touching += h.touch;
    expectMirrored(a.model, b.model, 1e-5);
  }
  EXPECT_GT(touching, 30);
}

}  // namespace
