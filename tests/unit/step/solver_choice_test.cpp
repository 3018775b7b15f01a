// The per-partition choice of solver by size (MdtWorldSetKeaIterativeRows):
// with the exact method, a partition of more rows than the threshold is
// solved iteratively, one of at most that many exactly; 0 means never; the
// default is 300 rows.
#include "step_scene.h"
#include "support/warning_capture.h"

namespace {

using karma_test::WarningCapture;
using step_test::Scene;

// A column of `boxes` 1 m cubes standing at x, settled for a second.
void Column(Scene &s, int boxes, MeReal x) {
  for (int i = 0; i < boxes; ++i) s.box(1, 1, 1, x, (MeReal)0.5 + (MeReal)i, 0);
}

MdtWorldStepStats Stats(const Scene &s) {
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(s.u->world, &stats);
  return stats;
}

TEST(SolverChoice, APartitionAtTheThresholdIsExactAndOneRowMoreIsIterative) {
  Scene s;
  Column(s, 2, 0);
  s.step(60);
  const int rows = Stats(s).rows;
  ASSERT_GT(rows, 0);
  ASSERT_EQ(Stats(s).partitions, 1);
  EXPECT_EQ(Stats(s).iterativePartitions, 0);  // default: 300 rows, far above

  MdtWorldSetKeaIterativeRows(s.u->world, rows);
  EXPECT_EQ(MdtWorldGetKeaIterativeRows(s.u->world), rows);
  s.step();
  EXPECT_EQ(Stats(s).rows, rows);
  EXPECT_EQ(Stats(s).iterativePartitions, 0);
  EXPECT_EQ(Stats(s).keaSolved, 1);

  MdtWorldSetKeaIterativeRows(s.u->world, rows - 1);
  s.step();
  EXPECT_EQ(Stats(s).rows, rows);
  EXPECT_EQ(Stats(s).iterativePartitions, 1);
  EXPECT_EQ(Stats(s).keaFactorizations, 0);  // no factorisation in PGS
}

TEST(SolverChoice, ASmallStackStaysExactBesideALargeOneSolvedIteratively) {
  Scene s;
  Column(s, 2, 0);
  Column(s, 8, 5);
  s.step(60);
  ASSERT_EQ(Stats(s).partitions, 2);
  // Frictionless contacts, four a face: 8 rows in the pair, 32 in the eight.
  ASSERT_EQ(Stats(s).rows, 40);
  MdtWorldSetKeaIterativeRows(s.u->world, 16);
  ASSERT_EQ(MdtWorldGetBodyCount(s.u->world), 10u);
  for (int i = 0; i < 120; ++i) {
    s.step();
    ASSERT_EQ(Stats(s).partitions, 2) << "step " << i;
    EXPECT_EQ(Stats(s).iterativePartitions, 1) << "step " << i;
    // The small one: solved, or its warm start kept (one check).
    EXPECT_GE(Stats(s).keaFactorizations + Stats(s).keaStaleSolves + Stats(s).keaWarmStarts, 1) << "step " << i;
    EXPECT_LE(Stats(s).keaWarmStarts, 1) << "step " << i;  // never the iterative one
  }
}

TEST(SolverChoice, TheDefaultSendsOnlyPartitionsOfMoreThan300RowsToTheIterativeSolver) {
  Scene s;
  EXPECT_EQ(MdtWorldGetKeaIterativeRows(s.u->world), 300);
  // A column of 30 boxes: 30 contact faces of four frictionless rows, 120
  // rows, exact under the default; with a threshold below it, iterative;
  // with 0 (never), exact again.
  Column(s, 30, 0);
  s.step(30);
  ASSERT_EQ(Stats(s).partitions, 1);
  ASSERT_EQ(Stats(s).rows, 120);
  EXPECT_EQ(Stats(s).iterativePartitions, 0);
  MdtWorldSetKeaIterativeRows(s.u->world, 119);
  s.step();
  EXPECT_EQ(Stats(s).iterativePartitions, 1);
  MdtWorldSetKeaIterativeRows(s.u->world, 0);
  s.step();
  EXPECT_EQ(Stats(s).iterativePartitions, 0);
  // A column of 76 boxes: 304 rows, iterative under the default.
  Scene tall(true, 80);
  Column(tall, 76, 0);
  tall.step(2);
  ASSERT_EQ(Stats(tall).partitions, 1);
  ASSERT_EQ(Stats(tall).rows, 304);
  EXPECT_EQ(Stats(tall).iterativePartitions, 1);
}

TEST(SolverChoice, ANegativeThresholdWarnsAndIsIgnored) {
  Scene s;
  MdtWorldSetKeaIterativeRows(s.u->world, 30);
  WarningCapture warnings;
  MdtWorldSetKeaIterativeRows(s.u->world, -1);
  EXPECT_EQ(warnings.count(), 1u);
  EXPECT_TRUE(warnings.saw("MdtWorldSetKeaIterativeRows"));
  EXPECT_EQ(MdtWorldGetKeaIterativeRows(s.u->world), 30);
}

}  // namespace

TEST(SolverChoice, KeptWarmStartsAreOnByDefaultAndCanBeTurnedOff) {
  Scene s;
  Column(s, 2, 0);
  EXPECT_EQ(MdtWorldGetKeaAcceptWarmStart(s.u->world), 1);
  int kept = 0;
  for (int i = 0; i < 120; ++i) {
    s.step();
    kept += Stats(s).keaWarmStarts;
  }
  // Measured: 49 of the 120 steps in single precision, 22 in double. The
  // pair, created touching, settles first (each step solved: the first 29
  // in single, the first 90 in double, whose tolerance is 1e-10). At rest
  // about every other warm start is kept: a kept answer is last step's
  // impulses, which this step's slightly changed problem then rejects, and
  // the solve that follows ends near rounding and is kept the step after
  // (double keeps runs of up to a dozen). The bounds leave about a fifth
  // either side; below them the check has stopped paying, above them a warm
  // start is kept where it should have been solved.
  EXPECT_GE(kept, KARMA_DOUBLE ? 16 : 40);
  EXPECT_LE(kept, KARMA_DOUBLE ? 28 : 60);
  MdtWorldSetKeaAcceptWarmStart(s.u->world, 0);
  EXPECT_EQ(MdtWorldGetKeaAcceptWarmStart(s.u->world), 0);
  for (int i = 0; i < 60; ++i) {
    s.step();
    EXPECT_EQ(Stats(s).keaWarmStarts, 0) << "step " << i;
    EXPECT_EQ(Stats(s).keaFactorizations + Stats(s).keaStaleSolves, 1) << "step " << i;
  }
  MdtWorldSetKeaAcceptWarmStart(s.u->world, 7);  // any non-zero value is on
  EXPECT_EQ(MdtWorldGetKeaAcceptWarmStart(s.u->world), 1);
}
