/* kea_sparse_backend.h: the matrix operations of the active-set core
 * (kea_activeset_core.h) for a matrix in compressed sparse rows (not
 * installed).
 *
 * The free block (A + eps I)_FF is factorised one of three ways:
 *
 *  - Dense LDL^T (kea_dense_ldlt.h), under the default rule, for blocks
 *    of at most kDenseRows rows of a matrix at least a third full
 *    (DenseFits; a car, whose rows all share the chassis), or whose
 *    envelope would cost more (DenseCheaper, kDenseOverCrout; a rag
 *    doll, whose tree has no narrow band in any order): the envelope's
 *    Crout order would be a chain of dot products, each waiting on the
 *    entry before, while the dense updates run in vector lanes
 *    (docs/NOTES.md, "Dense small blocks"). Such a factor is kept as a
 *    stale one (below) only for a caller that offers an operator (then a
 *    stale solve needs neither A's values nor a factorisation; see
 *    kDenseStaleIterations) or under KeaFactorMemory::Always: with A
 *    assembled anyway, refactorising costs about as much as one
 *    conjugate-gradient step.
 *
 *  - Envelope LDL^T (kea_envelope_ldlt.h), allocation-free once its arrays
 *    have grown to the problem, and faster than the sparse LDL^T on small
 *    and on banded blocks; taken when the block has at most kEnvelopeRows
 *    rows or its envelope is a band (mean row width at most
 *    kEnvelopeWidth). The rows keep the order Mdt gave them (contact groups
 *    and joint chains come row by row, body by body, which is already a
 *    band) unless that order's envelope is much larger than the matrix's
 *    nonzeros; then they are renumbered by reverse Cuthill-McKee, once per
 *    problem (a rag doll's tree, a heap).
 *
 *  - Otherwise a sparse LDL^T (Eigen's SimplicialLDLT) in a fill-reducing
 *    order (approximate minimum degree, computed once per problem for the
 *    whole matrix; see computeOrder). This path allocates (Eigen's
 *    factorisation does); it is for blocks of pile size.
 *
 * Either factorisation is kept while the free set does not change (the
 * friction fixed point re-solving with new bounds, a warm start confirming
 * its set): only the right-hand side is rebuilt and solved again. When a
 * pivot changes the free set by at most KeaOptions::factorUpdateRows rows
 * from the rows of a dense factor made for this problem, the new block is
 * solved through that factor and a small capacitance matrix
 * (kea_schur_update.h) instead of refactorising, and refined from the
 * residual the caller computes next (refine); the base stays the factor's
 * rows, so updates do not pile up on one another, and a change beyond the
 * limit, or one the update refuses, refactorises (and becomes the new
 * base). A coupled friction step on an update (its solveWithFactor) is
 * refined the same way.
 *
 * Factor memory (reset with KeaOptions::factorMemory). A
 * factorisation may also outlive its problem: when the next problem has
 * the same sparsity (n, rowStart, col) and eps, the old factor L D L^T of
 * the old block B stays as a *stale* factor. It is the last factorisation
 * made, which after updates is their base, not the answer's set (in a
 * scene at rest, the set the next problem's warm start begins from). While the free set is the one
 * it was made for, the new block A_FF is solved by conjugate gradients
 * preconditioned with it (solveStale): for a scene at rest A_FF - B is
 * tiny, so B^-1 A_FF is close to I and a handful of iterations, each one
 * product with A_FF (O(nnz)) and one solve with the factor (O(envelope)),
 * replace a factorisation (O(envelope * band)). The iteration stops when
 * every component of A_FF x - rhs is within the target the caller gives
 * (far below the solved threshold) or within the rounding of its own
 * computation; after kMaxRefine iterations without that the block is
 * refactorised and solved directly. A factor is kept only where this is
 * expected to pay: always for the sparse LDL^T, for an envelope when its
 * factorisation (and, for a caller with an operator, A's assembly) costs
 * more than the stale solves a problem is expected to take, at the
 * iterations, failure rate and friction rounds this workspace has seen
 * (StaleSolveWorthIt, kStaleIterationsPrior). A stale factor never
 * decides the answer's accuracy, only its cost. A factorisation that
 * breaks down (not positive definite, e.g. eps = 0 with redundant rows)
 * falls back to a dense least-squares solve for blocks up to
 * kDenseFallback rows, and to a slightly shifted sparse LDL^T beyond.
 *
 * A problem with an operator (SparseLcpProblem::op; KeaSolveSparse hands
 * the backend one only for a solve that starts on a kept factor): every
 * product with A (residuals, the stale solves' conjugate gradients,
 * b_F - A_FC lambda_C, the rounding scale) goes through it, and A's
 * entries are read, after the operator's assemble(), only to fill a
 * factorisation or a column (values()). A stale solve that succeeds
 * therefore needs no entry. */
