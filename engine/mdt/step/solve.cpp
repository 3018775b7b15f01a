// solve.cpp: stage 5 of the step (step.h): the world's partition solver
// finds the kept rows' impulses, and the step stats record what it cost.
// MdtWorldSetKeaMethod chooses the solver; with the exact one, a partition
// of more rows than MdtWorldSetKeaIterativeRows's threshold (when set) is
// solved iteratively instead.
#include "step.h"

namespace karma::mdt {

std::span<MeReal> solveProblem(MdtWorldID world, StepScratch &s, const BodySpaceProblem &problem) {
  std::span<MeReal> lambda = s.arena.take<MeReal>((size_t)problem.rowCount);
  if (problem.rowCount == 0) return lambda;
  const MdtWorldParams &params = world->params;
  const bool iterative = params.keaMethod == MdtKeaMethodPGS ||
                         (params.keaIterativeRows > 0 && problem.rowCount > params.keaIterativeRows);
  PartitionSolver *solver = iterative ? s.pgs : s.activeSet;
  if (iterative) ++s.stats.iterativePartitions;
  SolverSettings settings;
  settings.maxIterations = params.keaMaxIterations;
  settings.tolerance = params.keaTolerance;
  const SolveReport report = solver->solve(problem, settings, s.arena, lambda);
  s.stats.keaIterations += report.iterations;
  s.stats.keaFactorizations += report.factorizations;
  s.stats.keaFrictionRounds += report.frictionRounds;
  s.stats.keaStaleSolves += report.staleSolves;
  if (report.solved)
    ++s.stats.keaSolved;
  else
    ++s.stats.keaUnsolved;
  if (report.cycle) ++s.stats.keaCycles;
  if (!iterative && !report.solved && !report.badInput)
    s.solveWarnings.note(report.cycle ? UnsolvedCause::Cycle : UnsolvedCause::IterationCap, report.residual);
  if (report.residual > s.stats.keaResidual) s.stats.keaResidual = report.residual;
  return lambda;
}

}  // namespace karma::mdt
