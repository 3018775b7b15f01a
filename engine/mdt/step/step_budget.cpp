// step_budget.cpp: the ladder, the cost model and the choice rule of
// step_budget.h.
#include "step_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace karma::mdt {

namespace {

constexpr const char *kNames[StepBudget::kLevels] = {"exact", "exact:8", "iterative"};

// Work of one exact linear solve of n rows: n^(3/2), between a banded
// factorisation (n) and a dense one (n^3) for the partitions contacts make.
MeReal exactWork(int rows) { return (MeReal)rows * std::sqrt((MeReal)rows); }

// Work of an iterative solve of n rows that makes `sweeps` sweeps: one
// pass to prepare the rows (M^-1 J^T, diagonals, blocks) and one per sweep.
MeReal iterativeWork(int rows, MeReal sweeps) { return (MeReal)rows * (1 + sweeps); }

}  // namespace

const char *StepBudget::levelName(int level) { return level >= 0 && level < kLevels ? kNames[level] : "off"; }

void StepBudget::setBudget(MeReal microseconds) { budget_ = microseconds > 0 ? microseconds : 0; }

void StepBudget::beginStep() {
  rowsSoFar_ = 0;
  spent_ = 0;
  predicted_ = 0;
  worstLevel_ = -1;
  fewestSweeps_ = 0;
}

void StepBudget::endStep(MeReal stepMicroseconds) {
  exact_.decay();
  iterative_.decay();
  exactSolves_.decay();
  sweepsCapped_.decay();
  sweepsStopped_.decay();
  overhead_.decay();
  MeReal outside = std::max<MeReal>(0, stepMicroseconds - spent_);
  if (overhead_.time > 0) outside = std::min(outside, kOutlier * overhead_.ratio());
  overhead_.add(outside, 1);
  expectedRows_ = rowsSoFar_;
  std::sort(current_.begin(), current_.end(),
            [](const PartitionRecord &a, const PartitionRecord &b) { return a.identity < b.identity; });
  last_.swap(current_);
  current_.clear();
}

const StepBudget::PartitionRecord *StepBudget::remembered(std::uintptr_t partition) const {
  if (partition == 0) return nullptr;
  const auto it = std::lower_bound(last_.begin(), last_.end(), partition,
                                   [](const PartitionRecord &r, std::uintptr_t id) { return r.identity < id; });
  return it != last_.end() && it->identity == partition ? &*it : nullptr;
}

MeReal StepBudget::expectedIterations(const BudgetChoice &c, const PartitionRecord *last) const {
  const MeReal cap = c.maxIterations > 0 ? (MeReal)c.maxIterations : MEINFINITY;
  if (last && (last->level == 2) == c.iterative) {
    if (last->iterations < last->cap) return std::clamp((MeReal)last->iterations, (MeReal)1, cap);
    // It ran to its cap: it may use all of a larger one.
    return c.iterative ? cap : std::clamp(std::max(exactSolves_.ratio(), (MeReal)last->iterations), (MeReal)1, cap);
  }
  if (!c.iterative) return std::clamp(exactSolves_.ratio(), (MeReal)1, cap);
  // A fraction f of iterative solves ran to their cap; the others stopped
  // after s sweeps on the mean.
  const MeReal f = sweepsCapped_.ratio();
  return f * cap + (1 - f) * std::clamp(sweepsStopped_.ratio(), (MeReal)1, cap);
}

MeReal StepBudget::cost(const BudgetChoice &c, const PartitionRecord *last, int rows) const {
  const MeReal iterations = expectedIterations(c, last);
  if (c.iterative) return iterative_.price() * iterativeWork(rows, iterations);
  return exact_.price() * exactWork(rows) * iterations;
}

MeReal StepBudget::predictedCost(const BudgetChoice &c, std::uintptr_t partition, int rows) const {
  return cost(c, remembered(partition), rows);
}

BudgetChoice StepBudget::choose(std::uintptr_t partition, int rows) const {
  const int rowsLeft = std::max(rows, expectedRows_ - rowsSoFar_);
  const MeReal left = budget_ - overhead_.ratio() - predicted_;
  const MeReal share = left * (MeReal)rows / (MeReal)rowsLeft;
  const PartitionRecord *last = remembered(partition);
  // Hysteresis (step_budget.h): no move to a more accurate level before
  // kDwellSteps steps at the present one.
  const bool mayUpgrade = !last || last->steps >= kDwellSteps;
  const auto fits = [&](const BudgetChoice &c) {
    if (last && c.level < last->level && !mayUpgrade) return false;
    return cost(c, last, rows) <= share;
  };
  const BudgetChoice exact{0, false, 0};
  if (fits(exact)) return exact;
  const BudgetChoice capped{1, false, kCappedSolves};
  if (fits(capped)) return capped;
  int sweeps = kMinSweeps;
  while (sweeps < kMaxSweeps && fits(BudgetChoice{2, true, sweeps + 1})) ++sweeps;
  return BudgetChoice{2, true, sweeps};
}

void StepBudget::recordSolve(std::uintptr_t partition, const BudgetChoice &c, int rows, int solves,
                             MeReal microseconds) {
  const PartitionRecord *last = remembered(partition);
  const MeReal predicted = cost(c, last, rows);
  predicted_ += predicted;
  // The model learns from at most kOutlier times its prediction: a solve
  // the machine interrupted must not reprice the next steps.
  const MeReal learned = std::min(microseconds, kOutlier * predicted);
  const int done = std::max(solves, 1);
  if (c.iterative) {
    iterative_.add(learned, iterativeWork(rows, (MeReal)done));
    const bool capped = done >= c.maxIterations;
    sweepsCapped_.add(capped ? 1 : 0, 1);
    if (!capped) sweepsStopped_.add((MeReal)done, 1);
    fewestSweeps_ = fewestSweeps_ == 0 ? c.maxIterations : std::min(fewestSweeps_, c.maxIterations);
  } else if (solves > 0) {
    exact_.add(learned, exactWork(rows) * (MeReal)done);
    if (c.level == 0) exactSolves_.add((MeReal)done, 1);
  }
  if (partition != 0)
    current_.push_back({partition, c.level, done,
                        c.maxIterations > 0 ? c.maxIterations : std::numeric_limits<int>::max(),
                        last && last->level == c.level ? last->steps + 1 : 1});
  rowsSoFar_ += rows;
  spent_ += microseconds;
  worstLevel_ = std::max(worstLevel_, c.level);
}

}  // namespace karma::mdt
