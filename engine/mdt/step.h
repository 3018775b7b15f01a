// step.h: the stages of MdtWorldStep and the work arrays they share. Not
// installed.
//
// MdtWorldStep(world, h):
//   1. gather     enabled bodies and simulated constraints, each sorted by
//                 (sort key, creation order) -- this order, not memory
//                 order, decides everything that follows;
//   2. partition  breadth-first search over bodies joined by constraints
//                 (the world is not a node, so world contacts join nothing);
//                 an enabled body reaching a disabled one wakes it;
//   3. per partition: predict velocities from forces, collect the
//                 constraints' rows (row protocol, constraint.h), cap the
//                 matrix, build A = J M^-1 J^T + softness, solve with Kea,
//                 apply the impulses, store each constraint's force;
//   4. integrate  positions and orientations from the corrected velocities;
//   5. auto-disable  a partition whose bodies have all stayed below every
//                 threshold (velocities and accelerations of this step) for
//                 the alive window goes to sleep.
#pragma once

#include <vector>

#include "constraint.h"
#include "kea_lcp.h"

namespace karma::mdt {

struct Partition {
  int bodyStart, bodyCount;              // into StepScratch::partBodies
  int constraintStart, constraintCount;  // into StepScratch::partConstraints
};

struct StepScratch {
  std::vector<MdtBody *> bodies;               // enabled, sorted
  std::vector<MdtConstraint *> constraints;    // simulated, sorted
  std::vector<int> adjStart, adj;              // body -> constraints (indices)
  std::vector<MdtBody *> partBodies;
  std::vector<MdtConstraint *> partConstraints;
  std::vector<Partition> partitions;
  std::vector<int> partitionRows;              // rows solved per partition (after capping)
  // Solve arrays of the current partition.
  std::vector<Row> rows;
  std::vector<int> rowBody0, rowBody1;         // partition body index or -1
  std::vector<int> constraintRowStart;         // per constraint of the partition, +1
  std::vector<char> keep;
  std::vector<MeReal> lambdaAll;
  MdtWorldStepStats stats;
};

// Stage 1 and 2: fills bodies, constraints, partitions (waking bodies).
void buildPartitions(MdtWorldID world, StepScratch &s);
// Stage 3, after the partition's solve and integration: updates each body's
// rest time from its new velocities and accelerations; true if the whole
// partition has rested for the alive window and was put to sleep.
bool autoDisablePartition(MdtWorldID world, StepScratch &s, const Partition &p, MeReal h);
// Fills each body's geometric stiffness from last step's constraint forces
// (stabilize.cpp); called before the velocities are predicted.
void accumulateGeometricStiffness(MdtWorldID world, StepScratch &s, const Partition &p);
// Stage 4 and 5 for one partition.
void solvePartition(MdtWorldID world, StepScratch &s, const Partition &p, const StepContext &ctx);
// Matrix capping: clears keep[] of the rows to drop so that at most
// maxRows remain, in the guide's order (or by the importance callback).
void capRows(MdtWorldID world, StepScratch &s, int rowCount, int maxRows);

}  // namespace karma::mdt
