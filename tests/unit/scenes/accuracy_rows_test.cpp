// The accuracy rows of the fast exact solver's goals (issue 13), each as a
// test on the anchor scene it names (SCENES.md), at the setting under which
// it holds: the guide's defaults where they suffice, and otherwise the one
// knob that buys it (world softness epsilon, joint projection). Where a row
// fails at the defaults, the defaults' figure is pinned too, within about
// 5 % either side (the same in both precisions and on every platform
// backend), so a change of the defaults' behaviour shows here; the figures
// and why the defaults fall short: docs/NOTES.md, "Two of issue 13's
// accuracy rows fail on the guide's default softness". Their costs are in
// bench/peers (peer_bench --epsilon, --joint-projection).
#include <gtest/gtest.h>

#include <cstdio>

#include "anchor_scene.h"

namespace {

using karma::scenes::AnchorScene;
using karma::scenes::SceneFigures;

constexpr double kCarSpeed = 16.18;  // SCENES.md: v(5 s), rolling without slip

// The scene's whole run; every partition of every step solved (no
// iteration cap reached, no cycle).
SceneFigures RunAndReport(AnchorScene &scene, const char *setting) {
  int unsolved = 0;
  for (int i = 0; i < scene.steps(); ++i) {
    scene.step();
    MdtWorldStepStats stats;
    MdtWorldGetStepStats(scene.world(), &stats);
    unsolved += stats.keaUnsolved;
  }
  const SceneFigures f = scene.finish();
  std::printf("[ figures  ] %s, %s: penetration %.3f mm, drop %.1f mm, unsolved partitions %d; %s\n", scene.name(),
              setting, f.penetration * 1e3, f.drop * 1e3, unsolved, f.detail.c_str());
  EXPECT_TRUE(f.stable()) << f.detail;
  EXPECT_EQ(unsolved, 0);
  return f;
}

// Speed at 5 s within 0.1 % of 16.18 m/s in any case; the wheels' sink is
// the contacts' give, gamma d / h = epsilon lambda: 8.5 mm at the guide's
// epsilon (0.01 at length scale 1; issue 13 asks <= 2 mm), a hundredth of
// it at 1e-4.
TEST(AccuracyRows, TheCarKeepsItsSpeedAndAtEpsilon1e4ItsWheelsSinkUnder2mm) {
  auto byDefault = karma::scenes::MakeCar();
  const SceneFigures d = RunAndReport(*byDefault, "defaults");
  EXPECT_NEAR(d.carVelocity, kCarSpeed, 0.001 * kCarSpeed);
  EXPECT_GT(d.penetration, 0.0081);  // the default softness's give: 8.50 mm
  EXPECT_LT(d.penetration, 0.0089);

  auto stiff = karma::scenes::MakeCar();
  MdtWorldSetEpsilon(stiff->world(), (MeReal)1e-4);
  const SceneFigures s = RunAndReport(*stiff, "epsilon 1e-4");
  EXPECT_NEAR(s.carVelocity, kCarSpeed, 0.001 * kCarSpeed);
  EXPECT_LE(s.penetration, 0.002);
}

// Every stack stands with its top box within 1 mm of where it started.
TEST(AccuracyRows, ToppleStacksAllStandWithTheirTopsWithin1mm) {
  auto scene = karma::scenes::MakeTopple();
  const SceneFigures f = RunAndReport(*scene, "defaults");
  EXPECT_EQ(f.standing, f.stacks);
  EXPECT_EQ(f.stacks, 6);
  EXPECT_LE(f.drift, 0.001);
}

// The top box drifts under 1 mm at the defaults; its drop is the 1 mm gaps
// closing (20 mm) plus the faces' give under their loads, which exceeds
// the 25 mm asked at the guide's epsilon and not at 1e-4.
TEST(AccuracyRows, Stack21StandsAndAtEpsilon1e4ItsTopDropsUnder25mm) {
  auto byDefault = karma::scenes::MakeStack21();
  const SceneFigures d = RunAndReport(*byDefault, "defaults");  // stable: standing
  EXPECT_LE(d.drift, 0.001);
  EXPECT_GT(d.drop, 0.056);  // the gaps and the default softness's give: 59.3 mm
  EXPECT_LT(d.drop, 0.062);

  auto stiff = karma::scenes::MakeStack21();
  MdtWorldSetEpsilon(stiff->world(), (MeReal)1e-4);
  const SceneFigures s = RunAndReport(*stiff, "epsilon 1e-4");
  EXPECT_LE(s.drift, 0.001);
  EXPECT_LE(s.drop, 0.025);
}

// Joint error at most 10 mm through the landing and 1 mm at the end with
// joint projection; without it the landing opens the joints by about
// 48 mm (ODE's exact solver: 40 mm) and the end stays above 1 mm.
TEST(AccuracyRows, TheRagDollsJointsHoldWithJointProjection) {
  auto byDefault = karma::scenes::MakeRagdoll();
  const SceneFigures d = RunAndReport(*byDefault, "defaults");
  EXPECT_GT(d.jointErrorMax, 0.0455);  // 47.9 mm
  EXPECT_LT(d.jointErrorMax, 0.0503);
  EXPECT_GT(d.jointErrorEnd, 0.0024);  // 2.52 mm
  EXPECT_LT(d.jointErrorEnd, 0.0027);

  auto projected = karma::scenes::MakeRagdoll();
  MdtWorldSetJointProjection(projected->world(), 4);
  const SceneFigures p = RunAndReport(*projected, "joint projection 4");
  EXPECT_LE(p.jointErrorMax, 0.010);
  EXPECT_LE(p.jointErrorEnd, 0.001);
}

}  // namespace
