/* kea_sparse.cpp: the solvers for problems whose matrix comes in compressed
 * sparse rows (what Mdt builds: A's sparsity follows which rows share a
 * body, so a chain gives a banded A with a handful of entries per row).
 *
 * Same contract, options, statuses and warnings as the dense solvers
 * (kea_lcp.h); only the matrix operations differ:
 *
 *  - Active set: the pivoting logic is the dense solver's, shared through
 *    kea_activeset_core.h. The free block (A + eps I)_FF is gathered from
 *    the CSR rows into a sparse triangle and factorised by a sparse LDL^T
 *    (Eigen's SimplicialLDLT) in a fill-reducing order (approximate minimum
 *    degree, computed once for the whole matrix; see SparseBackend), so a
 *    banded block costs O(m) to factorise and solve instead of O(m^3). When the free set is unchanged from the previous solve (the
 *    friction fixed point re-solving with new bounds) the factorisation is
 *    reused. Small free blocks (at most kDenseBlock rows) go through the
 *    dense LDL^T, which is faster there. A factorisation that breaks down
 *    (not positive definite, e.g. eps = 0 with redundant rows) falls back to
 *    the dense least-squares solve for blocks up to kDenseFallback rows, and
 *    to a slightly shifted sparse LDL^T beyond.
 *
 *  - PGS: the dense sweep, visiting only each row's stored entries: O(nnz)
 *    per sweep.
 *
 * Apart from the linear solves every step is O(n + nnz), so the cost of a
 * chain grows linearly with its length. */
#include "kea_activeset_core.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <utility>

namespace karma::kea {
namespace {

constexpr std::size_t kDenseBlock = 20;     /* free blocks up to this size are solved densely */
constexpr std::size_t kDenseFallback = 600; /* breakdown fallback: dense least squares up to this size */

using SpMat = Eigen::SparseMatrix<MeReal, Eigen::ColMajor, int>;
using Vec = Eigen::Matrix<MeReal, Eigen::Dynamic, 1>;

/* w = (A + eps I) lambda - b over the CSR rows. */
void SparseW(const SparseLcpProblem &p, MeReal eps, std::span<const MeReal> lambda, std::vector<MeReal> &w) {
  const auto n = static_cast<std::size_t>(p.n);
  w.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    MeReal wi = -p.b[i] + eps * lambda[i];
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
      wi += p.val[static_cast<std::size_t>(k)] * lambda[static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)])];
    w[i] = wi;
  }
}

MeReal SparseResidual(const SparseLcpProblem &p, MeReal eps, std::span<const MeReal> lambda,
                      std::vector<MeReal> &scratch) {
  SparseW(p, eps, lambda, scratch);
  return detail::ComplementarityResidual(detail::Rows(p), lambda, scratch);
}

/* The sparse matrix operations of the active-set core.
 *
 * Ordering: an approximate minimum degree (AMD) ordering is computed once,
 * for the pattern of the whole matrix, on the first sparse factorisation.
 * Each free block is then eliminated in the induced order (its rows in the
 * order AMD gave them). The fill of a principal submatrix under the induced
 * order is never more than the fill of the whole matrix under the full
 * order, so this keeps the factorisation sparse without re-running AMD (the
 * largest cost of a factorisation) at every pivot step. */
class SparseBackend {
 public:
  SparseBackend(const SparseLcpProblem &p, MeReal eps)
      : p_(p), eps_(eps), position_(static_cast<std::size_t>(p.n), -1) {}

  MeReal residual(std::span<const MeReal> lambda, std::span<MeReal> w) {
    const MeReal r = SparseResidual(p_, eps_, lambda, wScratch_);
    if (w.size() == wScratch_.size()) std::copy(wScratch_.begin(), wScratch_.end(), w.begin());
    return r;
  }

  void solveFree(const std::vector<unsigned char> &set, const std::vector<MeReal> &lo,
                 const std::vector<MeReal> &hi, std::vector<MeReal> &lambda) {
    const auto n = static_cast<std::size_t>(p_.n);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (set[i] == detail::AtLo) lambda[i] = lo[i];
      else if (set[i] == detail::AtHi) lambda[i] = hi[i];
      else ++m;
    }
    if (m == 0) return;

