/* kea_sparse_backend.cpp: the sparse matrix operations of the active-set
 * core (see kea_sparse_backend.h). */
#include "kea_sparse_backend.h"

#include "kea_activeset_core.h"

#include <Eigen/OrderingMethods>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace karma::kea::detail {
namespace {

using Vec = Eigen::Matrix<MeReal, Eigen::Dynamic, 1>;

std::size_t U(int i) { return static_cast<std::size_t>(i); }

/* max_a |x_a| (0 for none; a NaN is passed over, as std::max passes it). */
MeReal LargestMagnitude(std::span<const MeReal> x) {
  MeReal largest = 0;
  for (MeReal e : x) largest = std::max(largest, std::fabs(e));
  return largest;
}

/* y[a] = (A x)_i for i = rows[a] (i = a when rows is null), a < count:
 * through the problem's operator when it has one, else the stored entries
 * of CSR row i. */
void RowsTimes(const platform::Kernels &kernels, const SparseLcpProblem &p, const int *rows, std::size_t count,
               const MeReal *x, MeReal *y) {
  if (p.op) {
    p.op->times(rows, count, x, y);
    return;
  }
  kernels.sparseRowsTimes(p.rowStart.data(), p.col.data(), p.val.data(), rows, static_cast<int>(count), x, y);
}

}  // namespace

MeReal SparseMultiplyResidual(const platform::Kernels &kernels, const SparseLcpProblem &p, MeReal eps,
                              std::span<const MeReal> lambda, std::span<MeReal> w) {
  const auto n = static_cast<std::size_t>(p.n);
  RowsTimes(kernels, p, nullptr, n, lambda.data(), w.data());
  for (std::size_t i = 0; i < n; ++i) w[i] = (-p.b[i] + eps * lambda[i]) + w[i];
  return ComplementarityResidual(Rows(p), lambda, w);
}

namespace {

/* Whether the free block (m rows) of an n x n matrix with nnz stored
 * entries is taken by the dense LDL^T: m at most kDenseRows and the matrix
 * at least a third full. Such a block costs the envelope's Crout order
 * about as many multiply-adds as the dense factorisation, but there each
 * one ends a dot product waiting on the entry before, while the dense
 * updates run in vector lanes and skip the pairs of rows that do not meet
 * (docs/NOTES.md, "Dense small blocks"). Decided from the whole matrix's
 * counts, without looking at the free block's entries. */
bool DenseFits(std::size_t m, std::size_t n, std::size_t nnz) {
  return m <= SparseBackend::kDenseRows && 3 * nnz >= n * n;
}

/* Moves a learnt expectation a step of kStaleRecoveryRate toward its
 * prior, and onto the prior once rounding stops the step: approached from
 * above, value + rate (prior - value) rounds back to value a few ulps (up
 * to 1 / (2 rate)) above the prior, and a rule that asks for
 * value <= prior would never be met again. */
void RecoverTowardPrior(MeReal &value, MeReal prior) {
  const MeReal next = value + SparseBackend::kStaleRecoveryRate * (prior - value);
  value = next == value ? prior : next;
}

}  // namespace

/* See kea_sparse_backend.h. */
bool DenseCheaper(std::size_t n, std::size_t crout) { return n * n * n <= kDenseOverCrout * crout; }

/* See kea_sparse_backend.h. */
bool StaleSolveWorthIt(const EnvelopeSystem &e, std::size_t nnz, bool operatorOffered, const StaleRecord &record) {
  std::size_t crout = 0;
  for (int i = 0; i < e.m; ++i) {
    const auto width = static_cast<std::size_t>(i - e.first[U(i)]);
    crout += width * width;
  }
  const MeReal assembly = operatorOffered ? SparseBackend::kAssemblyPerEntry : MeReal(0);
  const MeReal passes = operatorOffered ? 3 : 2;
  const MeReal factorCost = static_cast<MeReal>(crout) + assembly * static_cast<MeReal>(nnz);
  const MeReal staleCost = record.solves * (passes + record.iterations) * static_cast<MeReal>(nnz + 2 * e.size());
  return staleCost + record.failures * factorCost < factorCost;
}

/* Whether `p` has the sparsity and eps of the problem the kept factor was
 * made for. */
bool SparseBackend::sameSparsity(const SparseLcpProblem &p, MeReal eps, int envelopeRows) const {
  return eps == eps_ && envelopeRows == envelopeRows_ && keptStructure(p);
}

bool SparseBackend::keptStructure(const SparseLcpProblem &p) const { return factorKept_ && sparsity_.matches(p); }

bool SparseBackend::startsStale(const SparseLcpProblem &p, MeReal eps, int envelopeRows, KeaFactorMemory memory) const {
  const bool usable = factor_ != Factor::None && (factor_ != Factor::Sparse || ldltOk_) && staleWorthIt_;
  return memory != KeaFactorMemory::Off && usable && sameSparsity(p, eps, envelopeRows);
}

bool SparsityRecord::matches(const SparseLcpProblem &p) const {
  if (!recorded_) return false;
  if (stamp_ != 0) return p.sparsityStamp == stamp_;
  const auto n = static_cast<std::size_t>(std::max(p.n, 0));
  return rowStart_.size() == n + 1 && p.rowStart.size() == n + 1 &&
         std::equal(rowStart_.begin(), rowStart_.end(), p.rowStart.begin()) && col_.size() == p.col.size() &&
         p.val.size() == p.col.size() && std::equal(col_.begin(), col_.end(), p.col.begin());
}

/* `p` must be valid (rowStart[n] entries in col). */
void SparsityRecord::record(const SparseLcpProblem &p) {
  recorded_ = true;
  stamp_ = p.sparsityStamp;
  if (stamp_ != 0) return;
  const auto n = static_cast<std::size_t>(p.n);
  rowStart_.assign(p.rowStart.begin(), p.rowStart.begin() + static_cast<std::ptrdiff_t>(n + 1));
  col_.assign(p.col.begin(), p.col.begin() + p.rowStart[n]);
}

/* The orderings of the previous problem (and the dense path's map) stay
 * when `p` has its sparsity (they depend on nothing else); otherwise they
 * are made again when first needed, and sparsity_ becomes p's. */
void SparseBackend::keepOrderings(const SparseLcpProblem &p) {
  upperFresh_ = false; /* upVal_ holds the previous problem's values */
  if (sparsity_.matches(p)) return;
  sparsity_.record(p);
  order_.clear();
  bandOrder_.clear();
  orderChosen_ = useBandOrder_ = denseCheaper_ = false;
  degreeOrder_.clear();
  denseMapRows_.clear();
  densePatternRows_.clear();
  denseCandidateRows_.clear();
}

