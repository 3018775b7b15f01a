// The warm-started solvers on the anchor scenes (SCENES.md): with contacts
// that remember their impulses, projected Gauss-Seidel holds the 21-box
// stack, and the exact solver needs few linear solves a step once a scene
// rests.
#include <gtest/gtest.h>

#include <cstdio>

#include "anchor_scene.h"

namespace {

// stack21 reports "top box drift D mm, ..."; the drift in metres.
double TopDrift(const karma::scenes::SceneFigures &f) {
  double mm = -1;
  EXPECT_EQ(std::sscanf(f.detail.c_str(), "top box drift %lf mm", &mm), 1) << f.detail;
  return mm * 1e-3;
}

// Issue 12 asks for a top box drift under 5 mm here. This PGS (body space,
// warm-started, symmetric sweeps, contact normals solved per face) reaches
// it only while every contact of the stack keeps its impulse from step to
// step, including the corners of aligned boxes that rounding renames
// (contact_cache.h, pass 3); re-made with zero impulses, the top box drifts
// by several millimetres or more.
TEST(WarmStart, PgsAtFiftySweepsKeepsTheTwentyOneBoxStackStanding) {
  auto scene = karma::scenes::MakeStack21();
  MdtWorldSetKeaMethod(scene->world(), MdtKeaMethodPGS);
  MdtWorldSetKeaMaxIterations(scene->world(), 50);
  const karma::scenes::SceneFigures f = scene->run();  // 1200 steps: 20 s
  std::printf("stack21 with PGS, 50 sweeps: %s, penetration %.2f mm\n", f.detail.c_str(), f.penetration * 1e3);
  EXPECT_TRUE(f.stable()) << f.detail;
  EXPECT_LT(TopDrift(f), 0.005);
  EXPECT_LT(f.penetration, 0.01);
}

// Per partition and step over the last `steps` of `total`: the linear
// solves, and the warm starts kept without one.
struct RestingCost {
  double solves = 0, warmStarts = 0;
};

RestingCost CostPerPartition(karma::scenes::AnchorScene &scene, int total, int steps) {
  long solves = 0, warmStarts = 0, partitions = 0;
  for (int i = 0; i < total; ++i) {
    scene.step();
    if (i < total - steps) continue;
    MdtWorldStepStats st;
    MdtWorldGetStepStats(scene.world(), &st);
    solves += st.keaIterations;
    warmStarts += st.keaWarmStarts;
    partitions += st.partitions;
  }
  if (partitions == 0) return {};
  return {(double)solves / (double)partitions, (double)warmStarts / (double)partitions};
}

TEST(WarmStart, ARestingToppleSceneNeedsAboutOneSolveAPartitionWithoutKeptWarmStarts) {
  auto scene = karma::scenes::MakeTopple();
  MdtWorldSetKeaAcceptWarmStart(scene->world(), FALSE);
  const RestingCost c = CostPerPartition(*scene, 300, 100);
  std::printf("topple at rest (steps 200-300), warm starts only guessing: %.2f linear solves per partition and step\n",
              c.solves);
  EXPECT_EQ(c.warmStarts, 0);
  EXPECT_GE(c.solves, 1.0);
  EXPECT_LE(c.solves, 1.05);  // a warm start confirmed by one solve
}

// By default a warm start that already meets a sixteenth of the tolerance
// is kept without a solve: at rest, most of topple's stacks each step.
TEST(WarmStart, ARestingToppleSceneKeepsMostWarmStartsAndSolvesTheRestOnce) {
  auto scene = karma::scenes::MakeTopple();
  const RestingCost c = CostPerPartition(*scene, 300, 100);
  std::printf("topple at rest (steps 200-300): %.2f linear solves and %.2f kept warm starts per partition and step\n",
              c.solves, c.warmStarts);
  EXPECT_GT(c.warmStarts, 0.5);
  EXPECT_GE(c.solves + c.warmStarts, 1.0);
  EXPECT_LE(c.solves + c.warmStarts, 1.05);
}

TEST(WarmStart, TheCarRollsAtTheSpeedRollingWithoutSlipPredicts) {
  // SCENES.md: v(5 s) = 16.18 m/s. The wheels sink into the ground by the
  // contacts' softness (about 8 mm at the default epsilon); acting at the
  // wheel's own surface point, friction keeps the rolling radius 0.3 m.
  auto scene = karma::scenes::MakeCar();
  const karma::scenes::SceneFigures f = scene->run();
  std::printf("car at 5 s: %s\n", f.detail.c_str());
  EXPECT_NEAR(f.carVelocity, 16.18, 0.005 * 16.18);
}

}  // namespace
