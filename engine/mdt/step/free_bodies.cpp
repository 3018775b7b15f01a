// free_bodies.cpp: the partitions of one body and no constraint, stepped
// in one batch (issue 17). Such a body has no rows, so of the stages of
// stepPartition (pipeline.cpp) only predict (2), integrate (7) and sleep
// (8) do anything; here each runs over the whole batch before the next.
// Nothing in those stages reads another body, so each body goes through
// exactly the computations it would as a partition of its own, and the
// results are the same bit for bit; the batch skips the arena, the empty
// row, assembly, solve, apply and bounce stages.
#include "step.h"

namespace karma::mdt {

int stepFreeBodies(MdtWorldID world, StepScratch &s, const StepContext &ctx) {
  for (int pi : s.freePartitions) {
    const Partition &part = s.partitions[(size_t)pi];
    predictPartition(world, s, part, ctx.h);
  }
  for (int pi : s.freePartitions) integratePartition(s, s.partitions[(size_t)pi], ctx.h);
  int asleep = 0;
  for (int pi : s.freePartitions)
    if (autoDisablePartition(world, s, s.partitions[(size_t)pi], ctx.h)) ++asleep;
  return asleep;
}

}  // namespace karma::mdt
