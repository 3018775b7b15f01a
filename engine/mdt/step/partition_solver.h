// partition_solver.h: the interface between the step and its solvers. Not
// installed.
//
// A partition solver receives one partition's body-space problem
// (problem.h) and writes one impulse per row. It may take scratch from the
// step arena (given back after the partition) and keep its own memory
// across steps, but it must not allocate from the heap once problems stop
// growing. Contract of the answer: the LCP of problem.h solved to the
// settings' tolerance, or the best iterate found when a limit stops it
// (report.solved false); on bad input, all impulses zero and
// report.badInput. Solvers today: the exact active-set method (Kea, on the
// assembled matrix A; solver_kea.cpp) and projected Gauss-Seidel in body
// space (solver_pgs.cpp).
#pragma once

#include <cstdint>

#include "arena.h"
#include "problem.h"
#include "kernels.h"

namespace karma::mdt {

struct SolverSettings {
  int maxIterations = 0;  // 0: the solver's default
  MeReal tolerance = 0;   // 0: the solver's default
  // The world's platform backend for the exact solver's array kernels
  // (kernels.h); nullptr: the process default. It changes speed only.
  const platform::Kernels *kernels = nullptr;
  // Exact solver: keep a warm start that already meets the tolerance
  // (MdtWorldSetKeaAcceptWarmStart).
  bool acceptWarmStart = false;
  // The world's step, counted from 1: what a solver remembers of a
  // partition from step - 1 is last step's; from earlier, it is stale.
  std::uint64_t step = 0;
};

struct SolveReport {
  int iterations = 0;
  MeReal residual = 0;
  int factorizations = 0;          // exact solver: factorisations of a free block
  int frictionRounds = 0;          // exact solver: friction fixed-point rounds beyond the first
  int staleSolves = 0;             // exact solver: linear solves with last step's factor
  int factorUpdates = 0;           // exact solver: pivots served by an update of a factor
  bool warmStartAccepted = false;  // exact solver: the warm start was the answer
  bool solved = true;
  bool cycle = false;  // stopped by a detected cycle
  bool badInput = false;
};

class PartitionSolver {
 public:
  virtual ~PartitionSolver() = default;
  virtual const char *name() const = 0;
  // lambda: rowCount values, written.
  virtual SolveReport solve(const BodySpaceProblem &problem, const SolverSettings &settings, StepArena &arena,
                            std::span<MeReal> lambda) = 0;
};

// The solvers the world can choose (MdtWorldSetKeaMethod): each lives as
// long as the world's step scratch.
PartitionSolver *CreateKeaActiveSetSolver();
PartitionSolver *CreatePgsSolver();

}  // namespace karma::mdt
