// step_budget.h: the controller behind MdtWorldSetStepBudget. Not installed.
//
// Contract. With a budget of B microseconds per MdtWorldStep (B > 0), each
// partition's solve runs at one level of an accuracy ladder, most accurate
// first:
//   0 exact        Kea with the world's iteration cap
//   1 exact:8      Kea capped at 8 linear solves
//   2 iterative:k  projected Gauss-Seidel with k sweeps, kMinSweeps <= k <= kMaxSweeps
// A partition of n rows gets the most accurate level whose predicted cost
// fits its share of what is left of the budget,
//   share = (B - overhead - spent) * n / max(n, rowsLeft),
// where `overhead` is the predicted cost of the step outside the solves,
// `spent` the predicted cost of this step's solves so far (predicted, not
// measured, so that one interrupted solve does not starve the partitions
// after it) and `rowsLeft` the rows the step is expected to solve from this
// partition on (last step's total minus this step's so far). At level 2, k
// is the most sweeps that fit the share, at least kMinSweeps however little
// is left (fewer sweeps let a resting stack fall: topple's stacks stand at
// 10, not at 5). Hysteresis: a partition moves to a more accurate level
// only after kDwellSteps steps at its present one, so that noise in the
// measured costs cannot toggle it between solvers (each change starts the
// new solver from the other's impulses); it moves to a less accurate one
// at once, so the budget holds. The world's method (MdtWorldSetKeaMethod)
// and size rule (MdtWorldSetKeaIterativeRows) are set aside while a budget
// is on. When even level 2 at kMinSweeps does
// not fit, the step runs over its budget: the budget cannot buy less than
// the step's cost outside the solves plus the cheapest solves.
//
// Cost model, learned from the step's own clock as the world runs:
//   exact levels  c_exact * n^(3/2) * s      (s linear solves)
//   iterative     c_iter * n * (1 + s)       (s sweeps; one pass prepares)
// where s is what the partition made last step at the same kind of level
// if it stopped short of its cap (a warm-started solve of a resting
// partition stops after a sweep or a solve or two). If it ran to its cap,
// s is the new cap (iterative) or at least what it made (exact). For a
// partition with no record at that kind of level, s is learned over all
// partitions: for exact levels the mean linear solves at level 0;
// for the iterative level f * k + (1 - f) * s', where f is the share of
// solves that ran to their cap and s' the mean sweeps of those that
// stopped short. s never exceeds the level's cap. An exact solve whose
// warm start was kept (no linear solve) is not learned from: a partition
// that keeps it is priced as one that solves once. A partition is known
// from one step to the next by its identity (problem.h).
// Each coefficient is the ratio of exponentially weighted sums of measured
// time and work (weights decay by kDecay per step), started from a prior of
// kPriorWork units at kPriorMicroseconds each, so a level never yet run is
// still priced. A coefficient not measured for u steps prices its level at
// its ratio divided by min(kStaleDiscount, 1 + u / kStaleSteps): a level
// priced out by a few expensive solves (a landing, a cold first step) is
// tried again once its discounted price fits, and learns its cost anew,
// while one that costs more than kStaleDiscount times its share (an exact
// solve of a heap) is never tried. The overhead is the same kind of
// average of the step's measured time minus its solve time. A measurement enters a model at most
// kOutlier times what the model predicted, so one interrupted step does
// not reprice the following ones.
//
// Determinism: the choices follow measured time, so a budgeted world is not
// bit-identical from run to run; without a budget nothing here runs.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "MdtWorld.h"
#include "MePrecision.h"

namespace karma::mdt {

// A partition solve's settings at one ladder level.
struct BudgetChoice {
  int level = 0;  // 0 exact, 1 exact:8, 2 iterative
  bool iterative = false;
  int maxIterations = 0;  // linear solves or sweeps; 0: the world's own cap
};

class StepBudget {
 public:
  static constexpr int kLevels = 3;
  static constexpr int kCappedSolves = 8;
  static constexpr int kMaxSweeps = 50;
  static constexpr int kMinSweeps = 10;
  static constexpr MeReal kDecay = (MeReal)0.9;
  static constexpr MeReal kOutlier = 3;
  static constexpr int kDwellSteps = 15;
  static constexpr MeReal kPriorWork = 100;
  static constexpr MeReal kPriorMicroseconds = (MeReal)0.02;  // per unit of work
  static constexpr MeReal kStaleSteps = 30;
  static constexpr MeReal kStaleDiscount = 3;

  // "exact", "exact:8", "iterative"; "off" for any other level.
  static const char *levelName(int level);

  // microseconds <= 0 turns the budget off.
  void setBudget(MeReal microseconds);
  MeReal budget() const { return budget_; }
  bool on() const { return budget_ > 0; }

  // The step's bracket: beginStep at its start, endStep with its measured
  // time at its end.
  void beginStep();
  void endStep(MeReal stepMicroseconds);