#ifndef KARMA_KEA_SPARSE_BACKEND_H
#define KARMA_KEA_SPARSE_BACKEND_H

#include "kea_dense_ldlt.h"
#include "kea_envelope_ldlt.h"
#include "kea_internal.h"
#include "kea_schur_update.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace karma::kea::detail {

/* w = (A + eps I) lambda - b over the CSR rows (w: n values, not
 * overlapping lambda); returns the contract's residual of lambda. */
MeReal SparseMultiplyResidual(const platform::Kernels &kernels, const SparseLcpProblem &p, MeReal eps,
                              std::span<const MeReal> lambda, std::span<MeReal> w);

/* What a backend remembers of a sparsity (n, rowStart, col) to know it
 * again: the problem's stamp when it has one (SparseLcpProblem::
 * sparsityStamp; nothing is copied or compared), else a copy of the
 * arrays, compared entry by entry. */
class SparsityRecord {
 public:
  bool matches(const SparseLcpProblem &p) const;
  void record(const SparseLcpProblem &p);
  void clear() { recorded_ = false; }
  bool empty() const { return !recorded_; }

 private:
  bool recorded_ = false;
  std::uint64_t stamp_ = 0;
  std::vector<int> rowStart_, col_; /* only for a problem without a stamp */
};

/* What a workspace's problems have taken, as running means: the cost
 * model's expectations (SparseBackend keeps them). */
struct StaleRecord {
  MeReal iterations; /* conjugate-gradient iterations a stale solve (a failure: kMaxRefine) */
  MeReal failures;   /* the fraction of stale solves that failed */
  MeReal solves;     /* solves of one problem: the first and one per friction round */
};

/* Whether solving with a stale envelope factor is expected to cost less
 * than factorising afresh. In the model's units:
 *   F = sum_i (i - first_i)^2 for the factorisation (twice its Crout
 *       multiply-adds: the weight the rule has always given it), plus
 *       SparseBackend::kAssemblyPerEntry * nnz when the caller offers an
 *       operator (A's entries must then be assembled for a factorisation;
 *       a stale solve never assembles them);
 *   S = nnz + 2 * envelope: one product with A_FF and two triangular
 *       solves, a conjugate-gradient iteration's worth.
 * A stale solve costs about (passes + iterations) S: passes = 2 for its
 * first solve with the factor and the residual that accepts it, and 3
 * with an operator, whose preparation (M^-1 J^T of every row, once a
 * problem) is counted once a solve, an approximation (a solve that starts
 * from the impulses, kStartProbe, makes no first solve: for it the rule
 * errs on the side of refactorising); `iterations` counts
 * a failure as all it was allowed. A problem takes `solves` of them (each
 * friction round solves again; the two triangular solves a round costs on
 * a fresh factor are left out), and a failure, at rate `failures`, costs a
 * factorisation besides. Kept when
 *   solves (passes + iterations) S + failures F < F.
 * The weights were checked against instruction counts of the anchor
 * scenes (docs/NOTES.md, "The keep rule of a stale factor"). */
bool StaleSolveWorthIt(const EnvelopeSystem &e, std::size_t nnz, bool operatorOffered, const StaleRecord &record);