void SparseBackend::reset(const SparseLcpProblem &p, MeReal eps, int envelopeRows, KeaFactorMemory memory,
                          MeReal target) {
  factorizations_ = staleSolves_ = staleIterations_ = factorUpdates_ = 0;
  updated_ = false;
  envelopeFresh_ = false;
  productValid_ = false; /* made for the previous problem */
  target_ = target;
  if (startsStale(p, eps, envelopeRows, memory)) {
    /* The orderings depend on the sparsity only: they stay too. */
    p_ = &p;
    stale_ = true;
    upperFresh_ = false;
    return;
  }
  stale_ = false;
  memory_ = memory;
  factorKept_ = false; /* set when a factor worth keeping is made */
  p_ = &p;
  eps_ = eps;
  const auto n = static_cast<std::size_t>(p.n);
  /* Room for Room(n) rows (kea_internal.h), so that a problem a few rows
   * larger than the last one reallocates nothing. The per-row arrays take it
   * only when they have less than n (ReserveRoom); the factors' arrays
   * (envelope_, dense_, update_, denseFill_) are sized from it outright:
   * nothing swaps them, so they too grow once per power of two. */
  const std::size_t room = Room(n);
  ReserveRoom(position_, n);
  position_.assign(n, -1);
  ReserveRoom(naturalRows_, n);
  ReserveRoom(denseRows_, n);
  ReserveRoom(degreeOrder_, n);
  ReserveRoom(denseMapRows_, n);
  ReserveRoom(densePatternRows_, n);
  ReserveRoom(denseCandidateRows_, n);
  /* Reverse Cuthill-McKee scratch (computeBandOrder). */
  ReserveRoom(bandRank_, n);
  ReserveRoom(queue_, n);
  ReserveRoom(factoredSet_, n);
  ReserveRoom(envelopeFactorRows_, n);
  ReserveRoom(rhs_, n);
  ReserveRoom(rhsFull_, n);
  ReserveRoom(x_, n);
  ReserveRoom(wScratch_, n);
  /* Room for the largest envelope the rule below accepts, so that no free
   * set of this problem makes the envelope grow. */
  std::size_t accepted = std::max(kEnvelopeRows * (kEnvelopeRows + 1) / 2, kEnvelopeWidth * room);
  if (envelopeRows > 0)
    accepted = static_cast<std::size_t>(envelopeRows) * (static_cast<std::size_t>(envelopeRows) + 1) / 2;
  if (envelopeRows < 0) accepted = 0;
  envelope_.reserve(room, std::min(accepted, room * (room + 1) / 2));
  dense_.reserve(std::min(room, kDenseRows));
  update_.reserve(room, std::min(room, kDenseRows));
  ReserveRoom(updatedSet_, n);
  /* refine()'s vectors (the stale solves' too). */
  ReserveRoom(cgR_, n);
  ReserveRoom(cgZ_, n);
  ReserveRoom(cgFull_, n);
  /* The dense map's entries: the free block's upper triangle (made only
   * once a free set comes back, so reserved here). */
  const std::size_t denseRowsMax = std::min(room, kDenseRows);
  denseFill_.reserve(std::min(Room(U(p.rowStart[n])), denseRowsMax * (denseRowsMax + 1) / 2));
  ReserveRoom(densePattern_, denseRowsMax);
  envelopeRows_ = envelopeRows;
  keepOrderings(p);
  ReserveRoom(bandRows_, n);
  ReserveRoom(bandOrder_, n);
  factor_ = Factor::None;
  ldltOk_ = false;
}

MeReal SparseBackend::residual(std::span<const MeReal> lambda, std::span<MeReal> w) {
  std::span<MeReal> out = w;
  if (w.size() != lambda.size()) {
    wScratch_.resize(lambda.size());
    out = wScratch_;
  }
  if (!productOf(lambda)) return SparseMultiplyResidual(*kernels_, *p_, eps_, lambda, out);
  const SparseLcpProblem &p = *p_;
  for (std::size_t i = 0; i < lambda.size(); ++i) out[i] = (-p.b[i] + eps_ * lambda[i]) + productFull_[i];
  return ComplementarityResidual(Rows(p), lambda, out);
}

/* Whether productFull_ holds A lambda for lambda = cgFull_, bit for bit:
 * the last multiplyFree covered every row of this problem through its
 * operator (the operator's product of a row is a function of the whole
 * vector only, the bodies' sums, so it is the one SparseMultiplyResidual
 * would compute), or a stale solve took it from its accepted recursion
 * (acceptRecursive: within rounding of that product). */
bool SparseBackend::productOf(std::span<const MeReal> lambda) const {
  return productValid_ && lambda.size() == cgFull_.size() &&
         std::memcmp(lambda.data(), cgFull_.data(), lambda.size() * sizeof(MeReal)) == 0;
}

void SparseBackend::solveFree(const std::vector<unsigned char> &set, const std::vector<MeReal> &lo,
                              const std::vector<MeReal> &hi, std::vector<MeReal> &lambda) {
  const SparseLcpProblem &p = *p_;
  const auto n = static_cast<std::size_t>(p.n);
  naturalRows_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (set[i] == AtLo)
      lambda[i] = lo[i];
    else if (set[i] == AtHi)
      lambda[i] = hi[i];
    else
      naturalRows_.push_back(static_cast<int>(i));
  }
  const std::size_t m = naturalRows_.size();
  updateToCheck_ = false;
  if (m == 0) return;

  if (factor_ == Factor::None || naturalRows_ != factoredSet_) {
    if (!updateServesFreeRows()) {
      factorise(set);
      factoredSet_ = naturalRows_;
      ++factorizations_;
      stale_ = false;
    }
  } else {
    updated_ = false;
  }

  buildRhs(factorOrder(), set, lambda);
  x_.resize(m);
  if (stale_) {
    const std::vector<int> &rows = factorOrder();
    if (solveStaleAndLearn(rows, chooseStaleStart(rows, lambda), lambda)) {
      for (std::size_t a = 0; a < m; ++a) lambda[U(rows[a])] = x_[a];
      return;
    }
    /* Same free set, so the same order: only the values are new. */
    factorise(set);
    ++factorizations_;
    stale_ = false;
  }
  const std::vector<int> &rows = factorOrder();
  if (updated_) {
    /* Checked by refine() against the residual the caller computes next. */
    solveThroughUpdate(rhs_, x_);
    updateToCheck_ = true;
    refinements_ = kMaxRefine;
  } else if (factor_ == Factor::Dense) {
    dense_.solve(rhs_, x_);
  } else if (factor_ != Factor::Sparse) {
    envelope_.solve(rhs_, x_);
  } else if (!solveSparse(m)) {
    fallback(set, lambda);
    return;
  }
  for (std::size_t a = 0; a < m; ++a) lambda[U(rows[a])] = x_[a];
}

/* Whether the free rows (naturalRows_, not the factor's) are served by a
 * Schur-complement update of the dense factor made for this problem: the
 * update already prepared for them, or a new one from the factor's rows.
 * Not on a stale factor (its values are an earlier problem's). */
