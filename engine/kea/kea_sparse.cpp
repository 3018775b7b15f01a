/* kea_sparse.cpp: the solvers for problems whose matrix comes in compressed
 * sparse rows (what Mdt builds: A's sparsity follows which rows share a
 * body, so a chain gives a banded A with a handful of entries per row).
 *
 * Same contract, options, statuses and warnings as the dense solvers
 * (kea_lcp.h); only the matrix operations differ:
 *
 *  - Active set: the pivoting logic is the dense solver's, shared through
 *    kea_activeset_core.h; the free block (A + eps I)_FF is gathered from
 *    the CSR rows and factorised by an envelope LDL^T (small or banded
 *    blocks) or a sparse LDL^T in a fill-reducing order (large ones), kept
 *    while the free set does not change (kea_sparse_backend.h). A banded
 *    block costs O(m) to factorise and solve instead of O(m^3).
 *
 *  - PGS: the dense sweep, visiting only each row's stored entries: O(nnz)
 *    per sweep.
 *
 * Apart from the linear solves every step is O(n + nnz), so the cost of a
 * chain grows linearly with its length.
 *
 * Workspace. Every array of a solve lives in the caller's KeaWorkspace
 * (the core's sets, bounds and best iterate, the backend's row lists,
 * envelope factor and residual, PGS's bounds and diagonal) and the answer
 * in the caller's KeaResult; std::vector keeps its capacity on clear(),
 * resize() and assign(), so once a workspace has solved a problem with n
 * rows, solves of problems no larger whose free blocks take the envelope
 * path, and PGS solves, allocate nothing. The allocating entry point runs
 * the same code on a workspace of its own. */
#include "kea_activeset_core.h"
#include "kea_sparse_backend.h"

#include <algorithm>
#include <cmath>

namespace karma::kea {
namespace detail {

/* The arrays of a PGS solve (see SparsePgs). */
struct PgsScratch {
  std::vector<MeReal> lo, hi, diag, best, w;
};

}  // namespace detail

struct KeaWorkspace {
  detail::ActiveSetScratch activeSet;
  detail::SparseBackend backend;
  detail::PgsScratch pgs;
  KeaResult retry; /* the cold retry of a cycling warm start (RetryCold) */
};

namespace {

/* Projected Gauss-Seidel over the CSR rows (see kea_pgs.cpp for the
 * method). */
void SparsePgs(const SparseLcpProblem &p, const KeaOptions &o, const char *name, detail::PgsScratch &s, KeaResult &r) {
  const auto n = static_cast<std::size_t>(p.n);
  const MeReal eps = o.epsilon;
  const int cap = o.maxIterations > 0 ? o.maxIterations : 50;
  const detail::RowView rows = detail::Rows(p);
  const MeReal threshold = detail::SolvedThreshold(rows, o);

  detail::InitialLambda(o, n, r.lambda);
  r.w.assign(n, MeReal(0));
  r.factorizations = 0;
  r.frictionRounds = 0;
  r.warmStartAccepted = false;
  r.threshold = threshold;
  r.staleSolves = r.staleIterations = r.factorUpdates = 0;

  detail::ComputeBounds(rows, r.lambda, s.lo, s.hi);
  for (std::size_t i = 0; i < n; ++i) r.lambda[i] = std::clamp(r.lambda[i], s.lo[i], s.hi[i]);

  s.diag.assign(n, MeReal(0));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
      if (static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)]) == i)
        s.diag[i] = p.val[static_cast<std::size_t>(k)] + eps;

  s.best = r.lambda;
  s.w.resize(n);
  const platform::Kernels &kernels = detail::KernelsOf(o);
  MeReal bestResidual = detail::SparseMultiplyResidual(kernels, p, eps, r.lambda, s.w);
  const bool friction = !p.findex.empty();
  int sweeps = 0;
  while (bestResidual > threshold && sweeps < cap) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.diag[i] > 0)) continue; /* a null row: nothing to gain from it */
      const int k0 = p.rowStart[i];
      const MeReal wi =
          (-p.b[i] + eps * r.lambda[i]) +
          platform::GatherDot(kernels, p.val.data() + k0, p.col.data() + k0, r.lambda.data(), p.rowStart[i + 1] - k0);
      MeReal rowLo = s.lo[i], rowHi = s.hi[i];
      if (friction && p.findex[i] >= 0) {
        const MeReal limit = p.mu[i] * std::max(r.lambda[static_cast<std::size_t>(p.findex[i])], MeReal(0));
        rowLo = -limit;
        rowHi = limit;
      }
      r.lambda[i] = std::clamp(r.lambda[i] - wi / s.diag[i], rowLo, rowHi);
    }
    ++sweeps;
    const MeReal residual = detail::SparseMultiplyResidual(kernels, p, eps, r.lambda, s.w);
    if (residual < bestResidual) {
      bestResidual = residual;
      s.best = r.lambda;
    }
  }

  r.lambda = s.best;
  r.residual = detail::SparseMultiplyResidual(kernels, p, eps, r.lambda, r.w);
  r.iterations = sweeps;
  if (r.residual <= threshold) {
    r.status = KeaStatus::Solved;
  } else {
    r.status = KeaStatus::IterationLimit;
    detail::WarnIterationLimit(o, name, sweeps, r.residual);
  }
}

