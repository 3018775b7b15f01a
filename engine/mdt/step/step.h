// step.h: the stages of MdtWorldStep and the memory they share. Not
// installed.
//
// MdtWorldStep(world, h), one file per stage, in this order:
//   1. gather      (gather.cpp) enabled bodies and simulated constraints,
//                  each sorted by (sort key, creation order) -- this order,
//                  not memory order, decides everything that follows; then
//                  partitions: breadth-first search over bodies joined by
//                  constraints (the world is not a node, so world contacts
//                  join nothing); an enabled body reaching a disabled one
//                  wakes it.
//   Per partition with constraints (pipeline.cpp); a partition of one body
//   and no constraint has no rows, and all of those go through stages 2, 7
//   and 8 together in one batch after the others (free_bodies.cpp):
//   2. predict     (predict.cpp) velocities from the forces, before the
//                  constraints (and geometric stiffness, stabilize.cpp);
//   3. rows        (collect_rows.cpp) every constraint writes its rows (the row
//                  protocol, constraint.h); non-finite ones are dropped;
//                  matrix capping (capping.cpp) marks the rows to drop;
//   4. assemble    (assemble.cpp) the body-space problem (problem.h) of the
//                  kept rows: Jacobian blocks, inverse masses and inertias,
//                  right-hand side, bounds, friction links, warm impulses;
//   5. solve       (solve.cpp) the world's partition solver
//                  (partition_solver.h; solver_kea.cpp) finds the row
//                  impulses;
//   6. apply       (apply.cpp) impulses to the bodies' velocities, forces
//                  and warm-start memory to the constraints;
//   7. integrate   (advance.cpp) positions and orientations; then the
//                  bounces owed (bounce.cpp) and, if the world asks for it,
//                  the point joints' projection (project_joints.cpp);
//   8. sleep       (sleep.cpp) a partition whose bodies have all stayed below
//                  every threshold for the alive window goes to sleep.
//
// Memory. The per-partition arrays of stages 3-6 come from the step arena
// (arena.h), given back after each partition; the step-long arrays of stage
// 1 are vectors kept in StepScratch from step to step. Both only grow, so
// once a scene has reached its size a step allocates nothing (tested by
// counting allocations).
#pragma once

#include <span>
#include <vector>

#include "arena.h"
#include "constraint.h"
#include "partition_solver.h"
#include "problem.h"
#include "solve_warnings.h"
#include "step_budget.h"

namespace karma::mdt {

struct Partition {
  int bodyStart, bodyCount;              // into StepScratch::partBodies
  int constraintStart, constraintCount;  // into StepScratch::partConstraints
};

// The rows of one partition (stage 3), in the arena.
struct PartitionRows {
  std::span<Row> rows;                // every row written, constraint by constraint
  std::span<int> constraintRowStart;  // per constraint of the partition, +1
  std::span<char> keep;               // 0: dropped by capping
  std::span<int> solveIndex;          // row -> index among the kept rows, or -1
  int count = 0;                      // rows written
  int kept = 0;                       // rows kept
  int bounceRows = 0;                 // rows written with bounceAfter > 0 (stage 7b has work)
  // The largest |J| value and |softness| of the rows written, all finite
  // (as BodySpaceProblem's: -1 until collectRows has scanned them).
  MeReal largestJ = -1, largestSoftness = -1;
};

struct StepScratch {
  StepScratch();
  ~StepScratch();
  StepScratch(const StepScratch &) = delete;
  StepScratch &operator=(const StepScratch &) = delete;

  std::vector<MdtBody *> bodies;             // enabled, sorted
  std::vector<MdtConstraint *> constraints;  // simulated, sorted
  std::vector<int> adjStart, adj, adjFill;   // body -> constraints (indices)
  std::vector<MdtBody *> partBodies;
  std::vector<MdtConstraint *> partConstraints;
  std::vector<MdtConstraint *> found;  // one partition's constraints, while searching
  std::vector<Partition> partitions;
  std::vector<int> partitionRows;   // rows solved per partition (after capping), by partition index
  std::vector<int> freePartitions;  // indices of the partitions of one body and no constraint
  StepArena arena;
  PartitionSolver *activeSet;  // the solvers, one of each
  PartitionSolver *pgs;
  MdtWorldStepStats stats;
  SolveWarnings solveWarnings;  // the exact solver's, rate-limited
  StepBudget budget;            // MdtWorldSetStepBudget
  std::uint64_t step = 0;       // MdtWorldStep calls so far, this one included (SolverSettings::step)
};

// Stage 1: fills bodies, constraints, partitions (waking bodies).
void buildPartitions(MdtWorldID world, StepScratch &s);
// Stages 2-8 for partition `index` (pipeline.cpp); true if it went to sleep.
bool stepPartition(MdtWorldID world, StepScratch &s, int index, const StepContext &ctx);
// Stages 2, 7 and 8 for every partition in freePartitions, one stage at a
// time over the batch (free_bodies.cpp); how many went to sleep.
int stepFreeBodies(MdtWorldID world, StepScratch &s, const StepContext &ctx);

// Stage 2.
void predictPartition(MdtWorldID world, StepScratch &s, const Partition &p, MeReal h);
// Fills each body's geometric stiffness from last step's constraint forces
// (stabilize.cpp); called before the velocities are predicted.
void accumulateGeometricStiffness(MdtWorldID world, StepScratch &s, const Partition &p);
// Stage 3.
PartitionRows collectRows(MdtWorldID world, StepScratch &s, const Partition &p, const StepContext &ctx);
// Matrix capping: clears keep[] of the rows to drop so that at most maxRows
// remain, in the guide's order (or by the importance callback).
void capRows(MdtWorldID world, std::span<const Row> rows, std::span<char> keep, int maxRows);
// Stage 4.
BodySpaceProblem assembleProblem(StepScratch &s, const Partition &p, const PartitionRows &rows, const StepContext &ctx);
// Stage 5: the impulses of the kept rows (problem.rowCount of them).
std::span<MeReal> solveProblem(MdtWorldID world, StepScratch &s, const BodySpaceProblem &problem);
// Stage 6: lambda holds the kept rows' impulses.
void applyImpulses(StepScratch &s, const Partition &p, const PartitionRows &rows, std::span<const MeReal> lambda,
                   const StepContext &ctx);
// Stage 7.
void integratePartition(StepScratch &s, const Partition &p, MeReal h);
// Stage 7b: the bounces owed by impacts found apart (bounce.cpp); nothing
// at all when no row asked for one (rows.bounceRows = 0).
void applyBounces(StepScratch &s, const Partition &p, const PartitionRows &rows, const BodySpaceProblem &problem);
// Stage 7c, optional (MdtWorldSetJointProjection): the point joints'
// anchors brought back together by position impulses (project_joints.cpp).
void projectJoints(MdtWorldID world, StepScratch &s, const Partition &p);
// Stage 8: updates each body's rest time from its new velocities and
// accelerations; true if the whole partition has rested for the alive window
// and was put to sleep.
bool autoDisablePartition(MdtWorldID world, StepScratch &s, const Partition &p, MeReal h);

}  // namespace karma::mdt