bool SparseBackend::updateServesFreeRows() {
  if (stale_ || factor_ != Factor::Dense || updateRows_ <= 0) {
    updated_ = false;
    return false;
  }
  if (updated_ && naturalRows_ == updatedSet_) return true;
  updated_ = update_.prepare(
      denseRows_, naturalRows_, U(p_->n), eps_, updateRows_,
      [this](int row, std::span<const int> position, std::span<MeReal> out) { column(row, position, out); },
      [this](std::span<const MeReal> in, std::span<MeReal> out) { dense_.solve(in, out); });
  if (updated_) {
    updatedSet_ = naturalRows_;
    ++factorUpdates_;
  }
  return updated_;
}

/* out = the updated block's inverse times in (update_.order()), through
 * the dense base factor. */
void SparseBackend::solveThroughUpdate(std::span<const MeReal> in, std::span<MeReal> out) const {
  update_.solve(in, out, [this](std::span<const MeReal> b, std::span<MeReal> x) { dense_.solve(b, x); });
}

/* After a solve through the update: its free rows' residual is -w_F (w =
 * (A + eps I) lambda - b, as the caller computed it). While that is above
 * target_ and above the rounding of its own computation (the stale
 * solves' acceptance, solveStale), a step of iterative refinement
 * (Higham, "Accuracy and Stability of Numerical Algorithms", ch. 12):
 * lambda_F += update^-1 (-w_F), at most kMaxRefine of them; the caller
 * computes the residual again after each. An ill-conditioned base makes
 * the update's correction W z cancel digits (docs/NOTES.md, "Pivots
 * without refactorising"). */
bool SparseBackend::refine(std::vector<MeReal> &lambda, std::span<const MeReal> w) {
  if (!updateToCheck_) return false;
  const std::vector<int> &rows = update_.order();
  const std::size_t m = rows.size();
  cgR_.resize(m);
  for (std::size_t a = 0; a < m; ++a) cgR_[a] = -w[U(rows[a])];
  const MeReal residual = LargestOrInfinite(cgR_);
  updateToCheck_ = residual > target_ && refinements_ > 0;
  if (!updateToCheck_) return false;
  /* productScale reads x scattered to all rows (as multiplyFree leaves
   * it); the product kept for residual() is then no longer x's. */
  cgFull_.assign(U(p_->n), MeReal(0));
  for (std::size_t a = 0; a < m; ++a) cgFull_[U(rows[a])] = x_[a] = lambda[U(rows[a])];
  productValid_ = false;
  const MeReal rounding = 4 * ME_REAL_EPSILON * (productScale(rows, x_) + LargestOrInfinite(rhs_));
  updateToCheck_ = residual > rounding;
  if (!updateToCheck_) return false;
  --refinements_;
  cgZ_.resize(m);
  solveThroughUpdate(cgR_, cgZ_);
  for (std::size_t a = 0; a < m; ++a) lambda[U(rows[a])] += cgZ_[a];
  return true;
}

/* A's entries, assembled first when the problem has an operator. */
std::span<const MeReal> SparseBackend::values() const {
  if (p_->op) p_->op->assemble();
  return p_->val;
}

/* The free rows in the kept factor's order. */
const std::vector<int> &SparseBackend::factorOrder() const {
  if (updated_) return update_.order();
  if (factor_ == Factor::Dense) return denseRows_;
  return factor_ == Factor::Envelope ? naturalRows_ : factor_ == Factor::BandEnvelope ? bandRows_ : orderedRows_;
}

/* y = (A + eps I)_FF x, the free rows in the order `rows`; with `scale`,
 * also *scale = productScale(rows, x), in the same pass as the product
 * when an operator can (SparseLcpOperator::timesAndAbsTimesMax). Leaves x
 * scattered in cgFull_ (for productScale). */
void SparseBackend::multiplyFree(const std::vector<int> &rows, std::span<const MeReal> x, std::span<MeReal> y,
                                 MeReal *scale) {
  /* y = (A + eps I)_FF x (y must not overlap x). x scattered to all n rows
   * (zero on the clamped ones): then every stored entry multiplies without
   * a test. */
  const SparseLcpProblem &p = *p_;
  const std::size_t m = rows.size();
  cgFull_.assign(static_cast<std::size_t>(p.n), MeReal(0));
  for (std::size_t a = 0; a < m; ++a) cgFull_[U(rows[a])] = x[a];
  if (scale && p.op) {
    const MeReal bound = p.op->timesAndAbsTimesMax(rows.data(), m, cgFull_.data(), y.data());
    *scale = bound + std::fabs(eps_) * LargestMagnitude(x);
  } else {
    RowsTimes(*kernels_, p, rows.data(), m, cgFull_.data(), y.data());
    if (scale) *scale = productScale(rows, x);
  }
  /* Every row free: the product is A times the whole vector, which the
   * residual of the same lambda reuses (productOf). */
  productValid_ = p.op && m == U(p.n);
  if (productValid_) {
    productFull_.resize(m);
    for (std::size_t a = 0; a < m; ++a) productFull_[U(rows[a])] = y[a];
  }
  for (std::size_t a = 0; a < m; ++a) y[a] = eps_ * x[a] + y[a];
}

/* The largest component of (|A + eps I|)_FF |x|, or with an operator an
 * upper bound of it (absTimesMax, plus |eps| max|x|): the scale of the
 * rounding of multiplyFree's y. Right after multiplyFree(rows, x, ...),
 * which scattered x into cgFull_. */
MeReal SparseBackend::productScale(const std::vector<int> &rows, std::span<const MeReal> x) const {
  const SparseLcpProblem &p = *p_;
  if (p.op) return p.op->absTimesMax(rows.data(), rows.size(), cgFull_.data()) + std::fabs(eps_) * LargestMagnitude(x);
  MeReal scale = 0;
  for (std::size_t a = 0; a < rows.size(); ++a) {
    const auto i = U(rows[a]);
    /* Four partial sums (term k in sum k mod 4): a bound needs no order,
     * and one running sum would be a chain of additions. */
    auto term = [&](int k) { return std::fabs(p.val[U(k)] * cgFull_[U(p.col[U(k)])]); };
    MeReal s[4] = {std::fabs(eps_ * x[a]), 0, 0, 0};
    const int end = p.rowStart[i + 1];
    int k = p.rowStart[i];
    for (; k + 4 <= end; k += 4)
      for (int l = 0; l < 4; ++l) s[l] += term(k + l);
    for (; k < end; ++k) s[0] += term(k);
    scale = std::max(scale, (s[0] + s[1]) + (s[2] + s[3]));
  }
  return scale;
}

namespace {

/* The expected cost of a stale solve, in products with A
 * (kSolveProducts): the factor's start costs a solve, the impulses' none;
 * the first residual a product; each iteration a solve and a product; and
 * a solve that iterates two products more (the rounding scale, and the
 * true residual that accepts it). The scale of a start from the impulses
 * is taken with its first product, for less than a product, and when every
 * row is free the accepting residual comes from the recursion
 * (acceptRecursive); the model still counts both as whole products
 * (counting one less changed neither pile1000 nor stack21 by more than
 * 0.1 %). */
MeReal StaleStartCost(bool fromFactor, MeReal iterations) {
  constexpr MeReal kSolve = SparseBackend::kSolveProducts;
  return (fromFactor ? kSolve : 0) + 1 + iterations * (kSolve + 1) + 2 * std::min(iterations, MeReal(1));
}

}  // namespace

