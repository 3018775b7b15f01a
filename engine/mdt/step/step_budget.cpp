// step_budget.cpp: the ladder, the cost model and the choice rule of
// step_budget.h.
#include "step_budget.h"

#include <algorithm>
#include <cmath>

namespace karma::mdt {

namespace {

constexpr const char *kNames[StepBudget::kLevels] = {"exact", "exact:8", "iterative"};

// Work of one exact linear solve of n rows: n^(3/2), between a banded
// factorisation (n) and a dense one (n^3) for the partitions contacts make.
MeReal exactWork(int rows) { return (MeReal)rows * std::sqrt((MeReal)rows); }

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
  overhead_.decay();
  MeReal outside = std::max<MeReal>(0, stepMicroseconds - spent_);
  if (overhead_.time > 0) outside = std::min(outside, kOutlier * overhead_.ratio());
  overhead_.add(outside, 1);
  expectedRows_ = rowsSoFar_;
}

MeReal StepBudget::predictedCost(const BudgetChoice &c, int rows) const {
  if (c.iterative) return iterative_.ratio() * (MeReal)rows * (MeReal)c.maxIterations;
  MeReal solves = exactSolves_.ratio();
  if (c.maxIterations > 0) solves = std::min(solves, (MeReal)c.maxIterations);
  return exact_.ratio() * exactWork(rows) * solves;
}

BudgetChoice StepBudget::choose(int rows) const {
  const int rowsLeft = std::max(rows, expectedRows_ - rowsSoFar_);
  const MeReal left = budget_ - overhead_.ratio() - predicted_;
  const MeReal share = left * (MeReal)rows / (MeReal)rowsLeft;
  const BudgetChoice exact{0, false, 0};
  if (predictedCost(exact, rows) <= share) return exact;
  const BudgetChoice capped{1, false, kCappedSolves};
  if (predictedCost(capped, rows) <= share) return capped;
  const MeReal perSweep = iterative_.ratio() * (MeReal)rows;
  const MeReal fit = share > 0 ? std::floor(share / perSweep) : 0;
  const int sweeps = (int)std::clamp<MeReal>(fit, kMinSweeps, kMaxSweeps);
  return BudgetChoice{2, true, sweeps};
}

void StepBudget::recordSolve(const BudgetChoice &c, int rows, int solves, MeReal microseconds) {
  const MeReal predicted = predictedCost(c, rows);
  predicted_ += predicted;
  // The model learns from at most kOutlier times its prediction: a solve
  // the machine interrupted must not reprice the next steps.
  const MeReal learned = std::min(microseconds, kOutlier * predicted);
  const int done = std::max(solves, 1);
  if (c.iterative) {
    iterative_.add(learned, (MeReal)rows * (MeReal)done);
    fewestSweeps_ = fewestSweeps_ == 0 ? c.maxIterations : std::min(fewestSweeps_, c.maxIterations);
  } else {
    exact_.add(learned, exactWork(rows) * (MeReal)done);
    if (c.level == 0) exactSolves_.add((MeReal)done, 1);
  }
  rowsSoFar_ += rows;
  spent_ += microseconds;
  worstLevel_ = std::max(worstLevel_, c.level);
}

}  // namespace karma::mdt