/* A solve with a stale factor (KeaOptions::factorMemory) leaves residual
 * components at most the solved threshold divided by this: its inexactness
 * stays far below what decides "Solved". */
constexpr MeReal kStaleTargetDivisor = 64;

/* A warm-started active-set solve that ended in a cycle is repeated once
 * from a cold start (lambda = 0 clamped into the bounds), with what is left
 * of a caller's iteration cap (the default cap afresh); the better of the
 * two answers is returned, and the counts are summed. A warm start near a
 * solution of a changed problem can steer the pivoting into a cycle that
 * the cold start's path avoids. */
void RetryCold(const SparseLcpProblem &p, const KeaOptions &o, MeReal target, KeaWorkspace &workspace,
               KeaResult &result) {
  KeaOptions cold = o;
  cold.warmStart = {};
  if (o.maxIterations > 0) {
    cold.maxIterations = o.maxIterations - result.iterations;
    if (cold.maxIterations <= 0) {
      detail::WarnCycle(o, "KeaSolveSparse", result.iterations, result.residual);
      return;
    }
  }
  cold.warnings = false; /* the final status is reported below */
  KeaResult &retry = workspace.retry;
  workspace.backend.useKernels(detail::KernelsOf(o));
  workspace.backend.reset(p, o.epsilon, o.envelopeRows, o.factorMemory, target);
  workspace.backend.allowUpdates(o.factorUpdateRows);
  detail::ActiveSetCore(detail::Rows(p), cold, "KeaSolveSparse", workspace.backend, workspace.activeSet, retry);
  retry.iterations += result.iterations;
  retry.frictionRounds += result.frictionRounds;
  retry.factorizations = result.factorizations + workspace.backend.factorizations();
  retry.staleSolves = result.staleSolves + workspace.backend.staleSolves();
  retry.staleIterations = result.staleIterations + workspace.backend.staleIterations();
  retry.factorUpdates = result.factorUpdates + workspace.backend.factorUpdates();
  if (retry.status == KeaStatus::Solved || retry.residual <= result.residual) {
    std::swap(result.lambda, retry.lambda);
    std::swap(result.w, retry.w);
    result.status = retry.status;
    result.residual = retry.residual;
  } else {
    result.status = KeaStatus::CycleDetected; /* the warm start's answer stays */
  }
  result.iterations = retry.iterations;
  result.frictionRounds = retry.frictionRounds;
  result.factorizations = retry.factorizations;
  result.staleSolves = retry.staleSolves;
  result.staleIterations = retry.staleIterations;
  result.factorUpdates = retry.factorUpdates;
  if (result.status == KeaStatus::CycleDetected)
    detail::WarnCycle(o, "KeaSolveSparse", result.iterations, result.residual);
  else if (result.status == KeaStatus::IterationLimit)
    detail::WarnIterationLimit(o, "KeaSolveSparse", result.iterations, result.residual);
}