/* The start of a stale solve (kStartProbe): the factor's when no free
 * row has an impulse. */
SparseBackend::StaleChoice SparseBackend::chooseStaleStart(const std::vector<int> &rows,
                                                           const std::vector<MeReal> &lambda) {
  const bool anyImpulse = std::any_of(rows.begin(), rows.end(), [&](int r) { return lambda[U(r)] != 0; });
  if (!anyImpulse) return {StaleStart::Factor, false};
  const bool impulsesCheaper =
      StaleStartCost(false, iterationsFromImpulses_) < StaleStartCost(true, iterationsFromFactor_);
  const bool probe = ++startChoices_ % kStartProbe == 0;
  return {impulsesCheaper != probe ? StaleStart::Impulses : StaleStart::Factor, probe};
}

/* x_ solving (A + eps I)_FF x = rhs_ with the stale factor as the
 * preconditioner of conjugate gradients (Saad, "Iterative Methods for
 * Sparse Linear Systems", alg. 9.1), restarted from the true residual
 * whenever the recursive one says it is done, except when every row is
 * free and A comes through an operator (acceptRecursive). Accepted when
 * every component of the residual rhs - A_FF x is within target_, or
 * within the rounding of its own computation (4 eps (|A_FF||x| + |rhs|),
 * what a direct solve leaves too). False after kMaxRefine iterations
 * without that: the caller refactorises. It starts from the factor's
 * solve of rhs_, or from the free rows' impulses in `lambda`
 * (kStartProbe); `iterations` counts the iterations taken. */
bool SparseBackend::solveStale(const std::vector<int> &rows, StaleStart start, const std::vector<MeReal> &lambda,
                               int &iterations) {
  const std::size_t m = rows.size();
  cgR_.resize(m);
  cgZ_.resize(m);
  cgD_.resize(m);
  cgQ_.resize(m);
  auto largest = [](const std::vector<MeReal> &v) { return LargestOrInfinite(v); };
  auto dot = [this, m](const std::vector<MeReal> &a, const std::vector<MeReal> &b) {
    return platform::Dot(*kernels_, a.data(), b.data(), static_cast<int>(m));
  };
  const MeReal rhsSize = largest(rhs_);
  MeReal accept = target_;
  bool scaled = false;
  /* The true residual into cgR_; whether it is accepted. The rounding
   * scale is only needed when the residual is above the target, and is
   * taken once, at the first such iterate: the later ones differ from it
   * by a correction far below its size. A start from the impulses is
   * almost never within the target, so through an operator its scale is
   * taken with its product, in one pass (timesAndAbsTimesMax); any other
   * start's only when needed. */
  auto converged = [&]() {
    /* !scaled: the first call (a later one follows a first that failed). */
    MeReal scale = 0;
    const bool scaleNow = !scaled && start == StaleStart::Impulses && p_->op;
    multiplyFree(rows, x_, cgQ_, scaleNow ? &scale : nullptr);
    for (std::size_t a = 0; a < m; ++a) cgR_[a] = rhs_[a] - cgQ_[a];
    const MeReal residual = largest(cgR_);
    if (!(residual > target_)) return true;
    if (!scaled) {
      const MeReal productSize = scaleNow ? scale : productScale(rows, x_);
      accept = std::max(target_, 4 * ME_REAL_EPSILON * (productSize + rhsSize));
    }
    scaled = true;
    return !(residual > accept);
  };
  if (start == StaleStart::Factor)
    solveWithFactor(rhs_, x_);
  else
    for (std::size_t a = 0; a < m; ++a) x_[a] = lambda[U(rows[a])];
  int budget = kMaxRefine;
  while (!converged()) {
    if (budget == 0 || !std::isfinite(largest(x_))) return false;
    solveWithFactor(cgR_, cgZ_);
    cgD_ = cgZ_;
    MeReal rz = dot(cgR_, cgZ_);
    while (budget > 0) {
      --budget;
      ++iterations;
      multiplyFree(rows, cgD_, cgQ_);
      const MeReal dq = dot(cgD_, cgQ_);
      if (!(dq > 0) || !(rz > 0)) return false;
      const MeReal alpha = rz / dq;
      for (std::size_t a = 0; a < m; ++a) {
        x_[a] += alpha * cgD_[a];
        cgR_[a] -= alpha * cgQ_[a];
      }
      if (!(largest(cgR_) > accept)) {
        if (acceptRecursive(rows, accept)) return true;
        break;
      }
      solveWithFactor(cgR_, cgZ_);
      const MeReal rzNext = dot(cgR_, cgZ_);
      const MeReal beta = rzNext / rz;
      rz = rzNext;
      for (std::size_t a = 0; a < m; ++a) cgD_[a] = cgZ_[a] + beta * cgD_[a];
    }
  }
  return true;
}

/* A conjugate-gradient iterate whose recursive residual r (cgR_) is within
 * `accept`, when every row is free, A comes through an operator and accept
 * is at most kRecursiveAcceptance times the target: the residual the
 * caller computes next (residual(), a product with A over every row) is
 * taken from the recursion instead, A x = rhs - r - eps x, and not checked
 * by a product of its own. The recursion's r drifts from
 * rhs - (A + eps I) x by the rounding of each iteration's update and
 * product, about eps (|A||x| + |A||d|): a quarter of the rounding allowance
 * (4 eps (|A||x| + |rhs|)) an iteration, so after the kMaxRefine
 * iterations allowed the true residual is within 2.5 accept <= 2.5 * 8 /
 * kStaleTargetDivisor of the solved threshold (a third of it). In the pile's
 * settled steps nearly every stale solve that iterates has every row free
 * (docs/NOTES.md, "A stale solve's last product"). Otherwise false: the
 * caller multiplies. */
bool SparseBackend::acceptRecursive(const std::vector<int> &rows, MeReal accept) {
  const SparseLcpProblem &p = *p_;
  const std::size_t m = rows.size();
  if (!p.op || m != U(p.n) || !(accept <= kRecursiveAcceptance * target_)) return false;
  if (!std::isfinite(LargestOrInfinite(x_))) return false;
  cgFull_.resize(m);
  productFull_.resize(m);
  for (std::size_t a = 0; a < m; ++a) {
    const auto i = U(rows[a]);
    cgFull_[i] = x_[a];
    productFull_[i] = (rhs_[a] - cgR_[a]) - eps_ * x_[a];
  }
  productValid_ = true;
  return true;
}

void SparseBackend::learnFrictionRounds(int rounds) {
  frictionRoundsExpected_ += kStaleLearningRate * (static_cast<MeReal>(rounds) - frictionRoundsExpected_);
}