    /* The free rows, in the elimination order (natural order for the
     * dense solve). */
    freeRows_.clear();
    if (m <= kDenseBlock) {
      for (std::size_t i = 0; i < n; ++i)
        if (set[i] == detail::Free) freeRows_.push_back(static_cast<int>(i));
    } else {
      if (order_.empty()) computeOrder();
      for (int i : order_)
        if (set[static_cast<std::size_t>(i)] == detail::Free) freeRows_.push_back(i);
    }
    for (std::size_t a = 0; a < m; ++a) position_[static_cast<std::size_t>(freeRows_[a])] = static_cast<int>(a);

    /* rhs = b_F - A_FC lambda_C */
    rhs_.resize(static_cast<Eigen::Index>(m));
    for (std::size_t a = 0; a < m; ++a) {
      const auto i = static_cast<std::size_t>(freeRows_[a]);
      MeReal r = p_.b[i];
      for (int k = p_.rowStart[i]; k < p_.rowStart[i + 1]; ++k) {
        const auto j = static_cast<std::size_t>(p_.col[static_cast<std::size_t>(k)]);
        if (set[j] != detail::Free) r -= p_.val[static_cast<std::size_t>(k)] * lambda[j];
      }
      rhs_(static_cast<Eigen::Index>(a)) = r;
    }

