// solve.cpp: stage 5 of the step (step.h): the world's partition solver
// finds the kept rows' impulses, and the step stats record what it cost.
// MdtWorldSetKeaMethod chooses the solver; with the exact one, a partition
// of more rows than MdtWorldSetKeaIterativeRows's threshold (when set) is
// solved iteratively instead. With a step budget (step_budget.h) the
// budget's level decides instead.
#include <chrono>

#include "step.h"

namespace karma::mdt {

namespace {

struct SolverChoice {
  bool iterative = false;
  SolverSettings settings;
  bool budgeted = false;
  BudgetChoice budget;  // when budgeted
};

SolverChoice chooseSolver(MdtWorldID world, const StepScratch &s, const BodySpaceProblem &problem) {
  const int rows = problem.rowCount;
  const MdtWorldParams &params = world->params;
  SolverChoice c;
  c.settings.maxIterations = params.keaMaxIterations;
  c.settings.tolerance = params.keaTolerance;
  c.settings.kernels = world->priv->kernels;
  c.settings.acceptWarmStart = params.keaAcceptWarmStart != 0;
  c.settings.step = s.step;
  if (s.budget.on()) {
    c.budgeted = true;
    c.budget = s.budget.choose(problem.identity, rows);
    c.iterative = c.budget.iterative;
    if (c.budget.maxIterations > 0) c.settings.maxIterations = c.budget.maxIterations;
    return c;
  }
  c.iterative = params.keaMethod == MdtKeaMethodPGS || (params.keaIterativeRows > 0 && rows > params.keaIterativeRows);
  return c;
}

// Runs the solver; with a budget, times it and tells the budget.
SolveReport runSolver(StepScratch &s, const SolverChoice &c, const BodySpaceProblem &problem,
                      std::span<MeReal> lambda) {
  PartitionSolver *solver = c.iterative ? s.pgs : s.activeSet;
  if (!c.budgeted) return solver->solve(problem, c.settings, s.arena, lambda);
  using Clock = std::chrono::steady_clock;
  const Clock::time_point t0 = Clock::now();
  const SolveReport report = solver->solve(problem, c.settings, s.arena, lambda);
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  s.budget.recordSolve(problem.identity, c.budget, problem.rowCount, report.iterations, (MeReal)us);
  return report;
}

}  // namespace

std::span<MeReal> solveProblem(MdtWorldID world, StepScratch &s, const BodySpaceProblem &problem) {
  std::span<MeReal> lambda = s.arena.take<MeReal>((size_t)problem.rowCount);
  if (problem.rowCount == 0) return lambda;
  const SolverChoice choice = chooseSolver(world, s, problem);
  const bool iterative = choice.iterative;
  if (iterative) ++s.stats.iterativePartitions;
  const SolveReport report = runSolver(s, choice, problem, lambda);
  s.stats.keaIterations += report.iterations;
  s.stats.keaFactorizations += report.factorizations;
  s.stats.keaFrictionRounds += report.frictionRounds;
  s.stats.keaStaleSolves += report.staleSolves;
  s.stats.keaFactorUpdates += report.factorUpdates;
  if (report.warmStartAccepted) ++s.stats.keaWarmStarts;
  if (report.solved)
    ++s.stats.keaSolved;
  else
    ++s.stats.keaUnsolved;
  if (report.cycle) ++s.stats.keaCycles;
  // A budget's capped level stops short by design: not worth a warning.
  if (!iterative && (!choice.budgeted || choice.budget.level == 0) && !report.solved && !report.badInput)
    s.solveWarnings.note(report.cycle ? UnsolvedCause::Cycle : UnsolvedCause::IterationCap, report.residual);
  if (report.residual > s.stats.keaResidual) s.stats.keaResidual = report.residual;
  return lambda;
}

}  // namespace karma::mdt