/* A stale solve, and what it took teaches its start's mean and, unless
 * it was a probe, the keep rule's iteration count and failure rate (a
 * failure counts as every iteration allowed). */
bool SparseBackend::solveStaleAndLearn(const std::vector<int> &rows, StaleChoice choice,
                                       const std::vector<MeReal> &lambda) {
  ++staleSolves_;
  int iterations = 0;
  const bool solved = solveStale(rows, choice.start, lambda, iterations);
  staleIterations_ += iterations;
  const MeReal taken = static_cast<MeReal>(solved ? iterations : kMaxRefine);
  MeReal &startMean = choice.start == StaleStart::Factor ? iterationsFromFactor_ : iterationsFromImpulses_;
  startMean += kStaleLearningRate * (taken - startMean);
  if (choice.probe) return solved;
  staleIterationsExpected_ += kStaleLearningRate * (taken - staleIterationsExpected_);
  staleFailureRate_ += kStaleLearningRate * ((solved ? MeReal(0) : MeReal(1)) - staleFailureRate_);
  return solved;
}

std::span<const int> SparseBackend::factorRows() const {
  if (stale_) return {};                /* its solves are not exact: no coupled friction step on it */
  if (updated_) return update_.order(); /* its solves are refined after the step (refine) */
  switch (factor_) {
    case Factor::Dense:
      return denseRows_;
    case Factor::Envelope:
      return naturalRows_;
    case Factor::BandEnvelope:
      return bandRows_;
    case Factor::Sparse:
      return ldltOk_ ? std::span<const int>(orderedRows_) : std::span<const int>();
    default:
      return {};
  }
}

void SparseBackend::solveWithFactor(std::span<const MeReal> rhs, std::span<MeReal> x) {
  if (updated_) {
    solveThroughUpdate(rhs, x);
    updateToCheck_ = true; /* the coupled step's answer is refined like a solve's */
    refinements_ = kMaxRefine;
    return;
  }
  if (factor_ == Factor::Dense) {
    dense_.solve(rhs, x);
    return;
  }
  if (factor_ != Factor::Sparse) {
    envelope_.solve(rhs, x);
    return;
  }
  const Vec sol = ldlt_.solve(Eigen::Map<const Vec>(rhs.data(), static_cast<Eigen::Index>(rhs.size())));
  std::copy(sol.data(), sol.data() + sol.size(), x.begin());
}

void SparseBackend::column(int row, std::span<const int> position, std::span<MeReal> out) const {
  /* A is symmetric: column `row` is row `row`. */
  const SparseLcpProblem &p = *p_;
  const std::span<const MeReal> val = values();
  for (int k = p.rowStart[U(row)]; k < p.rowStart[U(row) + 1]; ++k) {
    const int c = position[U(p.col[U(k)])];
    if (c >= 0) out[U(c)] = val[U(k)];
  }
}

/* rhs = b_F - A_FC lambda_C. Through the problem's operator, one product
 * with lambda_C (zero on the free rows), made only when some clamped
 * lambda is not zero. Otherwise by the clamped rows: A is symmetric, so
 * column j of A_FC is row j's CSR entries, and each clamped row j, in
 * ascending order, subtracts its terms from every row it meets. Each free
 * row thus loses its clamped columns' terms in ascending column order, as
 * a row-by-row sum would, at the cost of the clamped rows' entries only. */
void SparseBackend::buildRhs(const std::vector<int> &rows, const std::vector<unsigned char> &set,
                             const std::vector<MeReal> &lambda) {
  const SparseLcpProblem &p = *p_;
  const auto n = static_cast<std::size_t>(p.n);
  rhs_.resize(rows.size());
  if (p.op) {
    rhsFull_.assign(n, MeReal(0)); /* lambda_C, zero on the free rows */
    bool any = false;
    for (std::size_t j = 0; j < n; ++j)
      if (set[j] != Free && lambda[j] != 0) {
        rhsFull_[j] = lambda[j];
        any = true;
      }
    if (!any) {
      for (std::size_t a = 0; a < rows.size(); ++a) rhs_[a] = p.b[U(rows[a])];
      return;
    }
    p.op->times(rows.data(), rows.size(), rhsFull_.data(), rhs_.data());
    for (std::size_t a = 0; a < rows.size(); ++a) rhs_[a] = p.b[U(rows[a])] - rhs_[a];
    return;
  }
  rhsFull_.assign(p.b.begin(), p.b.begin() + static_cast<std::ptrdiff_t>(n));
  for (std::size_t j = 0; j < n; ++j) {
    if (set[j] == Free || lambda[j] == 0) continue; /* a zero lambda subtracts nothing */
    const MeReal lj = lambda[j];
    for (int k = p.rowStart[j]; k < p.rowStart[j + 1]; ++k) {
      const auto i = U(p.col[U(k)]);
      rhsFull_[i] -= p.val[U(k)] * lj;
    }
  }
  for (std::size_t a = 0; a < rows.size(); ++a) rhs_[a] = rhsFull_[U(rows[a])];
}

/* The choice of factorisation for the free block (see
 * kea_sparse_backend.h): under the default rule, the dense LDL^T when the
 * block is small and the matrix full enough (DenseFits), or when the block
 * is small and the whole matrix's envelope in the order chosen below would
 * cost more than its dense factorisation (DenseCheaper, judged once per
 * sparsity), and it does not break down; else the envelope in the
 * rows' own order when it is a band;
 * else, under the default rule, the envelope in reverse Cuthill-McKee
 * order when the block is small or that order makes it a band; else the
 * sparse LDL^T. */
void SparseBackend::factorise(const std::vector<unsigned char> &set) {
  const std::size_t m = naturalRows_.size();
  const bool envelopeWasFresh = envelopeFresh_;
  envelopeFresh_ = false;
  const bool denseFits = envelopeRows_ == 0 && DenseFits(m, U(p_->n), U(p_->rowStart[U(p_->n)]));
  if (denseFits && factoriseDense(set)) {
    keepDenseFactor();
    return;
  }
  if (envelopeRows_ >= 0) {
    if (!orderChosen_) chooseEnvelopeOrder();
    /* A dense factorisation that broke down above is not tried again. */
    if (envelopeRows_ == 0 && !denseFits && m <= kDenseRows && denseCheaper_ && factoriseDense(set)) {
      keepDenseFactor();
      return;
    }
    if (useBandOrder_) {
      bandRows_.clear();
      for (int i : bandOrder_)
        if (set[U(i)] == Free) bandRows_.push_back(i);
    }
    const std::vector<int> &rows = useBandOrder_ ? bandRows_ : naturalRows_;
    const std::size_t entries = envelopeFirsts(rows);
    const bool accept = envelopeRows_ > 0 ? m <= static_cast<std::size_t>(envelopeRows_)
                                          : m <= kEnvelopeRows || entries <= kEnvelopeWidth * m;
    if (accept) {
      const std::size_t kept = envelopeWasFresh ? reusableEnvelopeRows(rows) : 0;
      fillEnvelope(rows, kept);
      envelope_.factor(static_cast<int>(kept));
      factor_ = useBandOrder_ ? Factor::BandEnvelope : Factor::Envelope;
      envelopeFactorRows_ = rows;
      envelopeFresh_ = !envelope_.broken;
      staleWorthIt_ = memory_ == KeaFactorMemory::Always ||
                      StaleSolveWorthIt(envelope_, U(p_->rowStart[U(p_->n)]), operatorOffered_,
                                        {staleIterationsExpected_, staleFailureRate_, 1 + frictionRoundsExpected_});
      /* A factor not kept teaches nothing: the expectations drift back to
       * the priors so that the factor is tried again. */
      if (!staleWorthIt_) {
        RecoverTowardPrior(staleIterationsExpected_, kStaleIterationsPrior);
        RecoverTowardPrior(staleFailureRate_, 0);
      }
      rememberFactor();
      return;
    }
  }
  factoriseSparse(set);
  staleWorthIt_ = true;
  rememberFactor();
}

