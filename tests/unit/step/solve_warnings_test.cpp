// Exact solves that stop short are reported at most once per cause per
// second of simulated time (solve_warnings.h); the step stats count each.
#include <string>

#include "step_scene.h"
#include "support/warning_capture.h"

namespace {

using karma_test::WarningCapture;
using step_test::Scene;

TEST(SolveWarnings, AnExactSolverAtItsCapWarnsOnceASecondNotOnceAStep) {
  Scene s;
  // Ten boxes dropped in a column onto each other: with one linear solve
  // allowed, most steps' solves stop at the cap.
  for (int i = 0; i < 10; ++i) s.box(1, 1, 1, 0, (MeReal)0.6 + (MeReal)1.1 * (MeReal)i, 0);
  MdtWorldSetKeaMaxIterations(s.u->world, 1);
  WarningCapture warnings;
  int unsolved = 0;
  const int steps = 150;  // 2.5 s
  for (int i = 0; i < steps; ++i) {
    s.step();
    MdtWorldStepStats stats;
    MdtWorldGetStepStats(s.u->world, &stats);
    unsolved += stats.keaUnsolved;
  }
  EXPECT_GT(unsolved, 20);
  // At most one report a second of each cause: 3 in 2.5 s (at 0, 1, 2 s).
  EXPECT_GE(warnings.count(), 1u);
  EXPECT_LE(warnings.count(), 3u);
  EXPECT_TRUE(warnings.saw("MdtWorldStep"));
  EXPECT_TRUE(warnings.saw("iteration cap"));
}

TEST(SolveWarnings, ASolvedSceneSaysNothing) {
  Scene s;
  s.box(1, 1, 1, 0, (MeReal)0.5, 0);
  WarningCapture warnings;
  s.step(120);
  EXPECT_EQ(warnings.count(), 0u);
}

}  // namespace
