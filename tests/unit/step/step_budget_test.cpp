// The step budget (MdtWorldSetStepBudget, step_budget.h): the cost model
// learns a known cost, the choice rule picks the most accurate level that
// fits, a simulated scene whose costs follow the model holds its budget,
// and through the engine a generous or a starved budget gives exactly the
// fixed setting it must choose.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "step_budget.h"
#include "step_scene.h"
#include "support/warning_capture.h"

namespace {

using karma::mdt::BudgetChoice;
using karma::mdt::StepBudget;
using step_test::Scene;

// A synthetic scene's true costs: the form the model assumes, with
// coefficients the budget does not know.
struct TrueCosts {
  double exactPerWork = 0.02;  // microseconds per n^(3/2) per linear solve
  double exactSolves = 3;      // linear solves per exact solve
  double iterPerWork = 0.05;   // microseconds per row per pass (one to prepare, one per sweep)
  double overhead = 50;        // microseconds per step outside the solves
  double solveTime(const BudgetChoice &c, int rows) const {
    if (c.iterative) return iterPerWork * rows * (1 + c.maxIterations);
    const double solves = c.maxIterations > 0 ? std::min(exactSolves, (double)c.maxIterations) : exactSolves;
    return exactPerWork * rows * std::sqrt((double)rows) * solves;
  }
  int solves(const BudgetChoice &c) const {
    return c.iterative ? c.maxIterations : (int)std::min(exactSolves, c.maxIterations > 0 ? c.maxIterations : 1e9);
  }
};

// Steps the budget through `steps` steps of partitions of the given rows,
// each solve taking its true time; returns the last step's total time.
double RunSimulated(StepBudget &budget, const TrueCosts &truth, const std::vector<int> &partitionRows, int steps,
                    std::vector<BudgetChoice> *lastChoices = nullptr) {
  double total = 0;
  for (int step = 0; step < steps; ++step) {
    budget.beginStep();
    total = truth.overhead;
    if (lastChoices) lastChoices->clear();
    for (size_t k = 0; k < partitionRows.size(); ++k) {
      const int rows = partitionRows[k];
      const std::uintptr_t partition = k + 1;
      const BudgetChoice c = budget.choose(partition, rows);
      const double t = truth.solveTime(c, rows);
      budget.recordSolve(partition, c, rows, truth.solves(c), (MeReal)t);
      total += t;
      if (lastChoices) lastChoices->push_back(c);
    }
    budget.endStep((MeReal)total);
  }
  return total;
}

TEST(StepBudget, LearnsTheCostCoefficientsOfASceneThatFollowsItsModel) {
  StepBudget budget;
  budget.setBudget(1e9);  // every solve exact
  TrueCosts truth;
  RunSimulated(budget, truth, {100, 100}, 100);
  // The prior's weight has decayed by 0.9^100: the ratio is the truth.
  EXPECT_NEAR(budget.exactCoefficient(), truth.exactPerWork, 1e-4 * truth.exactPerWork);
  EXPECT_NEAR(budget.overhead(), truth.overhead, 1e-3 * truth.overhead);
  // A budget that forces the iterative level teaches its coefficient.
  budget.setBudget(100);
  RunSimulated(budget, truth, {100, 100}, 100);
  EXPECT_NEAR(budget.iterativeCoefficient(), truth.iterPerWork, 1e-4 * truth.iterPerWork);
}

TEST(StepBudget, ChoosesTheMostAccurateLevelThatFitsItsShare) {
  StepBudget budget;
  TrueCosts truth;
  // Exact costs enough that its price, discounted for the steps it is not
  // run below, stays above the iterative budgets tried.
  truth.exactSolves = 20;
  budget.setBudget(1e9);
  RunSimulated(budget, truth, {400}, 60);
  budget.setBudget(80);
  RunSimulated(budget, truth, {400}, 60);  // learns the iterative cost too
  const int rows = 400;
  const BudgetChoice exact{0, false, 0};
  const double exactCost = budget.predictedCost(exact, 0, rows);
  // One partition: its share is all the budget leaves after the overhead.
  // A budget just above overhead + exact cost chooses exact; just below, not.
  budget.setBudget((MeReal)(budget.overhead() + exactCost * 1.01));
  budget.beginStep();
  EXPECT_EQ(budget.choose(0, rows).level, 0);
  budget.setBudget((MeReal)(budget.overhead() + exactCost * 0.99));
  EXPECT_NE(budget.choose(0, rows).level, 0);
  // Iterative, solves that ran to their caps: k sweeps (and the
  // preparing pass) fit and k + 1 do not.
  const double perPass = budget.iterativeCoefficient() * rows;
  budget.setBudget((MeReal)(budget.overhead() + perPass * 13.5));
  const BudgetChoice c = budget.choose(0, rows);
  ASSERT_EQ(c.level, 2);
  EXPECT_EQ(c.maxIterations, 12);
  // Nothing left still runs the fewest sweeps.
  budget.setBudget((MeReal)1e-3);
  EXPECT_EQ(budget.choose(0, rows).maxIterations, StepBudget::kMinSweeps);
}

TEST(StepBudget, AKeptWarmStartDoesNotCheapenTheExactPrice) {
  // Every solve exact; every other step partition 1 keeps its warm start (no
  // linear solve, a hundredth of a solve's time). The exact coefficient and
  // the mean solves are those of the real solves, and partition 1 is still
  // priced as a partition that solves once.
  StepBudget budget;
  TrueCosts truth;
  truth.exactSolves = 1;
  budget.setBudget(1e9);
  const int rows = 100;
  const BudgetChoice exact{0, false, 0};
  const double oneSolve = truth.exactPerWork * rows * std::sqrt((double)rows);
  for (int step = 0; step < 100; ++step) {
    budget.beginStep();
    for (std::uintptr_t partition : {1u, 2u}) {
      ASSERT_EQ(budget.choose(partition, rows).level, 0);
      const bool kept = partition == 1 && step % 2 == 1;
      budget.recordSolve(partition, exact, rows, kept ? 0 : 1, (MeReal)(kept ? oneSolve / 100 : oneSolve));
    }
    budget.endStep((MeReal)(truth.overhead + 2 * oneSolve));
  }
  EXPECT_NEAR(budget.exactCoefficient(), truth.exactPerWork, 1e-4 * truth.exactPerWork);
  EXPECT_NEAR(budget.predictedCost(exact, 1, rows), oneSolve, 1e-3 * oneSolve);
  EXPECT_NEAR(budget.predictedCost(exact, 0, rows), oneSolve, 1e-3 * oneSolve);
}

// Steps a starved budget (every solve iterative) through partitions 1 and 2
// of `rows` rows: partition 1 converges after `stopsAfter` sweeps, partition
// 2 runs to its cap; each solve takes exactly the passes it makes.
void RunIterativePair(StepBudget &budget, const TrueCosts &truth, int rows, int stopsAfter, int steps) {
  budget.setBudget((MeReal)1e-3);
  for (int step = 0; step < steps; ++step) {
    budget.beginStep();
    for (std::uintptr_t partition : {1u, 2u}) {
      const BudgetChoice c = budget.choose(partition, rows);
      const int sweeps = partition == 1 ? std::min(stopsAfter, c.maxIterations) : c.maxIterations;
      budget.recordSolve(partition, c, rows, sweeps, (MeReal)(truth.iterPerWork * rows * (1 + sweeps)));
    }
    budget.endStep(1);
  }
}

TEST(StepBudget, PricesAPartitionByTheSweepsItMadeLastStep) {
  StepBudget budget;
  TrueCosts truth;
  const int rows = 100;
  truth.exactSolves = 20;  // exact out of reach of the shares below, discounted or not
  budget.setBudget(1e9);
  RunSimulated(budget, truth, {rows, rows}, 60);
  RunIterativePair(budget, truth, rows, 2, 100);
  EXPECT_NEAR(budget.iterativeCoefficient(), truth.iterPerWork, 1e-4 * truth.iterPerWork);
  const BudgetChoice fifty{2, true, 50};
  const double perPass = truth.iterPerWork * rows;
  // Partition 1 stopped after 2 sweeps: any cap of 2 or more costs 3 passes.
  EXPECT_NEAR(budget.predictedCost(fifty, 1, rows), 3 * perPass, 1e-3 * perPass);
  // Partition 2 ran to its cap: a cap of 50 costs 51 passes.
  EXPECT_NEAR(budget.predictedCost(fifty, 2, rows), 51 * perPass, 1e-3 * perPass);
  // Unknown partitions: half the solves ran to their cap, half stopped
  // after 2: 1 + (50 + 2) / 2 passes.
  EXPECT_NEAR(budget.predictedCost(fifty, 0, rows), 27 * perPass, 1e-2 * perPass);
  EXPECT_NEAR(budget.predictedCost(fifty, 77, rows), 27 * perPass, 1e-2 * perPass);
  // So a share of 10 passes buys partition 1 the most sweeps, and the
  // others the fewest.
  budget.setBudget((MeReal)(budget.overhead() + 2 * 10 * perPass));
  budget.beginStep();
  EXPECT_EQ(budget.choose(1, rows).maxIterations, StepBudget::kMaxSweeps);
  EXPECT_EQ(budget.choose(2, rows).maxIterations, StepBudget::kMinSweeps);
}

TEST(StepBudget, APartitionMovesToAMoreAccurateLevelOnlyAfterDwellingAtItsOwn) {
  StepBudget budget;
  TrueCosts truth;
  const int rows = 100;
  budget.setBudget(1e9);
  RunSimulated(budget, truth, {rows, rows}, 60);  // learns the exact cost
  RunIterativePair(budget, truth, rows, 2, 1);    // both partitions drop to iterative
  budget.setBudget(1e9);                          // exact fits again
  budget.beginStep();
  EXPECT_EQ(budget.choose(1, rows).level, 2);   // one step at iterative: it stays
  EXPECT_EQ(budget.choose(0, rows).level, 0);   // no memory: exact fits
  EXPECT_EQ(budget.choose(77, rows).level, 0);  // unknown identity: the same
  RunIterativePair(budget, truth, rows, 2, StepBudget::kDwellSteps - 2);
  budget.setBudget(1e9);
  budget.beginStep();
  EXPECT_EQ(budget.choose(1, rows).level, 2);  // kDwellSteps - 1 steps: still
  RunIterativePair(budget, truth, rows, 2, 1);
  budget.setBudget(1e9);
  budget.beginStep();
  EXPECT_EQ(budget.choose(1, rows).level, 0);  // kDwellSteps: it may move
  // Moving down needs no dwelling: a partition exact for one step takes the
  // iterative level at once when exact no longer fits.
  RunSimulated(budget, truth, {rows, rows}, 1);
  budget.setBudget((MeReal)1e-3);
  budget.beginStep();
  EXPECT_EQ(budget.choose(1, rows).level, 2);
}

TEST(StepBudget, ALevelNotRunForAWhileIsPricedLowerUntilItRunsAgain) {
  StepBudget budget;
  TrueCosts truth;
  const int rows = 100;
  const BudgetChoice exact{0, false, 0};
  budget.setBudget(1e9);
  RunSimulated(budget, truth, {rows, rows}, 60);
  const double fresh = budget.predictedCost(exact, 0, rows);
  // The price falls as 1 / (1 + unused / kStaleSteps) ...
  RunIterativePair(budget, truth, rows, 2, (int)StepBudget::kStaleSteps);
  EXPECT_NEAR(budget.predictedCost(exact, 0, rows), fresh / 2, 1e-4 * fresh);
  // ... down to 1 / kStaleDiscount, and no lower.
  RunIterativePair(budget, truth, rows, 2, (int)(4 * StepBudget::kStaleSteps));
  EXPECT_NEAR(budget.predictedCost(exact, 0, rows), fresh / StepBudget::kStaleDiscount, 1e-4 * fresh);
  EXPECT_NEAR(budget.exactCoefficient(), truth.exactPerWork, 1e-4 * truth.exactPerWork);  // learned ratio kept
  // Run once more, the level is priced at what it learned again.
  budget.setBudget(1e9);
  RunSimulated(budget, truth, {rows, rows}, 1);
  EXPECT_NEAR(budget.predictedCost(exact, 0, rows), fresh, 1e-4 * fresh);
}

TEST(StepBudget, HoldsItsBudgetWithinTwentyPercentOnASceneWhoseCostItCanPredict) {
  TrueCosts truth;
  const std::vector<int> partitions = {60, 120, 200, 40};
  for (double b : {300.0, 350.0}) {
    StepBudget budget;
    budget.setBudget((MeReal)b);
    std::vector<BudgetChoice> choices;
    const double total = RunSimulated(budget, truth, partitions, 200, &choices);
    EXPECT_LE(total, 1.02 * b) << "budget " << b;
    EXPECT_GE(total, 0.8 * b) << "budget " << b;
    // Too little for every partition exact (that costs 342): some go iterative.
    EXPECT_TRUE(std::any_of(choices.begin(), choices.end(), [](const BudgetChoice &c) { return c.level == 2; }))
        << "budget " << b;
  }
  // Ample: every partition exact, well under the budget.
  StepBudget ample;
  ample.setBudget(1000);
  std::vector<BudgetChoice> choices;
  EXPECT_LT(RunSimulated(ample, truth, partitions, 50, &choices), 1000);
  for (const BudgetChoice &c : choices) EXPECT_EQ(c.level, 0);
}

// A column of boxes on the ground, stepped 120 times; returns the top box's
// height and the last step's stats.
struct ColumnRun {
  MeReal topY = 0;
  MdtWorldStepStats stats{};
};

template <typename Setup>
ColumnRun RunColumn(Setup setup) {
  Scene s;
  McdModelID top = nullptr;
  for (int i = 0; i < 6; ++i) top = s.box(1, 1, 1, 0, (MeReal)0.5 + (MeReal)1.001 * (MeReal)i, 0);
  setup(s.u->world);
  s.step(120);
  ColumnRun r;
  MeVector3 p;
  Scene::position(top, p);
  r.topY = p[1];
  MdtWorldGetStepStats(s.u->world, &r.stats);
  return r;
}

TEST(StepBudget, AGenerousBudgetSolvesExactlyAsWithoutOne) {
  const ColumnRun plain = RunColumn([](MdtWorldID) {});
  const ColumnRun budgeted = RunColumn([](MdtWorldID w) { MdtWorldSetStepBudget(w, 1e9); });
  EXPECT_EQ(plain.topY, budgeted.topY);  // bit-identical
  EXPECT_EQ(plain.stats.budgetLevel, -1);
  EXPECT_EQ(budgeted.stats.budgetLevel, 0);
  EXPECT_GT(budgeted.stats.budgetMeasured, 0);
  EXPECT_GT(budgeted.stats.budgetPredicted, 0);
}

TEST(StepBudget, AStarvedBudgetRunsTheFewestSweepsExactlyAsThatFixedSetting) {
  const ColumnRun fixed = RunColumn([](MdtWorldID w) {
    MdtWorldSetKeaMethod(w, MdtKeaMethodPGS);
    MdtWorldSetKeaMaxIterations(w, StepBudget::kMinSweeps);
  });
  const ColumnRun starved = RunColumn([](MdtWorldID w) { MdtWorldSetStepBudget(w, (MeReal)1e-3); });
  EXPECT_EQ(fixed.topY, starved.topY);  // bit-identical
  EXPECT_EQ(starved.stats.budgetLevel, 2);
  EXPECT_EQ(starved.stats.budgetSweeps, StepBudget::kMinSweeps);
  EXPECT_EQ(starved.stats.iterativePartitions, fixed.stats.iterativePartitions);
}

TEST(StepBudget, RejectsBadBudgetsAndNamesItsLevels) {
  Scene s;
  MdtWorldSetStepBudget(s.u->world, 300);
  {
    karma_test::WarningCapture warnings;
    MdtWorldSetStepBudget(s.u->world, -1);
    MdtWorldSetStepBudget(s.u->world, (MeReal)NAN);
    EXPECT_EQ(warnings.count(), 2u);
  }
  EXPECT_EQ(MdtWorldGetStepBudget(s.u->world), 300);
  MdtWorldSetStepBudget(s.u->world, 0);
  EXPECT_EQ(MdtWorldGetStepBudget(s.u->world), 0);
  EXPECT_STREQ(MdtWorldGetStepBudgetLevelName(0), "exact");
  EXPECT_STREQ(MdtWorldGetStepBudgetLevelName(1), "exact:8");
  EXPECT_STREQ(MdtWorldGetStepBudgetLevelName(2), "iterative");
  EXPECT_STREQ(MdtWorldGetStepBudgetLevelName(3), "off");
  EXPECT_STREQ(MdtWorldGetStepBudgetLevelName(-1), "off");
}

}  // namespace