/* Whether the dense factor just made is worth keeping (see
 * kDenseStaleIterations), and keeps it if so. */
void SparseBackend::keepDenseFactor() {
  staleWorthIt_ =
      memory_ == KeaFactorMemory::Always || (operatorOffered_ && staleIterationsExpected_ <= kDenseStaleIterations);
  if (!staleWorthIt_)
    RecoverTowardPrior(staleIterationsExpected_, kStaleIterationsPrior);
  rememberFactor();
}

/* Marks the factor as kept for this problem's sparsity when it is worth
 * keeping. */
void SparseBackend::rememberFactor() {
  if (memory_ != KeaFactorMemory::Off && staleWorthIt_) factorKept_ = true;
}

/* The order of the envelope path, once per problem. Any order's envelope
 * holds the lower triangle's nonzeros, so when the natural order's envelope
 * is within kOrderSlack of that count no renumbering can gain much and the
 * rows keep their order (stacks, chains: O(n) to check). Otherwise reverse
 * Cuthill-McKee is computed and kept if its envelope is smaller. Also
 * judges, in the order kept, whether a small block is cheaper dense
 * (denseCheaper_). */
void SparseBackend::chooseEnvelopeOrder() {
  const SparseLcpProblem &p = *p_;
  const auto n = static_cast<std::size_t>(p.n);
  constexpr std::size_t kOrderSlack = 3; /* in halves: 1.5 */
  /* Symmetric with every diagonal present: the lower triangle holds
   * (nnz + n) / 2 entries. */
  const std::size_t lower = (U(p.rowStart[n]) + n) / 2;
  std::size_t natural = 0, naturalCrout = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t width = i - std::min(i, U(p.col[U(p.rowStart[i])]));
    natural += width + 1;
    naturalCrout += width * width;
  }
  orderChosen_ = true;
  useBandOrder_ = false;
  /* Judged once per problem on the whole matrix in the order kept; each
   * free block of at most kDenseRows rows follows the judgement. */
  denseCheaper_ = DenseCheaper(n, naturalCrout);
  if (2 * natural <= kOrderSlack * lower) return;
  computeBandOrder();
  for (std::size_t r = 0; r < n; ++r) bandRank_[U(bandOrder_[r])] = static_cast<int>(r);
  std::size_t band = 0, bandCrout = 0;
  for (std::size_t r = 0; r < n; ++r) {
    const auto i = U(bandOrder_[r]);
    std::size_t first = r;
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k) first = std::min(first, U(bandRank_[U(p.col[U(k)])]));
    band += r - first + 1;
    bandCrout += (r - first) * (r - first);
  }
  useBandOrder_ = band < natural;
  if (useBandOrder_) denseCheaper_ = DenseCheaper(n, bandCrout);
}

/* envelope_.first[] for the free block with its rows in the order of
 * `rows` (row a's leftmost free column, by position in `rows`); returns the
 * envelope's size. */
std::size_t SparseBackend::envelopeFirsts(const std::vector<int> &rows) {
  const SparseLcpProblem &p = *p_;
  const std::size_t m = rows.size();
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = static_cast<int>(a);
  envelope_.begin(static_cast<int>(m));
  std::size_t entries = 0;
  /* Rows in ascending order (the natural order) have ascending positions
   * along a CSR row, so the first free column found is the leftmost. */
  const bool ascending = &rows == &naturalRows_;
  for (std::size_t a = 0; a < m; ++a) {
    const auto i = U(rows[a]);
    int first = static_cast<int>(a);
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k) {
      const int c = position_[U(p.col[U(k)])];
      if (c >= 0 && c < first) {
        first = c;
        if (ascending) break;
      }
    }
    envelope_.first[a] = first;
    entries += a - U(first) + 1;
  }
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = -1;
  return entries;
}

/* How many leading rows of the last envelope factor the free block with
 * rows `rows` (in factor order) can keep: the length of the two row lists'
 * common prefix. Row a of an envelope LDL^T depends on rows 0..a of the
 * matrix only, and the leading block of the free rows is the same matrix
 * when the same rows lead in the same order, with the same envelope
 * (envelopeFirsts looks only left of the diagonal). So a pivot that frees
 * or clamps the row at position k refactorises rows k.. only, and the
 * factor is the one a whole factorisation gives, bit for bit. */
std::size_t SparseBackend::reusableEnvelopeRows(const std::vector<int> &rows) const {
  const auto mismatch = std::mismatch(rows.begin(), rows.end(), envelopeFactorRows_.begin(), envelopeFactorRows_.end());
  return static_cast<std::size_t>(mismatch.first - rows.begin());
}

/* visit(a, c, k) for each stored entry k of free row rows[a], a >= from,
 * whose column is free row rows[c] (positions in `rows`). */
template <class Visit>
void SparseBackend::forEachFreeEntry(const std::vector<int> &rows, Visit visit, std::size_t from) {
  const SparseLcpProblem &p = *p_;
  const std::size_t m = rows.size();
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = static_cast<int>(a);
  for (std::size_t a = from; a < m; ++a) {
    const auto i = U(rows[a]);
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
      if (const int c = position_[U(p.col[U(k)])]; c >= 0) visit(a, U(c), k);
  }
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = -1;
}

/* Lays the envelope out (firsts from envelopeFirsts on the same rows) and
 * stores the free block (A + eps I)_FF in it, from row `from` on (the rows
 * before it keep what they hold: see reusableEnvelopeRows). */
