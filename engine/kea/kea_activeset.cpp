/* kea_activeset.cpp: the exact boxed-LCP method.
 *
 * Every row is in one of three sets: free (lo < lambda < hi, w = 0), at its
 * lower bound, or at its upper bound. Given a guess of the sets, the clamped
 * rows take their bound values and the free rows solve the linear system
 *     (A + eps I)_FF lambda_F = b_F - A_FC lambda_C
 * by an LDL^T (Cholesky) factorisation of the free block. The guess is then
 * checked: a free row outside its box, or a clamped row whose w has the wrong
 * sign, is infeasible and changes set. The sets are updated by block
 * principal pivoting (Judice & Pires): all infeasible rows change set at
 * once while the number of infeasibilities keeps falling; when it stops
 * falling for a few steps, one row at a time changes set (Murty's rule, the
 * highest-index infeasible row), which terminates for a positive definite
 * matrix. During single pivoting the sets already tried are remembered; a
 * repeat is a cycle (rounding, or eps = 0 on a singular matrix).
 *
 * Friction rows: their bounds depend on the normal lambdas. The inner
 * pivoting solves the LCP with the bounds frozen at the current lambda; then
 * the bounds are recomputed from the new normal lambdas and, if any moved,
 * the inner solve is repeated from the current sets. This fixed-point
 * iteration is the approximate handling the contract describes: it is not
 * guaranteed to converge, but does in practice (friction bounds only grow or
 * shrink with their normal force, which changes little once the contact set
 * is right); the iteration cap bounds it either way. After 10 rounds the
 * bound update is relaxed by half (kea_activeset_core.h), which turns the
 * usual failure, a 2-cycle of the bounds, into convergence.
 *
 * A warm start (last step's lambda) gives the initial sets: rows at a finite
 * bound start clamped there, the rest free. A good guess usually needs one
 * or two linear solves.
 *
 * The pivoting logic lives in kea_activeset_core.h and is shared with the
 * sparse solver (kea_sparse.cpp); this file supplies the dense matrix
 * operations: the residual over the dense rows and a dense LDL^T of the free
 * block. */
#include "kea_activeset_core.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace karma::kea {
namespace detail {

void SolveDenseBlock(std::vector<MeReal> &block, std::vector<MeReal> &rhs, int m, std::vector<MeReal> &x) {
  using Mat = Eigen::Matrix<MeReal, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<MeReal, Eigen::Dynamic, 1>;
  const Eigen::Map<const Mat> A(block.data(), m, m);
  const Eigen::Map<const Vec> b(rhs.data(), m);
  Vec sol;
  Eigen::LDLT<Mat> ldlt(A);
  if (ldlt.info() == Eigen::Success) sol = ldlt.solve(b);
  if (sol.size() != m || !sol.allFinite()) {
    /* Not positive semi-definite, or breakdown: a least-squares solve. */
    sol = A.completeOrthogonalDecomposition().solve(b);
  }
  x.assign(sol.data(), sol.data() + m);
}

}  // namespace detail

namespace {

/* The dense matrix operations of the active-set core. */
struct DenseBackend {
  const LcpProblem &p;
  MeReal eps;
  std::vector<std::size_t> freeRows;
  std::vector<MeReal> block, rhs, x;

  MeReal residual(std::span<const MeReal> lambda, std::span<MeReal> w) { return KeaResidual(p, eps, lambda, w); }

  /* Solves for the free rows with the clamped rows at their (frozen)
   * bounds; writes the whole lambda. */
  void solveFree(const std::vector<unsigned char> &set, const std::vector<MeReal> &lo,
                 const std::vector<MeReal> &hi, std::vector<MeReal> &lambda) {
    const auto n = static_cast<std::size_t>(p.n);
    freeRows.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (set[i] == detail::AtLo) lambda[i] = lo[i];
      else if (set[i] == detail::AtHi) lambda[i] = hi[i];
      else freeRows.push_back(i);
    }
    const std::size_t m = freeRows.size();
    if (m == 0) return;
    block.assign(m * m, MeReal(0));
    rhs.assign(m, MeReal(0));
    for (std::size_t a = 0; a < m; ++a) {
      const std::size_t i = freeRows[a];
      const MeReal *row = p.A.data() + i * n;
      /* Column-major; the block is symmetric, so row a is column a. */
      for (std::size_t c = 0; c < m; ++c) block[c * m + a] = row[freeRows[c]];
      block[a * m + a] += eps;
      MeReal r = p.b[i];
      for (std::size_t j = 0; j < n; ++j)
        if (set[j] != detail::Free) r -= row[j] * lambda[j];
      rhs[a] = r;
    }
    detail::SolveDenseBlock(block, rhs, static_cast<int>(m), x);
    for (std::size_t a = 0; a < m; ++a) lambda[freeRows[a]] = x[a];
  }
};

}  // namespace

KeaResult KeaSolveActiveSet(const LcpProblem &p, const KeaOptions &o) {
  static const char *const kName = "KeaSolveActiveSet";
  if (!detail::Validate(p, o, kName)) return detail::BadInputResult(p.n);
  DenseBackend backend{p, o.epsilon, {}, {}, {}, {}};
  return detail::ActiveSetCore(detail::Rows(p), o, kName, backend);
}

}  // namespace karma::kea