  // The settings for partition `partition` (its identity, problem.h; 0:
  // none) of `rows` rows about to be solved.
  BudgetChoice choose(std::uintptr_t partition, int rows) const;
  // The predicted cost of that partition's solve with `choice`.
  MeReal predictedCost(const BudgetChoice &choice, std::uintptr_t partition, int rows) const;
  // What that solve did: `solves` linear solves or sweeps in `microseconds`.
  // An exact solve that made no linear solve (its warm start kept: one
  // product with A; or bad input) teaches the exact levels' price and mean
  // solves nothing: their unit is the linear solve. It still counts as one
  // solve in its partition's record, and its time as spent this step.
  void recordSolve(std::uintptr_t partition, const BudgetChoice &choice, int rows, int solves, MeReal microseconds);

  // This step so far (for the step stats).
  int worstLevel() const { return worstLevel_; }
  int fewestSweeps() const { return fewestSweeps_; }  // 0: no iterative solve
  MeReal predictedSolveTime() const { return predicted_; }

  // The model's coefficients (for tests and the profile).
  MeReal exactCoefficient() const { return exact_.ratio(); }
  MeReal iterativeCoefficient() const { return iterative_.ratio(); }
  MeReal overhead() const { return overhead_.ratio(); }

 private:
  // An exponentially weighted ratio sum(time) / sum(work), and how many
  // steps have passed since anything was added to it.
  struct Average {
    MeReal time = kPriorWork * kPriorMicroseconds;
    MeReal work = kPriorWork;
    int unusedSteps = 0;
    bool usedThisStep = false;
    MeReal ratio() const { return time / work; }
    // The ratio as a price: discounted by 1 + unusedSteps / kStaleSteps,
    // down to 1 / kStaleDiscount of the ratio.
    MeReal price() const { return ratio() / std::min(kStaleDiscount, 1 + (MeReal)unusedSteps / kStaleSteps); }
    void add(MeReal t, MeReal w) {
      time += t;
      work += w;
      usedThisStep = true;
    }
    void decay() {
      time *= kDecay;
      work *= kDecay;
      unusedSteps = usedThisStep ? 0 : unusedSteps + 1;
      usedThisStep = false;
    }
  };

  // What a partition's solve did last step.
  struct PartitionRecord {
    std::uintptr_t identity = 0;
    int level = 0;
    int iterations = 0;  // linear solves or sweeps made
    int cap = 0;         // the cap it was given (INT_MAX: none)
    int steps = 1;       // consecutive steps at this level, this one included
  };
  // Last step's record of `partition`, or null.
  const PartitionRecord *remembered(std::uintptr_t partition) const;
  // The linear solves or sweeps a solve with `choice` is expected to make.
  MeReal expectedIterations(const BudgetChoice &choice, const PartitionRecord *last) const;
  // predictedCost with the partition's record already looked up.
  MeReal cost(const BudgetChoice &choice, const PartitionRecord *last, int rows) const;

  MeReal budget_ = 0;
  Average exact_;                         // microseconds per n^(3/2) per solve
  Average iterative_;                     // microseconds per row per pass (iterativeWork)
  Average exactSolves_{1, 1};             // linear solves per exact solve at level 0
  Average sweepsCapped_{1, 1};            // share of iterative solves that ran to their cap
  Average sweepsStopped_{1, 1};           // sweeps of iterative solves that stopped short
  Average overhead_{0, 1};                // microseconds of the step outside the solves
  int expectedRows_ = 0;                  // rows the last step solved
  int rowsSoFar_ = 0;                     // rows solved this step
  MeReal spent_ = 0;                      // measured solve microseconds this step
  MeReal predicted_ = 0;                  // predicted solve microseconds this step
  std::vector<PartitionRecord> last_;     // last step's partitions, by identity
  std::vector<PartitionRecord> current_;  // this step's so far
  int worstLevel_ = -1;                   // least accurate level used this step
  int fewestSweeps_ = 0;                  // fewest sweeps given at level 2 this step
};

// Brackets one MdtWorldStep: begins the budget's step when it is made, and
// stop() ends it with the measured time and writes the budget's step stats.
// Without a budget it reads no clock.
class StepClock {
 public:
  explicit StepClock(StepBudget &budget) : budget_(budget) {
    if (!budget_.on()) return;
    budget_.beginStep();
    start_ = Clock::now();
  }
  void stop(MdtWorldStepStats &stats) const {
    stats.budgetLevel = -1;
    if (!budget_.on()) return;
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - start_).count();
    budget_.endStep((MeReal)us);
    stats.budgetLevel = budget_.worstLevel();
    stats.budgetSweeps = budget_.fewestSweeps();
    stats.budgetPredicted = budget_.predictedSolveTime();
    stats.budgetMeasured = (MeReal)us;
  }

 private:
  using Clock = std::chrono::steady_clock;
  StepBudget &budget_;
  Clock::time_point start_{};
};

}  // namespace karma::mdt