void SparseBackend::fillEnvelope(const std::vector<int> &rows, std::size_t from) {
  const SparseLcpProblem &p = *p_;
  const std::span<const MeReal> val = values();
  const std::size_t m = rows.size();
  envelope_.layout(static_cast<int>(from));
  /* Rows in ascending order (the natural order) meet their columns in
   * ascending positions, so a row's lower entries end at its diagonal. */
  const bool ascending = &rows == &naturalRows_;
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = static_cast<int>(a);
  for (std::size_t a = from; a < m; ++a) {
    const auto i = U(rows[a]);
    /* row[c - first] = entry (a, c): envelopeFirsts made first the
     * leftmost free column. */
    const int first = envelope_.first[a];
    MeReal *row = envelope_.value.data() + envelope_.at(static_cast<int>(a), first);
    const int end = p.rowStart[i + 1];
    if (ascending) {
      for (int k = p.rowStart[i]; k < end && U(p.col[U(k)]) <= i; ++k)
        if (const int c = position_[U(p.col[U(k)])]; c >= 0) row[c - first] = val[U(k)];
    } else {
      for (int k = p.rowStart[i]; k < end; ++k)
        if (const int c = position_[U(p.col[U(k)])]; c >= 0 && U(c) <= a) row[c - first] = val[U(k)];
    }
    row[a - U(first)] += eps_;
  }
  for (std::size_t a = 0; a < m; ++a) position_[U(rows[a])] = -1;
}

/* The upper-triangle entries of the free block (A + eps I)_FF with the
 * rows and columns in the order denseRows_, as pairs (CSR index, index in
 * the dense block, row-major), kept with the sparsity and the free rows
 * they were made for. */
void SparseBackend::mapDense() {
  const auto stride = U(dense_.stride);
  denseFill_.clear();
  densePattern_.assign(denseRows_.size(), DenseLdlt::RowBits{});
  forEachFreeEntry(denseRows_, [&](std::size_t a, std::size_t c, int k) {
    if (c >= a) denseFill_.emplace_back(k, static_cast<int>(a * stride + c));
    if (c > a) DenseLdlt::SetRowBit(densePattern_[a], c);
  });
  denseMapRows_ = denseRows_;
}

/* All rows by their number of nonzeros, then by index (std::sort: no
 * allocation). */
void SparseBackend::computeDegreeOrder() {
  const SparseLcpProblem &p = *p_;
  degreeOrder_.resize(U(p.n));
  for (std::size_t i = 0; i < degreeOrder_.size(); ++i) degreeOrder_[i] = static_cast<int>(i);
  const auto degree = [&p](int i) { return p.rowStart[U(i) + 1] - p.rowStart[U(i)]; };
  std::sort(degreeOrder_.begin(), degreeOrder_.end(),
            [&](int a, int b) { return degree(a) != degree(b) ? degree(a) < degree(b) : a < b; });
}

/* The free block (A + eps I)_FF factorised densely, its rows ordered by
 * their number of nonzeros in A, then by index (denseRows_): a row that
 * meets few others is eliminated before the fill reaches it (see
 * kea_dense_ldlt.h). False on breakdown (the envelope path then takes the
 * block, with its least-squares fallback). */
bool SparseBackend::factoriseDense(const std::vector<unsigned char> &set) {
  const std::span<const MeReal> val = values();
  /* The order, the map and the pattern depend on the sparsity only (the
   * map and the pattern on the free rows too): keepOrderings drops all
   * three for a problem of another one. */
  if (degreeOrder_.empty()) computeDegreeOrder();
  std::vector<int> &rows = denseRows_;
  rows.clear();
  for (int i : degreeOrder_)
    if (set[U(i)] == Free) rows.push_back(i);
  const std::size_t m = rows.size();
  /* The pattern, and so which rows meet, depends on the sparsity and the
   * free rows only: the last dense factor's is kept while they stay. */
  const bool samePattern = rows == densePatternRows_;
  dense_.begin(static_cast<int>(m), samePattern ? DenseLdlt::Pattern::Kept : DenseLdlt::Pattern::Noted);
  MeReal *upper = dense_.upper.data();
  /* The map pays when the same free rows come back (the next step's first
   * factorisation, from the warm start's active set); while pivots change
   * them, the block is filled straight from the CSR rows (the same values
   * in the same places), and the rows are remembered as a candidate. */
  if (rows != denseMapRows_ && rows != denseCandidateRows_) {
    const auto stride = U(dense_.stride);
    forEachFreeEntry(rows, [&](std::size_t a, std::size_t c, int k) {
      if (c < a) return;
      upper[a * stride + c] = val[U(k)];
      if (c > a && !samePattern) dense_.notePattern(static_cast<int>(a), static_cast<int>(c));
    });
    denseCandidateRows_ = rows;
  } else {
    if (rows != denseMapRows_) mapDense();
    for (const auto &[k, at] : denseFill_) upper[U(at)] = val[U(k)];
    if (!samePattern) std::copy(densePattern_.begin(), densePattern_.end(), dense_.pattern.begin());
  }
  densePatternRows_ = rows;
  for (std::size_t a = 0; a < m; ++a) upper[a * U(dense_.stride) + a] += eps_;
  if (!dense_.factor()) return false;
  factor_ = Factor::Dense;
  return true;
}

/* Reverse Cuthill-McKee on the whole matrix's graph (rows joined by a
 * nonzero), once per problem: each connected component is numbered breadth
 * first from a row of least degree, the unnumbered neighbours of a row
 * taken by increasing degree (then index), and the whole numbering is
 * reversed (George & Liu, ch. 4). This keeps each row's nonzeros near the
 * diagonal, so the envelope of a tree (a rag doll) or a heap is narrow
 * where the order the rows came in is not. */
void SparseBackend::computeBandOrder() {
  const SparseLcpProblem &p = *p_;
  const auto n = static_cast<std::size_t>(p.n);
  auto degree = [&](int i) { return p.rowStart[U(i) + 1] - p.rowStart[U(i)]; };
  bandOrder_.clear();
  bandRank_.assign(n, -1); /* -1 = not numbered yet */
  for (;;) {
    int start = -1;
    for (std::size_t i = 0; i < n; ++i)
      if (bandRank_[i] < 0 && (start < 0 || degree(static_cast<int>(i)) < degree(start))) start = static_cast<int>(i);
    if (start < 0) break;
    bandRank_[U(start)] = 0;
    bandOrder_.push_back(start);
    for (std::size_t head = bandOrder_.size() - 1; head < bandOrder_.size(); ++head) {
      const auto i = U(bandOrder_[head]);
      queue_.clear();
      for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k) {
        const int j = p.col[U(k)];
        if (bandRank_[U(j)] < 0) {
          bandRank_[U(j)] = 0;
          queue_.push_back(j);
        }
      }
      std::sort(queue_.begin(), queue_.end(),
                [&](int a, int b) { return degree(a) != degree(b) ? degree(a) < degree(b) : a < b; });
      bandOrder_.insert(bandOrder_.end(), queue_.begin(), queue_.end());
    }
  }
  std::reverse(bandOrder_.begin(), bandOrder_.end());
}

/* AMD on the whole matrix's pattern (CSR of a symmetric matrix is also its
 * CSC). order_ lists the rows in elimination order.
 *
 * Each free block is then eliminated in the induced order (its rows in the
 * order AMD gave them). The fill of a principal submatrix under the induced
 * order is never more than the fill of the whole matrix under the full
 * order, so this keeps the factorisation sparse without re-running AMD (the
 * largest cost of a factorisation) at every pivot step. */
