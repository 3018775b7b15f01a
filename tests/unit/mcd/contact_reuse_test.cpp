// contact_reuse_test.cpp: McdIntersect's contact reuse (contact_reuse.h):
// a resting pair is served from memory and agrees with a full test, in
// both orders of a mirrored interaction; a drift beyond the reuse
// distance, a turn, a grown tolerance, a resized shape or another cap sends
// the pair back to a full test; a test that finds contacts between the
// tolerance and the slack is done again at the tolerance and not
// remembered; pairs the rule does not serve (a sphere, an application's
// interaction, reuse off) keep no memory, and a call with room for no
// contact still reports touch.
#include <cmath>

#include "contact_reuse.h"
#include "nearfield_test_support.h"

using namespace mcd_test;
using namespace mcd_test::prim;

namespace {

const MeReal kReuse = (MeReal)1e-4;  // the default at length scale 1

// A helloed pair of two models, intersected on demand.
struct Pair {
  McdModelPair *pair;
  McdContact c[16];
  McdIntersectResult r{};
  Pair(McdModelID a, McdModelID b) : pair(McdModelPairCreate(a, b)) { McdHello(pair); }
  ~Pair() {
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
  }
  Pair(const Pair &) = delete;
  Pair &operator=(const Pair &) = delete;
  int intersect(int max = 16) {
    r = McdIntersectResult{};
    r.contacts = c;
    r.contactMaxCount = max;
    McdIntersect(pair, &r);
    return r.contactCount;
  }
  // Whether the rule serves the pair now (at the framework's tolerance),
  // without changing what it remembers.
  bool servable() {
    McdContact scratch[16];
    McdIntersectResult s{};
    s.contacts = scratch;
    s.contactMaxCount = 16;
    const McdFrameworkID fw = McdModelGetFramework(pair->model1);
    return karma::mcd::ServeFromMemory(pair, &s, McdFrameworkGetContactTolerance(fw), 16,
                                       karma::mcd::ReuseDistance(pair),
                                       karma::mcd::PoseOf(pair->model1, pair->model2));
  }
};

// A 2 m cube resting on a 4 x 4 x 2 base, 10 mm deep.
struct RestingBoxes {
  Framework fw;
  Placed base{McdBoxCreate(fw, 4, 4, 2), 0, 0, 0};
  Placed top{McdBoxCreate(fw, 2, 2, 2), (MeReal)0.5, (MeReal)0.3, (MeReal)1.99};
};

// The same contacts (as sets of positions): positions within `far`
// (summed over the axes), separations and normals within `eps`.
void expectSameContacts(const McdIntersectResult &a, const McdIntersectResult &b, double far, double eps) {
  ASSERT_EQ(a.contactCount, b.contactCount);
  for (int i = 0; i < a.contactCount; ++i) {
    double best = 1e30;
    int match = -1;
    for (int j = 0; j < b.contactCount; ++j) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += std::fabs((double)a.contacts[i].position[k] - b.contacts[j].position[k]);
      if (d < best) best = d, match = j;
    }
    EXPECT_LT(best, far) << "contact " << i;
    EXPECT_NEAR(a.contacts[i].separation, b.contacts[match].separation, eps) << "contact " << i;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.contacts[i].normal[k], b.contacts[match].normal[k], eps);
  }
}

// The largest distance (summed over the axes) from a contact of `a` to
// the nearest contact of `b`.
double largestOffset(const McdIntersectResult &a, const McdIntersectResult &b) {
  double largest = 0;
  for (int i = 0; i < a.contactCount; ++i) {
    double best = 1e30;
    for (int j = 0; j < b.contactCount; ++j) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += std::fabs((double)a.contacts[i].position[k] - b.contacts[j].position[k]);
      best = std::fmin(best, d);
    }
    largest = std::fmax(largest, best);
  }
  return largest;
}

// A full test of the two models (reuse off for the call).
struct FullTest {
  McdContact c[16];
  McdIntersectResult r{};
  FullTest(McdFrameworkID fw, McdModelID a, McdModelID b) {
    const MeReal reuse = McdFrameworkGetContactReuseDistance(fw);
    McdFrameworkSetContactReuseDistance(fw, 0);
    Hit h(a, b);
    McdFrameworkSetContactReuseDistance(fw, reuse);
    r = h.r;
    for (int i = 0; i < h.count(); ++i) c[i] = h.c[i];
    r.contacts = c;
  }
};

