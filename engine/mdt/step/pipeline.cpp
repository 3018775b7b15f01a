// pipeline.cpp: stages 2-8 of the step for one partition, in order (see
// step.h), and the step scratch's lifetime.
#include "step.h"

namespace karma::mdt {

StepScratch::StepScratch() : activeSet(CreateKeaActiveSetSolver()), pgs(CreatePgsSolver()), stats{} {}

StepScratch::~StepScratch() {
  delete activeSet;
  delete pgs;
}

bool stepPartition(MdtWorldID world, StepScratch &s, int index, const StepContext &ctx) {
  const Partition &part = s.partitions[(size_t)index];
  const StepArena::Mark mark = s.arena.mark();
  predictPartition(world, s, part, ctx.h);
  const PartitionRows rows = collectRows(world, s, part, ctx);
  s.partitionRows[(size_t)index] = rows.kept;
  s.stats.rows += rows.kept;
  s.stats.rowsRemoved += rows.count - rows.kept;
  const BodySpaceProblem problem = assembleProblem(s, part, rows, ctx);
  const std::span<const MeReal> lambda = solveProblem(world, s, problem);
  applyImpulses(s, part, rows, lambda, ctx);
  integratePartition(s, part, ctx.h);
  applyBounces(s, part, rows, problem);
  projectJoints(world, s, part);
  s.arena.release(mark);
  return autoDisablePartition(world, s, part, ctx.h);
}

}  // namespace karma::mdt