/* Whether the dense LDL^T of an n-row matrix is expected to cost less than
 * its envelope LDL^T, whose Crout multiply-adds are `crout` (sum over rows
 * of width^2, in the order the envelope would use): when
 *   n^3 <= kDenseOverCrout * crout.
 * The dense m^3 / 6 multiply-adds run in vector lanes, while each envelope
 * row is a chain of dot products waiting on the row before. Mdt's rows
 * come in an order that makes a stack or a chain a narrow band (small
 * crout, envelope); a rag doll's tree has no narrow band in any order
 * (dense). SparseBackend judges the whole matrix (n = all rows, crout of
 * its envelope) once per sparsity and applies the judgement to each free
 * block of at most kDenseRows rows. kDenseOverCrout = 32 was measured: the
 * rag doll's matrix (87 rows, Crout 21,763, n^3 / crout = 30.3) took 13 %
 * fewer instructions over 600 steps dense; stack21's free blocks of 88-96
 * rows in their natural band (m^3 / crout = 36 for the block) took 0.2 %
 * more when forced dense (docs/NOTES.md, "Dense blocks for trees"). */
inline constexpr std::size_t kDenseOverCrout = 32;
bool DenseCheaper(std::size_t n, std::size_t crout);

class SparseBackend {
 public:
  /* Free blocks up to this many rows take the envelope path whatever their
   * envelope (see docs/NOTES.md, "Kea workspace", for the measurement);
   * KeaOptions::envelopeRows overrides this rule. */
  static constexpr std::size_t kEnvelopeRows = 96;
  /* Larger blocks take it when their mean envelope row width is at most
   * this (a band: chains, stacks). */
  static constexpr std::size_t kEnvelopeWidth = 32;
  /* Free blocks up to this many rows of a matrix at least a third full
   * (DenseFits) are factorised densely (kea_dense_ldlt.h), under the
   * default rule only. */
  static constexpr std::size_t kDenseRows = DenseLdlt::kMaxRows;
  /* Breakdown of the sparse factorisation: dense least squares up to this
   * size. */
  static constexpr std::size_t kDenseFallback = 600;

  /* Conjugate-gradient iterations with a stale factor before refactorising. */
  static constexpr int kMaxRefine = 6;
  /* A stale solve takes its accepted residual from the recursion
   * (acceptRecursive) only while its acceptance is at most this many times
   * the target. */
  static constexpr MeReal kRecursiveAcceptance = 8;
  /* The conjugate-gradient iterations a stale solve is expected to take
   * before this backend has made one, and the weight of each stale solve's
   * count in the running mean that replaces it (a failed one counts
   * kMaxRefine; the failure rate and the friction rounds per problem are
   * running means of the same weight, from 0). A factor is kept for the
   * next problem when refactorising is expected to cost more than the
   * stale solves (StaleSolveWorthIt); each factor not kept moves the
   * iterations and the failure rate back toward their priors by
   * kStaleRecoveryRate, so that a workspace that learnt to refactorise
   * tries again now and then. The friction rounds are learnt from every
   * problem that is solved (not from a kept warm start, which makes no
   * linear solve) and need no recovery. */
  static constexpr MeReal kStaleIterationsPrior = 2;
  /* The multiply-adds of assembling one entry of A = J M^-1 J^T + diag
   * for a factorisation, counted in the envelope's cost model when the
   * caller offers an operator (StaleSolveWorthIt). */
  static constexpr MeReal kAssemblyPerEntry = 12;
  static constexpr MeReal kStaleLearningRate = MeReal(0.25);
  static constexpr MeReal kStaleRecoveryRate = MeReal(1) / 16;
  /* A dense factor is kept for the next problem (WhenCheaper) when the
   * caller offers an operator (offerOperator) and this workspace's stale
   * solves take at most this many iterations on average: a stale solve
   * then applies A through the operator, so it saves the assembly as well
   * as the factorisation (docs/NOTES.md, "Stale solves without A"). */
  static constexpr MeReal kDenseStaleIterations = 2;
  /* Where a stale solve's conjugate gradients start (solveStale): from the
   * stale factor's solve of the right-hand side, or from the free rows'
   * current impulses (the warm start, or the last pivot's answer) when
   * one of them is nonzero. The first suits a factor that is nearly this
   * problem's (made a step ago: its solve is accepted as it is); the
   * second impulses that are nearer the answer than the factor is to A (a
   * heap at rest on a factor made when it landed). Each start's
   * iterations are learnt as running means (kStaleLearningRate; from 0 for
   * the factor, which is tried first, and kStaleIterationsPrior for the
   * impulses), and the start whose expected cost (StaleStartCost) is lower
   * is taken; every kStartProbe-th choice takes the other one, so that
   * both means follow the scene. A probe teaches only its start's mean:
   * the keep rule's expectations (StaleSolveWorthIt, kDenseStaleIterations)
   * learn from the chosen starts alone, so that a probe of the worse start
   * never drops a factor the better one would keep. */
  static constexpr int kStartProbe = 16;
  /* A solve with a factor, in the cost of a product with A (envelope
   * solves against operator products, pile1000 under callgrind). */
  static constexpr MeReal kSolveProducts = 2;

