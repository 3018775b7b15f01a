/* kea_lcp.h: Kea's boxed linear complementarity problem (LCP) solvers.
 *
 * INTERNAL header (namespace karma::kea), not part of the public C API. It is
 * standalone: it knows nothing of bodies or constraints. Mdt builds the
 * problem from its constraints and hands it here.
 *
 * ===========================================================================
 * THE CONTRACT
 * ===========================================================================
 *
 * Unknowns. n constraint rows; lambda (n) is the vector of constraint
 * impulses (forces times the time step), one per row.
 *
 * Matrix. A = J M^-1 J^T + eps*I, n x n, dense, row-major, symmetric. J is
 * the constraint Jacobian (one row per constraint row), M the block-diagonal
 * mass matrix of the bodies. J M^-1 J^T is symmetric positive SEMI-definite:
 * it is singular whenever rows are redundant (two identical contacts, a
 * hinge closing a loop) or the configuration is degenerate. The caller passes
 * J M^-1 J^T in `A`; Options::epsilon adds eps on the diagonal (the solver
 * never changes the caller's array). Only symmetry is assumed, not checked.
 *
 * Slack. w = A*lambda - b (A including eps*I). For a velocity-level
 * time-stepper w is the constraint-space velocity after the step.
 *
 * Bounds. Row i has lo_i <= lambda_i <= hi_i. lo_i may be -infinity and hi_i
 * +infinity; any value with magnitude >= MEINFINITY (or an IEEE infinity)
 * means "unbounded on that side". Typical rows:
 *     joint (bilateral) row:  (-inf, +inf)
 *     contact normal row:     [0, +inf)
 *     limited motor row:      [-Fmax*h, +Fmax*h]
 *
 * Complementarity. The solution satisfies, for every row i,
 *     lambda_i = lo_i            =>  w_i >= 0
 *     lambda_i = hi_i            =>  w_i <= 0
 *     lo_i < lambda_i < hi_i     =>  w_i  = 0
 * (a row with lo_i = hi_i is fixed at that value and w_i is free). With only
 * infinite bounds this is the linear system A*lambda = b.
 *
 * Friction. A row i with findex[i] = j >= 0 is a friction row tied to the
 * normal row j: its bounds are not lo_i/hi_i but
 *     lo_i = -mu_i * max(lambda_j, 0),   hi_i = +mu_i * max(lambda_j, 0),
 * recomputed from the current lambda_j as the solver proceeds (a box
 * approximation of the Coulomb cone). findex[j] of a normal row must be -1.
 * This makes the problem a nonlinear complementarity problem; both solvers
 * handle it approximately, by iterating the bounds to a fixed point (see
 * KeaSolveActiveSet). It converges in practice; if not, the iteration cap
 * applies like any other.
 *
 * Epsilon (eps, Options::epsilon, >= 0). Regularisation and constraint
 * softness: (J M^-1 J^T + eps*I) is positive definite for any eps > 0, so a
 * solution always exists and is unique, even for redundant or singular
 * constraint sets. The price is compliance: a row behaves like a stiff spring
 * with 1/eps like a spring constant (eps has units time^2/mass for force-level
 * rows). Karma's default is 0.01.
 *
 * Gamma (error reduction) lives in the right-hand side, which is the
 * CALLER's job to build. For a velocity-level step of length h:
 *     b = -(gamma / h) * error - J v - h * J M^-1 f_ext
 * where error is the constraint's position error (penetration depth, joint
 * separation), v the current body velocities and f_ext the external forces.
 * gamma in [0, 1] is the fraction of the position error removed in one step
 * (gamma*h should stay below 0.5). The solver never sees gamma or h.
 *
 * Solved. The residual of an iterate is the largest complementarity
 * violation over the rows, measured with the natural map
 *     r_i = | lambda_i - clamp(lambda_i - w_i, lo_i, hi_i) |
 * which is zero exactly when row i satisfies its bounds and its
 * complementarity condition (friction bounds taken from that same iterate).
 * The problem is Solved when max_i r_i <= tolerance * (1 + max_i |b_i|).
 *
 * Iteration cap. If Options::maxIterations is reached before that, the
 * solver returns the best iterate it saw (lowest residual), status
 * IterationLimit, and, if Options::warnings is set, emits the MeWarning
 * "Kea: maximum number of iterations exceeded ...".
 *
 * Cycles. The active-set method can revisit an active set it has already
 * tried (only possible through rounding or a matrix that is not positive
 * definite, e.g. eps = 0 with redundant rows). It detects the repeat (of a
 * set tried since the count of infeasible rows last reached a new low; see
 * kea_activeset.cpp), stops,
 * returns the best iterate with status CycleDetected and (if warnings are
 * on) the MeWarning "Kea: cycle has been detected ...".
 *
 * Bad input. Mismatched array sizes, NaN anywhere, lo_i > hi_i, lo_i = +inf,
 * hi_i = -inf, negative or NaN mu or eps, a findex out of range or pointing
 * at another friction row: status BadInput, lambda and w all zeros (n of
 * them when n >= 0), one MeWarning naming the problem (always emitted), no
 * crash.
 *
 * ===========================================================================
 * Sparsity. KeaSolveActiveSet / KeaSolvePGS are the dense reference
 * implementation (A formed and factorised densely, O(n^3) per
 * factorisation); they are the specification the sparse path must agree
 * with. KeaSolveSparse (kea_sparse.cpp) takes A in CSR, as Mdt builds it
 * (A's sparsity follows body sharing), and is what the step uses: the same
 * active-set logic (shared code, kea_activeset_core.h) with the free block
 * factorised by an envelope (profile) LDL^T for blocks of at most 96 rows
 * or banded ones, else by a sparse LDL^T under an AMD ordering
 * (kea_sparse_backend.h; KeaOptions::envelopeRows overrides the choice);
 * the factorisation is reused while the free set is unchanged. PGS sweeps
 * the CSR rows. A chain or a stack (banded A) costs O(n) per pivot step /
 * sweep.
 *
 * Workspace. KeaSolveSparse with a KeaWorkspace keeps every array of the
 * solve in the workspace and writes into the caller's KeaResult: once a
 * workspace has solved a problem with n rows, solving problems with at most
 * n rows allocates nothing, except on the sparse-LDL^T path (blocks over 96
 * rows that are not banded), a breakdown (least-squares fallback), an
 * unusually long single-pivoting history, and the warnings.
 * Factor memory (KeaOptions::factorMemory): the workspace keeps the last
 * factorisation, and the next problem of the same sparsity is solved with
 * it as a preconditioner while its free set is unchanged.
 * TODO (sparsity): still open: rank-one updates of the factorisation
 * between pivot steps instead of refactorising.
 * ======================================================================== */