TEST(McdContactReuse, TheDistanceDefaultsToATenThousandthOfTheLengthScaleAndRejectsBadValues) {
  Framework fw(32, 64, 2);
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(fw), (MeReal)2e-4);
  McdFrameworkSetContactReuseDistance(fw, (MeReal)0.003);
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(fw), (MeReal)0.003);
  WarningCapture w;
  McdFrameworkSetContactReuseDistance(fw, -1);
  McdFrameworkSetContactReuseDistance(fw, std::nan(""));
  EXPECT_EQ(w.count(), 2);
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(fw), (MeReal)0.003);
}

TEST(McdContactReuse, ARestingPairIsServedAndAgreesWithAFullTest) {
  RestingBoxes s;
  Pair p(s.top.model, s.base.model);
  ASSERT_EQ(p.intersect(), 4);
  EXPECT_TRUE(p.servable());
  // Moved down and sideways by 5e-5 m, less than the reuse distance:
  // served. The separations follow the motion as a full test's do; a
  // position is the midpoint of the point carried by each model, so it
  // is off a full test's by at most the motion (here half of it).
  s.top.move((MeReal)0.5 + (MeReal)3e-5, (MeReal)0.3, (MeReal)1.99 - (MeReal)4e-5);
  EXPECT_TRUE(p.servable());
  ASSERT_EQ(p.intersect(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(p.c[i].separation, -0.01 - 4e-5, 1e-6);
  const FullTest full(s.fw, s.top.model, s.base.model);
  expectSameContacts(p.r, full.r, 5e-5, 1e-6);
  EXPECT_EQ(p.r.touch, 1);
  // McdIntersect served it: a full test puts the corners where the top box
  // moved them (3e-5 m sideways); the served ones are midpoints.
  EXPECT_GT(largestOffset(p.r, full.r), 1e-5);
}

TEST(McdContactReuse, BothOrdersOfAMirroredInteractionAreServedInTheirOwnOrder) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  // A cylinder (axis z) standing on the base, 5 mm deep.
  Placed can(McdCylinderCreate(fw, (MeReal)0.5, 2), 0, 0, (MeReal)1.995);
  Pair boxFirst(base.model, can.model), canFirst(can.model, base.model);
  ASSERT_GT(boxFirst.intersect(), 0);
  ASSERT_GT(canFirst.intersect(), 0);
  can.move(0, 0, (MeReal)1.995 - (MeReal)3e-5);
  EXPECT_TRUE(boxFirst.servable());
  EXPECT_TRUE(canFirst.servable());
  boxFirst.intersect();
  canFirst.intersect();
  const FullTest fullBoxFirst(fw, base.model, can.model), fullCanFirst(fw, can.model, base.model);
  // The convex manifold places its points using the tolerance it runs at:
  // the remembered test ran at the tolerance plus d, so its points may sit
  // up to d from a test at the tolerance alone, plus the 3e-5 m motion.
  expectSameContacts(boxFirst.r, fullBoxFirst.r, kReuse + 4e-5, 1e-6);
  expectSameContacts(canFirst.r, fullCanFirst.r, kReuse + 4e-5, 1e-6);
  ASSERT_GT(canFirst.r.contactCount, 0);
  EXPECT_NEAR(canFirst.c[0].normal[2], 1, 1e-6);  // from the base towards the cylinder
  EXPECT_NEAR(boxFirst.c[0].normal[2], -1, 1e-6);
  EXPECT_NEAR(canFirst.c[0].separation, -0.005 - 3e-5, 1e-6);
}

TEST(McdContactReuse, AnotherCapIsTestedAgainAndRoomForNoContactStillReportsTouch) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Placed can(McdCylinderCreate(fw, (MeReal)0.5, 2), 0, 0, (MeReal)1.995);
  Pair p(can.model, base.model);
  const int all = p.intersect();
  ASSERT_GT(all, 2);
  EXPECT_EQ(p.intersect(2), 2);  // not the memory's 16: a test with room for 2
  EXPECT_EQ(p.intersect(), all);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(p.intersect(0), 0);
    EXPECT_EQ(p.r.touch, 1) << "call " << i;
  }
}

TEST(McdContactReuse, AShiftBeyondTheDistanceIsTestedAgainAndRemembered) {
  RestingBoxes s;
  Pair p(s.top.model, s.base.model);
  ASSERT_EQ(p.intersect(), 4);
  s.top.move((MeReal)0.5 + 2 * kReuse, (MeReal)0.3, (MeReal)1.99);
  EXPECT_FALSE(p.servable());
  ASSERT_EQ(p.intersect(), 4);  // a full test, remembered at the new pose
  EXPECT_TRUE(p.servable());
  // Small steps add up: each within the distance of the last pose, but
  // together past it from the remembered one.
  s.top.move((MeReal)0.5 + (MeReal)2.6 * kReuse, (MeReal)0.3, (MeReal)1.99);
  EXPECT_TRUE(p.servable());
  p.intersect();
  s.top.move((MeReal)0.5 + (MeReal)3.2 * kReuse, (MeReal)0.3, (MeReal)1.99);
  EXPECT_FALSE(p.servable());
}