void SparseBackend::computeOrder() {
  const SparseLcpProblem &p = *p_;
  const auto n = static_cast<Eigen::Index>(p.n);
  const auto nnz = static_cast<Eigen::Index>(p.rowStart[U(p.n)]);
  const Eigen::Map<const SpMat> full(n, n, nnz, p.rowStart.data(), p.col.data(), values().data());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> pinv;
  Eigen::AMDOrdering<int> amd;
  amd(full.selfadjointView<Eigen::Upper>(), pinv);
  order_.assign(pinv.indices().data(), pinv.indices().data() + pinv.indices().size());
  if (order_.size() != U(p.n)) {
    order_.resize(U(p.n));
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  }
  buildOrderedUpper();
}

/* The upper triangle in elimination order, once per problem: for the row at
 * rank r (order_[r]), its entries at rank <= r, sorted by rank
 * (upStart_/upRow_/upVal_). A free block is a principal submatrix and its
 * rows keep their relative order, so gatherUpper only filters these lists:
 * no sorting per pivot step. */
void SparseBackend::buildOrderedUpper() {
  const SparseLcpProblem &p = *p_;
  const std::span<const MeReal> val = values();
  const auto n = static_cast<std::size_t>(p.n);
  rank_.resize(n);
  for (std::size_t r = 0; r < n; ++r) rank_[U(order_[r])] = static_cast<int>(r);
  upStart_.assign(n + 1, 0);
  upRow_.clear();
  upVal_.clear();
  for (std::size_t r = 0; r < n; ++r) {
    const auto i = U(order_[r]);
    entries_.clear(); /* (rank of the column, CSR index) */
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k) {
      const int c = rank_[U(p.col[U(k)])];
      if (c <= static_cast<int>(r)) entries_.emplace_back(c, k);
    }
    std::sort(entries_.begin(), entries_.end());
    for (const auto &[c, k] : entries_) {
      upRow_.push_back(p.col[U(k)]);
      upVal_.push_back(val[U(k)]);
    }
    upStart_[r + 1] = static_cast<int>(upRow_.size());
  }
}

/* The free block in elimination order (orderedRows_): column a holds free
 * row a's entries on and above the diagonal (positions <= a), sorted.
 * `shift` is added to the diagonal. */
void SparseBackend::gatherUpper(std::size_t m, MeReal shift) {
  for (std::size_t a = 0; a < m; ++a) position_[U(orderedRows_[a])] = static_cast<int>(a);
  std::size_t bound = 0;
  for (std::size_t a = 0; a < m; ++a) {
    const auto r = U(rank_[U(orderedRows_[a])]);
    bound += U(upStart_[r + 1] - upStart_[r]);
  }
  block_.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  block_.resizeNonZeros(static_cast<Eigen::Index>(bound));
  int *outer = block_.outerIndexPtr();
  int *inner = block_.innerIndexPtr();
  MeReal *value = block_.valuePtr();
  int at = 0;
  for (std::size_t a = 0; a < m; ++a) {
    outer[a] = at;
    const auto r = U(rank_[U(orderedRows_[a])]);
    for (int k = upStart_[r]; k < upStart_[r + 1]; ++k) {
      /* Ranks <= r, so a free column's position is <= a. */
      const int c = position_[U(upRow_[U(k)])];
      if (c < 0) continue;
      inner[at] = c;
      value[at] = upVal_[U(k)] + (c == static_cast<int>(a) ? eps_ + shift : MeReal(0));
      ++at;
    }
  }
  outer[m] = at;
  block_.resizeNonZeros(at); /* shrinks the size only: the entries stay */
  for (std::size_t a = 0; a < m; ++a) position_[U(orderedRows_[a])] = -1;
}

void SparseBackend::factoriseSparse(const std::vector<unsigned char> &set) {
  const std::size_t m = naturalRows_.size();
  if (order_.empty())
    computeOrder();
  else if (!upperFresh_)
    buildOrderedUpper();
  upperFresh_ = true;
  orderedRows_.clear();
  for (int i : order_)
    if (set[U(i)] == Free) orderedRows_.push_back(i);
  gatherUpper(m, 0);
  ldlt_.computePreordered(block_);
  ldltOk_ = ldlt_.info() == Eigen::Success;
  factor_ = Factor::Sparse;
}

/* x_ = the sparse factor's solution for rhs_; false when it broke down or
 * gave non-finite values. */
bool SparseBackend::solveSparse(std::size_t m) {
  if (!ldltOk_) return false;
  const Vec x = ldlt_.solve(Eigen::Map<const Vec>(rhs_.data(), static_cast<Eigen::Index>(m)));
  if (!x.allFinite()) return false;
  std::copy(x.data(), x.data() + m, x_.begin());
  return true;
}

/* The sparse factorisation broke down (or gave non-finite values): a dense
 * solve with least-squares fallback up to kDenseFallback rows (kept as the
 * factor of this free set), a diagonally shifted sparse LDL^T beyond. */
void SparseBackend::fallback(const std::vector<unsigned char> &set, std::vector<MeReal> &lambda) {
  const std::size_t m = naturalRows_.size();
  if (m <= kDenseFallback) {
    envelope_.begin(static_cast<int>(m)); /* full rows: a dense LDL^T */
    fillEnvelope(naturalRows_);
    envelope_.factor();
    factor_ = Factor::Envelope;
    buildRhs(naturalRows_, set, lambda);
    envelope_.solve(rhs_, x_);
    for (std::size_t a = 0; a < m; ++a) lambda[U(naturalRows_[a])] = x_[a];
    return;
  }
  /* A small shift on the diagonal makes a semi-definite block definite. */
  const SparseLcpProblem &p = *p_;
  const std::span<const MeReal> val = values();
  MeReal diagMax = 0;
  for (int i : naturalRows_)
    for (int k = p.rowStart[U(i)]; k < p.rowStart[U(i) + 1]; ++k)
      if (p.col[U(k)] == i) diagMax = std::max(diagMax, std::fabs(val[U(k)]));
  gatherUpper(m, std::sqrt(ME_REAL_EPSILON) * (1 + diagMax));
  const Ldlt shifted(block_);
  Vec x;
  if (shifted.info() == Eigen::Success)
    x = shifted.solve(Eigen::Map<const Vec>(rhs_.data(), static_cast<Eigen::Index>(m)));
  if (x.size() != static_cast<Eigen::Index>(m) || !x.allFinite()) x = Vec::Zero(static_cast<Eigen::Index>(m));
  /* The kept factorisation is the unshifted one; drop it. */
  factor_ = Factor::None;
  for (std::size_t a = 0; a < m; ++a) lambda[U(orderedRows_[a])] = x(static_cast<Eigen::Index>(a));
}

}  // namespace karma::kea::detail