#ifndef KARMA_KEA_LCP_H
#define KARMA_KEA_LCP_H

#include "MePrecision.h"
#include "kernels.h"

#include <cstdint>
#include <span>
#include <vector>

namespace karma::kea {

/* One boxed LCP. Spans refer to caller-owned arrays that must stay alive
 * during the solve. */
struct LcpProblem {
  int n = 0;
  std::span<const MeReal> A;   /* n*n, row-major, symmetric: J M^-1 J^T */
  std::span<const MeReal> b;   /* n */
  std::span<const MeReal> lo;  /* n; ignored on friction rows */
  std::span<const MeReal> hi;  /* n; ignored on friction rows */
  std::span<const int> findex; /* empty (no friction) or n; -1 = none */
  std::span<const MeReal> mu;  /* n when any findex >= 0 (read on friction rows) */
};

enum class KeaMethod {
  ActiveSet, /* exact: active-set guessing with a Cholesky (LDL^T) solve */
  PGS        /* projected Gauss-Seidel: a fixed budget of cheap sweeps */
};

enum class KeaStatus { Solved, IterationLimit, CycleDetected, BadInput };

/* KeaOptions::factorMemory. WhenCheaper keeps a factor only where the cost
 * model of kea_sparse_backend.h (StaleSolveWorthIt) expects stale solves
 * to cost less than a factorisation: always for the sparse LDL^T, for an
 * envelope while the stale solves a problem is expected to take (at the
 * iterations, failure rate and friction rounds its workspace has seen)
 * cost less than refactorising it (and, for a problem with an operator,
 * assembling A). */
enum class KeaFactorMemory { Off, WhenCheaper, Always };

/* A short name for a status ("Solved", ...), for messages and tests. */
const char *KeaStatusName(KeaStatus status);

struct KeaOptions {
  KeaMethod method = KeaMethod::ActiveSet;
  /* The platform backend of the array kernels (engine/platform/kernels.h);
   * nullptr: platform::DefaultKernels(). Every backend gives the same bits,
   * so this chooses speed only. */
  const platform::Kernels *kernels = nullptr;
  /* Active set: the number of linear solves (pivot steps) allowed over the
   * whole solve. PGS: the number of sweeps over all rows. 0 = the method's
   * default (active set: 10*n + 20, plus 20*n + 100 with friction rows; PGS: 50). */
  int maxIterations = 0;
  /* Relative tolerance of "Solved" (see the contract); 0 = default
   * (1e-4 for float MeReal, 1e-10 for double). */
  MeReal tolerance = 0;
  /* eps added to the diagonal of A; must be >= 0. */
  MeReal epsilon = 0;
  /* Optional initial lambda (empty or n values), e.g. last step's impulses.
   * The active-set method derives its initial active set from it; PGS starts
   * its sweeps from it. Without it both start from lambda = 0 clamped into
   * the bounds. It may be the result's own lambda (n values). */
  std::span<const MeReal> warmStart;
  /* Emit MeWarning on IterationLimit / CycleDetected. BadInput always warns. */
  bool warnings = true;
  /* KeaSolveSparse's choice of factorisation for a free block of m rows
   * (see kea_sparse_backend.h): 0 = the default rule (the envelope LDL^T
   * when m <= 96 or the block's envelope is a band of mean width <= 32,
   * else the sparse LDL^T); > 0: the envelope LDL^T exactly when m <=
   * envelopeRows; < 0: always the sparse LDL^T. The answer is the same up to
   * rounding; only cost and allocation differ (the sparse path allocates). */
  int envelopeRows = 0;
  /* KeaSolveSparse with a workspace, active set: whether the workspace
   * keeps its factorisation after the solve and starts from it when the
   * next problem has the same sparsity (rowStart, col) and epsilon. While
   * the free set is the one it was made for, the free block is then solved
   * by conjugate gradients preconditioned with that stale factor, to a
   * residual far below the solved threshold, and refactorised only if that
   * does not converge within a few iterations (kea_sparse_backend.h). For
   * a caller that solves the same system, slightly changed, step after
   * step (a resting scene). The answer meets the same contract; only
   * rounding differs from a fresh factor. */
  KeaFactorMemory factorMemory = KeaFactorMemory::Off;
  /* KeaSolveSparse: the caller built rowStart and col itself and vouches
   * that they meet the CSR rules above (starts ascending from 0, columns in
   * range and strictly ascending within a row, every diagonal present), so
   * only the values, b, the bounds and the options are checked. A caller
   * that breaks the promise gets undefined behaviour, not BadInput. */
  bool trustedStructure = false;
  /* Active set with a warm start: first check the warm start itself (one
   * product with A) and return it, without a linear solve, when its
   * residual is already at most the solved threshold over
   * warmAcceptDivisor. The answer meets the contract with room to spare
   * but is not refined further, where a solve usually ends near rounding.
   * For a caller whose problems change little from one call to the next (a
   * scene at rest); a workspace that sees its checks fail makes them
   * rarely (ActiveSetScratch::warmAccepted). Off: the warm start only
   * chooses the initial sets. */
  bool acceptWarmStart = false;
  /* At least 1 (else BadInput). Not the threshold itself by default: a
   * caller that passes each answer back as the next warm start keeps the
   * same impulses step after step against a problem that slowly changes,
   * so a kept answer's residual climbs to the divisor's bound and stays
   * there (kea_activeset_core.h, kWarmAcceptDivisor, says what that did
   * at a divisor of 1 and 4). A caller that knows how its last answer
   * came may loosen it for one call at a time (Mdt's exact solver:
   * warm_keep_rule.h, kLooseKeepDivisor). */
  MeReal warmAcceptDivisor = 16;
  /* KeaSolveSparse, active set: a pivot whose free set differs by at most
   * this many rows (freed and clamped together; at most 8, the default)
   * from the rows of the dense factor made for this problem solves the new
   * block through that factor and a capacitance matrix of that size
   * instead of refactorising (kea_schur_update.h), and refines the answer
   * from its residual; a singular or nearly singular change is factorised
   * instead, as are changes beyond the limit. 0: every new free set is
   * factorised. Rounding and cost differ; what the answer is checked
   * against does not. */
  int factorUpdateRows = 8;
};

struct KeaResult {
  std::vector<MeReal> lambda; /* n */
  std::vector<MeReal> w;      /* n: A*lambda - b, eps included */
  KeaStatus status = KeaStatus::BadInput;
  int iterations = 0;  /* linear solves (active set) or sweeps (PGS) */
  MeReal residual = 0; /* max complementarity violation (absolute) */
  /* The solved threshold the residual was held to (SolvedThreshold: the
   * tolerance scaled by the problem); 0 for BadInput. */
  MeReal threshold = 0;
  /* Statistics (active set; 0 for PGS): factorisations of a free block (a
   * solve whose free set is the previous solve's re-uses its factor), and
   * friction fixed-point rounds that needed another inner solve (0 when
   * the first consistent free set already met its own friction bounds). */
  int factorizations = 0;
  int frictionRounds = 0;
  /* Solves made with a stale factor (KeaOptions::factorMemory) and their
   * conjugate-gradient iterations. */
  int staleSolves = 0;
  int staleIterations = 0;
  /* Pivots served by a Schur-complement update of a factor instead of a
   * factorisation (KeaOptions::factorUpdateRows). */
  int factorUpdates = 0;
  /* Whether the answer is the warm start itself, accepted by
   * KeaOptions::acceptWarmStart without a linear solve. */
  bool warmStartAccepted = false;
};

/* A held by its caller as a product, e.g. A = J M^-1 J^T + diag(s) (Mdt's
 * rows), so that a solve can apply it without its entries. KeaSolveSparse
 * (active-set method) decides once per call: when the solve starts on a
 * kept factor (factor memory, the same sparsity) and entriesFinite() holds,
 * every product with A in that call (a cold retry included) goes through
 * times, absTimesMax and timesAndAbsTimesMax, and A's entries are read
 * only after assemble(), when the solve factorises. Otherwise it calls
 * assemble() first and solves with the stored values, checked as usual.
 * One call never mixes the two.
 * Contract:
 *  - times: y[a] = (A x)_i with i = rows[a] (i = a when rows is null) for
 *    a < count; x holds n values; y does not overlap x. Deterministic: the
 *    same x gives the same bits, and row i's value does not depend on
 *    which other rows are asked for, or in what order (Kea reuses a
 *    product over every row as A x). Its rounding may differ from the
 *    CSR values' row sums.
 *  - absTimesMax: the largest over those rows of a bound B_i >= sum_j
 *    |A_ij| |x_j| that also bounds times' rounding, as sum_j |A_ij x_j|
 *    does for a row sum (for a product J W J^T: (|J| |W| |J^T| |x|)_i).
 *  - timesAndAbsTimesMax: times(rows, count, x, y), returning
 *    absTimesMax(rows, count, x), bit for bit as the two calls; an
 *    operator may override it to do both in one pass (the default makes
 *    the two calls).
 *  - assemble: fills the problem's val with A's entries in the CSR layout
 *    (exactly symmetric); idempotent. Until it is called val may hold
 *    anything, and the solve does not read it.
 *  - entriesFinite: true only when A's entries and the operator's own
 *    factors are finite, with room for their rounding (the solve does not
 *    check values it never reads; a product with a large x may still
 *    overflow, as A x may, and a solve treats a non-finite residual as
 *    unsolved). */
class SparseLcpOperator {
 public:
  virtual void times(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const = 0;
  virtual MeReal absTimesMax(const int *rows, std::size_t count, const MeReal *x) const = 0;
  virtual MeReal timesAndAbsTimesMax(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const {
    times(rows, count, x, y);
    return absTimesMax(rows, count, x);
  }
  virtual void assemble() const = 0;
  virtual bool entriesFinite() const = 0;

 protected:
  SparseLcpOperator() = default;
  SparseLcpOperator(const SparseLcpOperator &) = default;
  SparseLcpOperator &operator=(const SparseLcpOperator &) = default;
  ~SparseLcpOperator() = default;
};

/* The same problem with A in compressed sparse rows: both triangles stored,
 * columns ascending within a row, every diagonal entry present. This is what
 * Mdt hands over: A's sparsity follows which rows share a body. */
struct SparseLcpProblem {
  int n = 0;
  std::span<const int> rowStart; /* n + 1 */
  std::span<const int> col;      /* rowStart[n] */
  std::span<const MeReal> val;   /* rowStart[n] */
  std::span<const MeReal> b, lo, hi;
  std::span<const int> findex;
  std::span<const MeReal> mu;
  /* The caller's name for the sparsity (n, rowStart, col), or 0 for none.
   * Two problems with the same nonzero stamp must have the same sparsity:
   * a solve that finds the stamp of the problem its workspace last kept a
   * factor or an ordering for takes the sparsity as known without
   * comparing the arrays. Unnamed problems are compared entry by entry. */
  std::uint64_t sparsityStamp = 0;
  /* When set, A may be applied through it (SparseLcpOperator), and val is
   * read only after its assemble(); rowStart and col hold A's layout all
   * the same. */
  const SparseLcpOperator *op = nullptr;
};

/* Solves a sparse problem with the same contract and options as KeaSolve
 * (see kea_sparse.cpp for how the sparsity is used). */
KeaResult KeaSolveSparse(const SparseLcpProblem &problem, const KeaOptions &options);

/* Scratch a caller keeps from one solve to the next (e.g. one per world), so
 * that repeated solves of problems no larger than earlier ones allocate
 * nothing: every array only grows. Opaque; create with KeaWorkspaceCreate. */
struct KeaWorkspace;
KeaWorkspace *KeaWorkspaceCreate();
void KeaWorkspaceDestroy(KeaWorkspace *workspace);

/* The same solve with the caller's workspace; the answer goes to `result`,
 * whose vectors keep their capacity from call to call. */
void KeaSolveSparse(const SparseLcpProblem &problem, const KeaOptions &options, KeaWorkspace &workspace,
                    KeaResult &result);

/* The exact method (see kea_activeset.cpp). */
KeaResult KeaSolveActiveSet(const LcpProblem &problem, const KeaOptions &options);

/* Projected Gauss-Seidel (see kea_pgs.cpp). */
KeaResult KeaSolvePGS(const LcpProblem &problem, const KeaOptions &options);

/* Dispatches on options.method. */
KeaResult KeaSolve(const LcpProblem &problem, const KeaOptions &options);

/* The contract's residual of a given lambda: max_i r_i, with w = (A + eps I)
 * lambda - b written to `w` when it is not empty (n values). Assumes a valid
 * problem. */
MeReal KeaResidual(const LcpProblem &problem, MeReal epsilon, std::span<const MeReal> lambda, std::span<MeReal> w = {});

/* The tolerance a given options value resolves to (its default when 0). */
MeReal KeaDefaultTolerance();

}  // namespace karma::kea

#endif