    if (m <= kDenseBlock) {
      solveDense(m);
    } else {
      if (!factored_ || freeRows_ != factoredRows_) factorise(m);
      Vec x;
      if (ldltOk_) x = ldlt_.solve(rhs_);
      if (!ldltOk_ || !x.allFinite()) x = fallback(m);
      x_.assign(x.data(), x.data() + x.size());
    }
    for (std::size_t a = 0; a < m; ++a) {
      const auto i = static_cast<std::size_t>(freeRows_[a]);
      lambda[i] = x_[a];
      position_[i] = -1;
    }
  }

 private:
  /* AMD on the whole matrix's pattern (CSR of a symmetric matrix is also its
   * CSC). order_ lists the rows in elimination order. Then the upper triangle
   * in that order, once per problem: for the row at rank r (order_[r]), its
   * entries at rank <= r, sorted by rank (upStart_/upRow_/upVal_). A free
   * block is a principal submatrix and its rows keep their relative order,
   * so gatherUpper only filters these lists: no sorting per pivot step. */
  void computeOrder() {
    const auto n = static_cast<Eigen::Index>(p_.n);
    const auto nnz = static_cast<Eigen::Index>(p_.rowStart[static_cast<std::size_t>(p_.n)]);
    const Eigen::Map<const SpMat> full(n, n, nnz, p_.rowStart.data(), p_.col.data(), p_.val.data());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> pinv;
    Eigen::AMDOrdering<int> amd;
    amd(full.selfadjointView<Eigen::Upper>(), pinv);
    order_.assign(pinv.indices().data(), pinv.indices().data() + pinv.indices().size());
    if (order_.size() != static_cast<std::size_t>(p_.n)) {
      order_.resize(static_cast<std::size_t>(p_.n));
      for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    }
    buildOrderedUpper();
  }

  void buildOrderedUpper() {
    const auto n = static_cast<std::size_t>(p_.n);
    std::vector<int> rank(n);
    for (std::size_t r = 0; r < n; ++r) rank[static_cast<std::size_t>(order_[r])] = static_cast<int>(r);
    upStart_.assign(n + 1, 0);
    upRow_.clear();
    upVal_.clear();
    std::vector<std::pair<int, int>> entries; /* (rank of the column, CSR index) */
    for (std::size_t r = 0; r < n; ++r) {
      const auto i = static_cast<std::size_t>(order_[r]);
      entries.clear();
      for (int k = p_.rowStart[i]; k < p_.rowStart[i + 1]; ++k) {
        const int c = rank[static_cast<std::size_t>(p_.col[static_cast<std::size_t>(k)])];
        if (c <= static_cast<int>(r)) entries.emplace_back(c, k);
      }
      std::sort(entries.begin(), entries.end());
      for (const auto &[c, k] : entries) {
        upRow_.push_back(p_.col[static_cast<std::size_t>(k)]);
        upVal_.push_back(p_.val[static_cast<std::size_t>(k)]);
      }
      upStart_[r + 1] = static_cast<int>(upRow_.size());
    }
    rank_.swap(rank);
  }

  /* The free block in elimination order: column a holds free row a's
   * entries on and above the diagonal (positions <= a), sorted. `shift` is
   * added to the diagonal. */
  void gatherUpper(std::size_t m, MeReal shift) {
    std::size_t bound = 0;
    for (std::size_t a = 0; a < m; ++a) {
      const auto r = static_cast<std::size_t>(rank_[static_cast<std::size_t>(freeRows_[a])]);
      bound += static_cast<std::size_t>(upStart_[r + 1] - upStart_[r]);
    }
    block_.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    block_.resizeNonZeros(static_cast<Eigen::Index>(bound));
    int *outer = block_.outerIndexPtr();
    int *inner = block_.innerIndexPtr();
    MeReal *value = block_.valuePtr();
    int at = 0;
    for (std::size_t a = 0; a < m; ++a) {
      outer[a] = at;
      const auto r = static_cast<std::size_t>(rank_[static_cast<std::size_t>(freeRows_[a])]);
      for (int k = upStart_[r]; k < upStart_[r + 1]; ++k) {
        /* Ranks <= r, so a free column's position is <= a. */
        const int c = position_[static_cast<std::size_t>(upRow_[static_cast<std::size_t>(k)])];
        if (c < 0) continue;
        inner[at] = c;
        value[at] = upVal_[static_cast<std::size_t>(k)] + (c == static_cast<int>(a) ? eps_ + shift : MeReal(0));
        ++at;
      }
    }
    outer[m] = at;
    block_.resizeNonZeros(at); /* shrinks the size only: the entries stay */
  }

  void factorise(std::size_t m) {
    gatherUpper(m, 0);
    ldlt_.computePreordered(block_);
    ldltOk_ = ldlt_.info() == Eigen::Success;
    factored_ = true;
    factoredRows_ = freeRows_;
  }

  void solveDense(std::size_t m) {
    dense_.assign(m * m, MeReal(0));
    for (std::size_t a = 0; a < m; ++a) {
      const auto i = static_cast<std::size_t>(freeRows_[a]);
      for (int k = p_.rowStart[i]; k < p_.rowStart[i + 1]; ++k) {
        const int c = position_[static_cast<std::size_t>(p_.col[static_cast<std::size_t>(k)])];
        if (c >= 0) dense_[static_cast<std::size_t>(c) * m + a] = p_.val[static_cast<std::size_t>(k)];
      }
      dense_[a * m + a] += eps_;
    }
    denseRhs_.assign(rhs_.data(), rhs_.data() + rhs_.size());
    detail::SolveDenseBlock(dense_, denseRhs_, static_cast<int>(m), x_);
  }

  /* The factorisation broke down (or gave non-finite values). */
  Vec fallback(std::size_t m) {
    if (m <= kDenseFallback) {
      solveDense(m);
      return Eigen::Map<const Vec>(x_.data(), static_cast<Eigen::Index>(m));
    }
    /* A small shift on the diagonal makes a semi-definite block definite. */
    MeReal diagMax = 0;
    for (std::size_t a = 0; a < m; ++a) {
      const auto i = static_cast<std::size_t>(freeRows_[a]);
      for (int k = p_.rowStart[i]; k < p_.rowStart[i + 1]; ++k)
        if (static_cast<std::size_t>(p_.col[static_cast<std::size_t>(k)]) == i)
          diagMax = std::max(diagMax, std::fabs(p_.val[static_cast<std::size_t>(k)]));
    }
    gatherUpper(m, std::sqrt(ME_REAL_EPSILON) * (1 + diagMax));
    Ldlt shifted(block_);
    Vec x;
    if (shifted.info() == Eigen::Success) x = shifted.solve(rhs_);
    if (x.size() != static_cast<Eigen::Index>(m) || !x.allFinite()) x = Vec::Zero(static_cast<Eigen::Index>(m));
    /* The cached factorisation is the unshifted one; drop it. */
    factored_ = false;
    return x;
  }

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

  const SparseLcpProblem &p_;
  MeReal eps_;
  std::vector<int> position_, freeRows_, factoredRows_, order_, rank_, upStart_, upRow_;
  std::vector<MeReal> upVal_;
  std::vector<MeReal> wScratch_, x_, dense_, denseRhs_;
  Vec rhs_;
  SpMat block_;
  PreorderedLdlt ldlt_;
  bool factored_ = false, ldltOk_ = false;
};

