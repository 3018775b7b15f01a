// Scenes through MstUniverseStep: a sphere coming to rest on a plane,
// sleeping (body disabled, model frozen) and woken by a hit; a box resting
// on a plane; restitution 1 bouncing back to the drop height.
#include "mst_test_support.h"

#include <algorithm>
#include <cmath>

using namespace mst_test;

TEST(MstScene, SphereRestsOnPlaneSleepsAndWakesWhenHit) {
  Scene s;
  McdModelID ball = s.ball((MeReal)0.5, 0, 0, 2);
  MdtBodyID body = McdModelGetBody(ball);
  int steps = 0;
  while (MdtBodyIsEnabled(body) && steps < 1000) {
    s.step();
    ++steps;
  }
  ASSERT_FALSE(MdtBodyIsEnabled(body)) << "the ball never went to sleep";
  EXPECT_NEAR(Scene::z(ball), 0.5, 1e-3);
  EXPECT_EQ(McdSpaceModelIsFrozen(ball), 1);  // the world handler froze it
  std::printf("[ figures  ] ball asleep after %d steps at z = %.6f\n", steps, (double)Scene::z(ball));
  // The sleeping ball keeps its pair and contact group with the ground.
  s.step(10);
  EXPECT_NEAR(Scene::z(ball), 0.5, 1e-3);
  EXPECT_FALSE(MdtBodyIsEnabled(body));

  // A second ball dropped on it wakes it and unfreezes its model.
  McdModelID hammer = s.ball((MeReal)0.5, (MeReal)0.3, 0, 2);
  bool woke = false;
  for (int i = 0; i < 100 && !woke; ++i) {
    s.step();
    woke = MdtBodyIsEnabled(body) != 0;
  }
  EXPECT_TRUE(woke);
  EXPECT_EQ(McdSpaceModelIsFrozen(ball), 0);
  s.step(300);  // pushed aside, both settle on the ground
  EXPECT_NEAR(Scene::z(ball), 0.5, 2e-3);
  EXPECT_NEAR(Scene::z(hammer), 0.5, 2e-3);
}

TEST(MstScene, BoxRestsFlatOnPlane) {
  Scene s;
  McdModelID box = MstModelAndBodyCreate(s.u, McdBoxCreate(s.u->frame, 1, 2, (MeReal)0.6), 1);
  MdtBodyID body = McdModelGetBody(box);
  MdtBodySetPosition(body, 0, 0, 1);
  s.step(300);
  EXPECT_NEAR(Scene::z(box), 0.3, 1e-3);
  MeMatrix3 R;
  MdtBodyGetOrientation(body, R);
  EXPECT_NEAR(R[2][2], 1, 1e-4);  // still flat
}

namespace {
// Largest height reached after the first impact.
double BounceHeight(MeReal restitution) {
  Scene s;
  McdModelID ball = s.ball((MeReal)0.25, 0, 0, 0);
  MstBridgeID bridge = s.u->bridge;
  const MstMaterialID ballMat = MstBridgeGetNewMaterial(bridge);
  const MstMaterialID floorMat = MstBridgeGetNewMaterial(bridge);
  MdtContactParamsID p = MstBridgeGetContactParams(bridge, ballMat, floorMat);
  EXPECT_EQ(p, MstBridgeGetContactParams(bridge, floorMat, ballMat));
  MdtContactParamsSetRestitution(p, restitution);
  McdModelSetMaterial(ball, ballMat);
  McdModelSetMaterial(s.ground, floorMat);
  const MeReal h = 1;  // drop height of the lowest point
  MdtBodySetPosition(McdModelGetBody(ball), 0, 0, h + (MeReal)0.25);
  bool hit = false;
  double top = 0;
  for (int i = 0; i < 300; ++i) {
    s.step();
    if (Scene::vz(ball) > 0) hit = true;
    if (hit) top = std::max(top, (double)Scene::z(ball) - 0.25);
  }
  return top;
}
}  // namespace

// The apex semi-implicit Euler reaches after leaving the ground at speed u
// (positions advance with each step's new velocity): u^2 / 2g - u h / 2.
// A ball dropped from H leaves at u = e sqrt(2 g H).
double DiscreteApex(double e, double H, double h) {
  const double u = e * std::sqrt(2 * (double)kG * H);
  return u * u / (2 * (double)kG) - u * h / 2;
}

TEST(MstScene, RestitutionOneBouncesBackToTheDropHeight) {
  const double top = BounceHeight(1), want = DiscreteApex(1, 1, (double)kH);
  std::printf("[ figures  ] restitution 1: bounce to %.4f of the 1 m drop (discrete apex %.4f)\n", top, want);
  EXPECT_NEAR(top, want, 0.02 * want);
  const double half = BounceHeight((MeReal)0.5), wantHalf = DiscreteApex(0.5, 1, (double)kH);
  std::printf("[ figures  ] restitution 0.5: bounce to %.4f (e^2 h = 0.25, discrete apex %.4f)\n", half, wantHalf);
  EXPECT_NEAR(half, wantHalf, 0.02 * wantHalf);
}

namespace {
// Three balls touching in a row on the ground go to sleep together; then
// the program wakes the first. Returns the steps until the last is awake.
int StepsToWakeTheNeighbour(bool keepFrozenPairs, int *groupsAsleep) {
  Scene s;
  McdSpaceSetKeepFrozenPairs(s.u->space, keepFrozenPairs);
  McdModelID a = s.ball((MeReal)0.5, 0, 0, (MeReal)0.5);
  s.ball((MeReal)0.5, 1, 0, (MeReal)0.5);
  McdModelID b = s.ball((MeReal)0.5, 2, 0, (MeReal)0.5);
  MdtBodyID ba = McdModelGetBody(a), bb = McdModelGetBody(b);
  for (int i = 0; i < 1000 && (MdtBodyIsEnabled(ba) || MdtBodyIsEnabled(bb)); ++i) s.step();
  EXPECT_FALSE(MdtBodyIsEnabled(ba) || MdtBodyIsEnabled(bb));
  s.step(5);  // asleep for a while: frozen pairs kept or said goodbye
  EXPECT_EQ(McdSpaceModelIsFrozen(a) + McdSpaceModelIsFrozen(b), 2);
  *groupsAsleep = (int)MdtWorldGetConstraintCount(s.u->world);
  MdtBodyEnable(ba);
  EXPECT_EQ(McdSpaceModelIsFrozen(a), 0);  // the handler unfroze it at once
  int steps = 0;
  while (!MdtBodyIsEnabled(bb) && steps < 10) {
    s.step();
    ++steps;
  }
  EXPECT_EQ(McdSpaceModelIsFrozen(b), 0);
  return steps;
}
}  // namespace

TEST(MstScene, KeptFrozenPairsWakeASleepingGroupAtOnce) {
  int kept = 0, dropped = 0;
  EXPECT_EQ(StepsToWakeTheNeighbour(true, &kept), 1);
  EXPECT_EQ(kept, 10);  // 5 groups (2 ball-ball, 3 ball-ground) + their 5 contacts (slots)
  const int later = StepsToWakeTheNeighbour(false, &dropped);
  EXPECT_EQ(dropped, 0);  // the plain rule: every frozen pair said goodbye
  EXPECT_EQ(later, 2);    // the middle ball wakes first, then its pair with the last says hello
  std::printf("[ figures  ] neighbour awake after %d step(s) with frozen pairs kept, %d without\n", 1, later);
}