  /* Starts a solve of `p` (which must outlive it) with eps on the diagonal;
   * forgets the previous problem's ordering and factorisation, keeps the
   * arrays. With a factor memory, a factorisation of a previous problem of the
   * same sparsity and eps is kept as a stale factor (see above), and
   * `target` is the largest residual component a solve with it may leave. */
  void reset(const SparseLcpProblem &p, MeReal eps, int envelopeRows = 0, KeaFactorMemory memory = KeaFactorMemory::Off,
             MeReal target = 0);

  /* The most rows (freed and clamped) by which a pivot's free set may
   * differ from the dense factor's for a Schur-complement update
   * (KeaOptions::factorUpdateRows; 0: always refactorise). */
  void allowUpdates(int rows) { updateRows_ = rows; }

  /* Whether the problems come with an operator (SparseLcpProblem::op),
   * whether or not this solve applies it: the dense factor's keep rule. */
  void offerOperator(bool offered) { operatorOffered_ = offered; }

  /* The backend of the array kernels from now on (default: the reference). */
  void useKernels(const platform::Kernels &kernels) { kernels_ = &kernels; }

  /* See kea_activeset_core.h. */
  MeReal residual(std::span<const MeReal> lambda, std::span<MeReal> w);
  bool refine(std::vector<MeReal> &lambda, std::span<const MeReal> w);
  void solveFree(const std::vector<unsigned char> &set, const std::vector<MeReal> &lo, const std::vector<MeReal> &hi,
                 std::vector<MeReal> &lambda);

  /* See kea_friction_coupling.h. */
  std::span<const int> factorRows() const;
  void solveWithFactor(std::span<const MeReal> rhs, std::span<MeReal> x);
  void column(int row, std::span<const int> position, std::span<MeReal> out) const;

  /* Whether p's sparsity is that of the problem the kept factor was made
   * for (only a problem that passed validation is kept). */
  bool keptStructure(const SparseLcpProblem &p) const;
  /* Whether reset() with these arguments keeps the last factor as a stale
   * one (the solve then starts from it). */
  bool startsStale(const SparseLcpProblem &p, MeReal eps, int envelopeRows, KeaFactorMemory memory) const;

  /* The friction rounds one solved problem took (KeaResult::frictionRounds,
   * a cold retry's included), which teaches the cost model how many times a
   * problem solves with its factor: on a stale factor each round is a
   * stale solve. A problem whose warm start was kept is not one. */
  void learnFrictionRounds(int rounds);

  /* Factorisations since reset(). */
  int factorizations() const { return factorizations_; }
  /* Schur-complement updates prepared since reset() (each serves a pivot
   * that would otherwise have refactorised). */
  int factorUpdates() const { return factorUpdates_; }
  /* Solves with a stale factor since reset(), and their iterations. */
  int staleSolves() const { return staleSolves_; }
  int staleIterations() const { return staleIterations_; }

 private:
  enum class Factor { None, Dense, Envelope, BandEnvelope, Sparse };