/* Projected Gauss-Seidel over the CSR rows (see kea_pgs.cpp for the
 * method). */
KeaResult SparsePgs(const SparseLcpProblem &p, const KeaOptions &o, const char *name) {
  const auto n = static_cast<std::size_t>(p.n);
  const MeReal eps = o.epsilon;
  const int cap = o.maxIterations > 0 ? o.maxIterations : 50;
  const detail::RowView rows = detail::Rows(p);
  const MeReal threshold = detail::SolvedThreshold(rows, o);

  KeaResult r;
  r.lambda.assign(n, MeReal(0));
  r.w.assign(n, MeReal(0));
  if (!o.warmStart.empty()) std::copy(o.warmStart.begin(), o.warmStart.end(), r.lambda.begin());

  std::vector<MeReal> lo, hi, scratch;
  detail::ComputeBounds(rows, r.lambda, lo, hi);
  for (std::size_t i = 0; i < n; ++i) r.lambda[i] = std::clamp(r.lambda[i], lo[i], hi[i]);

  std::vector<MeReal> diag(n, MeReal(0));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
      if (static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)]) == i) diag[i] = p.val[static_cast<std::size_t>(k)] + eps;

  std::vector<MeReal> best = r.lambda;
  MeReal bestResidual = SparseResidual(p, eps, r.lambda, scratch);
  const bool friction = !p.findex.empty();
  int sweeps = 0;
  while (bestResidual > threshold && sweeps < cap) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!(diag[i] > 0)) continue; /* a null row: nothing to gain from it */
      MeReal wi = -p.b[i] + eps * r.lambda[i];
      for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
        wi += p.val[static_cast<std::size_t>(k)] * r.lambda[static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)])];
      MeReal rowLo = lo[i], rowHi = hi[i];
      if (friction && p.findex[i] >= 0) {
        const MeReal limit = p.mu[i] * std::max(r.lambda[static_cast<std::size_t>(p.findex[i])], MeReal(0));
        rowLo = -limit;
        rowHi = limit;
      }
      r.lambda[i] = std::clamp(r.lambda[i] - wi / diag[i], rowLo, rowHi);
    }
    ++sweeps;
    const MeReal residual = SparseResidual(p, eps, r.lambda, scratch);
    if (residual < bestResidual) {
      bestResidual = residual;
      best = r.lambda;
    }
  }

  r.lambda = best;
  r.residual = SparseResidual(p, eps, r.lambda, r.w);
  r.iterations = sweeps;
  if (r.residual <= threshold) {
    r.status = KeaStatus::Solved;
  } else {
    r.status = KeaStatus::IterationLimit;
    detail::WarnIterationLimit(o, name, sweeps, r.residual);
  }
  return r;
}

}  // namespace

struct KeaWorkspace {};
KeaWorkspace *KeaWorkspaceCreate() { return new KeaWorkspace; }
void KeaWorkspaceDestroy(KeaWorkspace *workspace) { delete workspace; }

void KeaSolveSparse(const SparseLcpProblem &p, const KeaOptions &o, KeaWorkspace &,
                    KeaResult &result) {
  result = KeaSolveSparse(p, o);
}

KeaResult KeaSolveSparse(const SparseLcpProblem &p, const KeaOptions &o) {
  static const char *const kName = "KeaSolveSparse";
  if (!detail::ValidateSparse(p, o, kName)) return detail::BadInputResult(p.n);
  if (o.method == KeaMethod::PGS) return SparsePgs(p, o, kName);
  SparseBackend backend(p, o.epsilon);
  return detail::ActiveSetCore(detail::Rows(p), o, kName, backend);
}

}  // namespace karma::kea