/* The BadInput answer in `result`'s own vectors. */
void BadInput(int n, KeaResult &result) {
  const auto size = static_cast<std::size_t>(std::max(n, 0));
  result.lambda.assign(size, MeReal(0));
  result.w.assign(size, MeReal(0));
  result.status = KeaStatus::BadInput;
  result.iterations = result.factorizations = result.frictionRounds = 0;
  result.staleSolves = result.staleIterations = result.factorUpdates = 0;
  result.warmStartAccepted = false;
  result.residual = result.threshold = 0;
}

}  // namespace

KeaWorkspace *KeaWorkspaceCreate() { return new KeaWorkspace; }
void KeaWorkspaceDestroy(KeaWorkspace *workspace) { delete workspace; }

namespace {

/* Whether the solve of `p` applies A through its operator: only when it
 * starts on a kept factor (its stale solves then need no entry of A) and
 * the operator vouches for A's finiteness (the values' check is skipped
 * for it: ValidateSparse, ValidateSparseValues). Decided once per call, so
 * a solve never mixes the operator's products with the stored rows'. */
bool AppliesOperator(const SparseLcpProblem &p, const KeaOptions &o, const KeaWorkspace &workspace) {
  return p.op && o.method == KeaMethod::ActiveSet &&
         workspace.backend.startsStale(p, o.epsilon, o.envelopeRows, o.factorMemory) && p.op->entriesFinite();
}

void SolveSparse(const SparseLcpProblem &p, const KeaOptions &o, KeaWorkspace &workspace, KeaResult &result) {
  static const char *const kName = "KeaSolveSparse";
  /* A problem with the kept factor's structure had it validated before. */
  const bool knownStructure =
      o.trustedStructure || (o.factorMemory != KeaFactorMemory::Off && o.method == KeaMethod::ActiveSet &&
                             workspace.backend.keptStructure(p));
  if (knownStructure ? !detail::ValidateSparseValues(p, o, kName) : !detail::ValidateSparse(p, o, kName)) {
    BadInput(p.n, result);
    return;
  }
  if (o.method == KeaMethod::PGS) {
    SparsePgs(p, o, kName, workspace.pgs, result);
    return;
  }
  const detail::RowView rows = detail::Rows(p);
  const MeReal target = detail::SolvedThreshold(rows, o) / kStaleTargetDivisor;
  const bool warm = !o.warmStart.empty();
  KeaOptions first = o;
  first.warnings = o.warnings && !warm; /* a cycle here is retried, not reported */
  workspace.backend.useKernels(detail::KernelsOf(o));
  workspace.backend.reset(p, o.epsilon, o.envelopeRows, o.factorMemory, target);
  workspace.backend.allowUpdates(o.factorUpdateRows);
  detail::ActiveSetCore(rows, first, kName, workspace.backend, workspace.activeSet, result);
  result.factorizations = workspace.backend.factorizations();
  result.factorUpdates = workspace.backend.factorUpdates();
  result.staleSolves = workspace.backend.staleSolves();
  result.staleIterations = workspace.backend.staleIterations();
  if (warm && result.status == KeaStatus::CycleDetected)
    RetryCold(p, o, target, workspace, result);
  else if (warm && result.status == KeaStatus::IterationLimit)
    detail::WarnIterationLimit(o, kName, result.iterations, result.residual);
  /* A kept warm start solved nothing, so it says nothing of the solves the
   * keep rule prices (kea_sparse_backend.h, StaleRecord::solves). */
  if (!result.warmStartAccepted) workspace.backend.learnFrictionRounds(result.frictionRounds);
}

}  // namespace

void KeaSolveSparse(const SparseLcpProblem &p, const KeaOptions &o, KeaWorkspace &workspace, KeaResult &result) {
  workspace.backend.offerOperator(p.op != nullptr);
  if (!p.op || AppliesOperator(p, o, workspace)) {
    SolveSparse(p, o, workspace, result);
    return;
  }
  p.op->assemble();
  SparseLcpProblem stored = p;
  stored.op = nullptr;
  SolveSparse(stored, o, workspace, result);
}

KeaResult KeaSolveSparse(const SparseLcpProblem &p, const KeaOptions &o) {
  KeaWorkspace workspace;
  KeaResult result;
  KeaSolveSparse(p, o, workspace, result);
  return result;
}

}  // namespace karma::kea