TEST(McdContactReuse, ATurnMovesTheCornersByItsAngleTimesTheReach) {
  RestingBoxes s;
  Pair p(s.top.model, s.base.model);
  ASSERT_EQ(p.intersect(), 4);
  // The cube reaches sqrt(3) m from its centre and a turn by a small angle
  // a about z has |R - R0|_F = sqrt(2) a: 2e-5 rad gives D_1 = 4.9e-5 m,
  // within the distance; another 1e-4 rad about 2.9e-4 m, beyond it.
  s.top.turn({0, 0, 1}, (MeReal)2e-5);
  EXPECT_TRUE(p.servable());
  s.top.turn({0, 0, 1}, (MeReal)1e-4);
  EXPECT_FALSE(p.servable());
}

TEST(McdContactReuse, AGrownToleranceOrAResizedShapeIsTestedAgain) {
  RestingBoxes s;
  Pair p(s.top.model, s.base.model);
  ASSERT_EQ(p.intersect(), 4);
  const MeReal t = McdFrameworkGetContactTolerance(s.fw);
  // Room for the drift left in the slack: a tolerance up by half of it is
  // served, up by more than all of it is not (a farther feature might be
  // within it now).
  McdFrameworkSetContactTolerance(s.fw, t + kReuse / 2);
  EXPECT_TRUE(p.servable());
  McdFrameworkSetContactTolerance(s.fw, t + 2 * kReuse);
  EXPECT_FALSE(p.servable());
  McdFrameworkSetContactTolerance(s.fw, t);
  EXPECT_TRUE(p.servable());
  McdBoxSetDimensions(McdModelGetGeometry(s.top.model), 2, 2, 2);  // the same size, but set
  EXPECT_FALSE(p.servable());
}

TEST(McdContactReuse, ContactsBetweenTheToleranceAndTheSlackAreTestedAgainAndNotRemembered) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  // 50 micrometres above the base: beyond the 10 micrometre tolerance,
  // within the tolerance plus the 100 micrometre slack the test runs at.
  Placed top(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)2 + (MeReal)5e-5);
  Pair p(top.model, base.model);
  EXPECT_EQ(p.intersect(), 0);  // the answer of a test at the tolerance
  EXPECT_EQ(p.r.touch, 0);
  EXPECT_EQ(p.pair->m_contactMemory, nullptr);
  top.move(0, 0, (MeReal)2 + (MeReal)5e-6);  // now within the tolerance
  ASSERT_EQ(p.intersect(), 4);
  ASSERT_NE(p.pair->m_contactMemory, nullptr);
  // Lifted 3e-5 m: beyond the tolerance now, still served (a speculative
  // contact, reported with its separation).
  top.move(0, 0, (MeReal)2 + (MeReal)3.5e-5);
  EXPECT_TRUE(p.servable());
  ASSERT_EQ(p.intersect(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(p.c[i].separation, 3.5e-5, 1e-6);
}

TEST(McdContactReuse, PairsTheRuleDoesNotServeKeepNoMemory) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Placed ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)1.99);
  Pair sphereBox(ball.model, base.model);
  ASSERT_EQ(sphereBox.intersect(), 1);
  EXPECT_EQ(sphereBox.pair->m_contactMemory, nullptr);
  Placed top(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)1.99);
  McdFrameworkSetContactReuseDistance(fw, 0);
  Pair off(top.model, base.model);
  ASSERT_EQ(off.intersect(), 4);
  EXPECT_EQ(off.pair->m_contactMemory, nullptr);
}

int gUserCalls = 0;
int MEAPI CountingBoxBox(McdModelPair *, McdIntersectResult *r) {
  ++gUserCalls;
  r->contactCount = 0;
  r->touch = 0;
  return 0;
}

TEST(McdContactReuse, AnApplicationsInteractionIsCalledEveryTime) {
  Framework fw;
  McdInteractions mine{};
  mine.intersectFn = CountingBoxBox;
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeBox, &mine);
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Placed top(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)1.99);
  Pair p(top.model, base.model);
  gUserCalls = 0;
  for (int i = 0; i < 3; ++i) p.intersect();
  EXPECT_EQ(gUserCalls, 3);
  EXPECT_EQ(p.pair->m_contactMemory, nullptr);
}

}  // namespace
