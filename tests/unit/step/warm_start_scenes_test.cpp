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

// Linear solves per partition and step over the last `steps` of `total`.
double SolvesPerPartition(karma::scenes::AnchorScene &scene, int total, int steps) {
  long solves = 0, partitions = 0;
  for (int i = 0; i < total; ++i) {
    scene.step();
    if (i < total - steps) continue;
    MdtWorldStepStats st;
    MdtWorldGetStepStats(scene.world(), &st);
    solves += st.keaIterations;
    partitions += st.partitions;
  }
  return partitions ? (double)solves / (double)partitions : 0;
}

TEST(WarmStart, ARestingToppleSceneNeedsAboutOneSolveAPartition) {
  auto scene = karma::scenes::MakeTopple();
  const double solves = SolvesPerPartition(*scene, 300, 100);
  std::printf("topple at rest (steps 200-300): %.2f linear solves per partition and step\n", solves);
  EXPECT_GE(solves, 1.0);
  EXPECT_LE(solves, 1.05);  // a warm start confirmed by one solve
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