  void buildRhs(const std::vector<int> &rows, const std::vector<unsigned char> &set, const std::vector<MeReal> &lambda);
  bool sameSparsity(const SparseLcpProblem &p, MeReal eps, int envelopeRows) const;
  void keepOrderings(const SparseLcpProblem &p);
  void rememberFactor();
  void keepDenseFactor();
  const std::vector<int> &factorOrder() const;
  void multiplyFree(const std::vector<int> &rows, std::span<const MeReal> x, std::span<MeReal> y,
                    MeReal *scale = nullptr);
  MeReal productScale(const std::vector<int> &rows, std::span<const MeReal> x) const;
  bool productOf(std::span<const MeReal> lambda) const;
  std::span<const MeReal> values() const;
  enum class StaleStart { Factor, Impulses };
  /* A start, and whether it is the probe of the start expected to cost
   * more (kStartProbe). */
  struct StaleChoice {
    StaleStart start;
    bool probe;
  };
  StaleChoice chooseStaleStart(const std::vector<int> &rows, const std::vector<MeReal> &lambda);
  bool solveStale(const std::vector<int> &rows, StaleStart start, const std::vector<MeReal> &lambda, int &iterations);
  bool acceptRecursive(const std::vector<int> &rows, MeReal accept);
  bool solveStaleAndLearn(const std::vector<int> &rows, StaleChoice choice, const std::vector<MeReal> &lambda);
  void factorise(const std::vector<unsigned char> &set);
  bool updateServesFreeRows();
  void solveThroughUpdate(std::span<const MeReal> in, std::span<MeReal> out) const;
  std::size_t envelopeFirsts(const std::vector<int> &rows);
  template <class Visit>
  void forEachFreeEntry(const std::vector<int> &rows, Visit visit, std::size_t from = 0);
  void fillEnvelope(const std::vector<int> &rows, std::size_t from = 0);
  std::size_t reusableEnvelopeRows(const std::vector<int> &rows) const;
  bool factoriseDense(const std::vector<unsigned char> &set);
  void computeDegreeOrder();
  void mapDense();
  void chooseEnvelopeOrder();
  void computeBandOrder();
  void computeOrder();
  void buildOrderedUpper();
  void gatherUpper(std::size_t m, MeReal shift);
  void factoriseSparse(const std::vector<unsigned char> &set);
  bool solveSparse(std::size_t m);
  void fallback(const std::vector<unsigned char> &set, std::vector<MeReal> &lambda);

  using SpMat = Eigen::SparseMatrix<MeReal, Eigen::ColMajor, int>;
  /* The block comes already in elimination order: no reordering inside. */
  using Ldlt = Eigen::SimplicialLDLT<SpMat, Eigen::Upper, Eigen::NaturalOrdering<int>>;
  /* Ldlt::compute() runs Eigen's ordering step even for the natural order,
   * which copies the block twice (a quarter of the time of a factorisation
   * in pile1000's 12000-row partitions). The block is already ordered and
   * stored as its upper triangle with sorted columns, which is exactly what
   * the symbolic and numeric phases take, so they are called directly. */
  class PreorderedLdlt : public Ldlt {
   public:
    void computePreordered(const SpMat &a) {
      this->analyzePattern_preordered(a, true);
      this->template factorize_preordered<true>(a);
    }
  };

  const SparseLcpProblem *p_ = nullptr;
  const platform::Kernels *kernels_ = &platform::ReferenceKernels();
  MeReal eps_ = 0;
  int envelopeRows_ = 0; /* KeaOptions::envelopeRows */
  /* The free rows ascending (naturalRows_), in elimination order
   * (orderedRows_, sparse path), and the free rows of the kept factor. */
  std::vector<int> naturalRows_, orderedRows_, factoredSet_;
  /* The sparsity of the current problem, which every ordering and map
   * below was made for (keepOrderings): they are kept while problems of
   * that sparsity follow, and the kept factor is for it too. */
  SparsityRecord sparsity_;
  /* The dense path: all rows fewest nonzeros first (empty until needed),
   * the free rows in that order (the dense factor's), and where the free
   * block's upper-triangle entries go in the dense block, with the free
   * rows that map was made for (mapDense). */
  std::vector<int> degreeOrder_, denseRows_;
  std::vector<std::pair<int, int>> denseFill_;
  std::vector<DenseLdlt::RowBits> densePattern_; /* the map's entries as DenseLdlt::notePattern marks them */
  std::vector<int> denseMapRows_;
  /* The free rows of the last dense factorisation, whose pattern dense_
   * keeps (DenseLdlt::Pattern::Kept). */
  std::vector<int> densePatternRows_;
  /* The free rows of the last dense factorisation made without the map:
   * the map is made when they come back. */
  std::vector<int> denseCandidateRows_;
  /* The whole matrix's rows in reverse Cuthill-McKee order, and the free
   * rows in that order (envelope path when the natural order is wide). */
  std::vector<int> bandOrder_, bandRank_, bandRows_, queue_;
  bool orderChosen_ = false, useBandOrder_ = false;
  bool denseCheaper_ = false; /* DenseCheaper, judged with the order */
  std::vector<int> position_, order_, rank_, upStart_, upRow_;
  std::vector<std::pair<int, int>> entries_;
  std::vector<MeReal> upVal_, wScratch_, rhs_, rhsFull_, x_;
  EnvelopeSystem envelope_;
  /* The free rows, in order, of the envelope factor made last for this
   * problem, when envelopeFresh_: it holds this problem's values and did
   * not break down, so its leading rows serve the next free set that
   * starts with the same rows (reusableEnvelopeRows). */
  std::vector<int> envelopeFactorRows_;
  bool envelopeFresh_ = false;
  DenseLdlt dense_;
  SpMat block_;
  PreorderedLdlt ldlt_;
  Factor factor_ = Factor::None;
  bool ldltOk_ = false;
  int factorizations_ = 0;
  /* The Schur-complement update of the dense factor (kea_schur_update.h):
   * whether it serves the current free rows, which free rows it was
   * prepared for, the limit and the count since reset(). */
  SchurUpdate update_;
  bool updated_ = false, updateToCheck_ = false;
  int refinements_ = 0; /* refine() steps left for the last update's answer */
  std::vector<int> updatedSet_;
  int updateRows_ = SchurUpdate::kMaxRows;
  int factorUpdates_ = 0;
  /* Factor memory: whether a factor worth keeping was made for
   * sparsity_, whether it is stale (made for an earlier problem), whether
   * upVal_ holds this problem's values, the target residual, the CG
   * vectors and counts. */
  bool factorKept_ = false;
  bool stale_ = false, upperFresh_ = false;
  /* Whether the kept factor is worth keeping (StaleSolveWorthIt). */
  bool staleWorthIt_ = false;
  KeaFactorMemory memory_ = KeaFactorMemory::Off; /* reset's */
  MeReal target_ = 0;
  bool operatorOffered_ = false;
  std::vector<MeReal> cgR_, cgZ_, cgD_, cgQ_, cgFull_;
  /* (A x)_i for every row i, x = cgFull_, before eps is added, when
   * productValid_: multiplyFree's last product when it covered every row,
   * or a stale solve's accepted recursion (acceptRecursive). */
  std::vector<MeReal> productFull_;
  bool productValid_ = false;
  int staleSolves_ = 0, staleIterations_ = 0;
  MeReal staleIterationsExpected_ = kStaleIterationsPrior; /* running mean, kept across problems */
  MeReal staleFailureRate_ = 0;                            /* running mean of failures (1) and successes (0) */
  MeReal frictionRoundsExpected_ = 0;                      /* running mean per problem (learnFrictionRounds) */
  /* kStartProbe: each start's running mean of iterations, and the choices
   * made, kept across problems. */
  MeReal iterationsFromFactor_ = 0, iterationsFromImpulses_ = kStaleIterationsPrior;
  unsigned startChoices_ = 0;
};

}  // namespace karma::kea::detail

#endif
