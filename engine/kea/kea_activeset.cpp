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
 * repeat is a cycle (rounding, or eps = 0 on a singular matrix). The memory
 * starts again at each new fewest count of infeasible rows: what follows a
 * set depends on that count too (a new low gives block steps again), so a
 * set tried before the low may lead elsewhere after it, and the lows can
 * only fall n times, so the method still ends.
 *
 * Friction rows: their bounds depend on the normal lambdas. The inner
 * pivoting solves the LCP with the bounds frozen at the current lambda; then
 * the bounds are recomputed from the new normal lambdas. The fixed point is
 * reached when every clamped row's bound is unchanged (to well below the
 * solved threshold) and every free row still lies in its new box (a free
 * row's bounds do not enter the linear solve); otherwise the inner solve is
 * repeated from the current sets (with the same factorisation when the free
 * set does not change). A friction row that was clamped only because its
 * normal impulse was zero (lo = hi = 0) starts that next round free. This
 * fixed-point iteration is the approximate handling the contract describes:
 * it is not guaranteed to converge, but does in practice (friction bounds
 * only grow or shrink with their normal force, which changes little once
 * the contact set is right); the iteration cap bounds it either way. After
 * 10 rounds the bound update is relaxed by half (kea_activeset_core.h),
 * which turns the usual failure, a 2-cycle of the bounds, into convergence.
 *
 * A warm start (last step's lambda, friction rows included) gives the
 * initial bounds (friction boxes from the warm normal impulses) and the
 * initial sets: rows at a finite bound, or within half the solved threshold
 * of it, start clamped there, the rest free. A warm start that is already a
 * solution is confirmed by one linear solve (one factorisation); a good
 * guess usually needs one or two.
 *
 * The pivoting logic lives in kea_activeset_core.h and is shared with the
 * sparse solver (kea_sparse.cpp); this file supplies the dense matrix
 * operations: the residual over the dense rows and a dense LDL^T of the free
 * block (kea_envelope_ldlt.h, with a least-squares fallback when it breaks
 * down), re-used while the free set does not change. */
#include "kea_activeset_core.h"
#include "kea_envelope_ldlt.h"

#include <algorithm>
#include <cmath>

namespace karma::kea {
namespace {

/* The dense matrix operations of the active-set core. The free block is
 * factorised by the envelope LDL^T with full rows (a dense LDL^T), kept
 * while the free set does not change. */
struct DenseBackend {
  const LcpProblem &p;
  MeReal eps;
  std::vector<int> freeRows, factoredRows;
  std::vector<MeReal> rhs, x;
  detail::EnvelopeSystem block;
  int factorizations = 0;

  MeReal residual(std::span<const MeReal> lambda, std::span<MeReal> w) { return KeaResidual(p, eps, lambda, w); }
  /* The factorisation's solve is direct: nothing to refine. */
  bool refine(std::vector<MeReal> &, std::span<const MeReal>) { return false; }

  /* Solves for the free rows with the clamped rows at their (frozen)
   * bounds; writes the whole lambda. */
  void solveFree(const std::vector<unsigned char> &set, const std::vector<MeReal> &lo, const std::vector<MeReal> &hi,
                 std::vector<MeReal> &lambda) {
    const auto n = static_cast<std::size_t>(p.n);
    freeRows.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (set[i] == detail::AtLo)
        lambda[i] = lo[i];
      else if (set[i] == detail::AtHi)
        lambda[i] = hi[i];
      else
        freeRows.push_back(static_cast<int>(i));
    }
    const std::size_t m = freeRows.size();
    if (m == 0) return;
    if (!block.factored || freeRows != factoredRows) factorise();
    rhs.assign(m, MeReal(0));
    for (std::size_t a = 0; a < m; ++a) {
      const auto i = static_cast<std::size_t>(freeRows[a]);
      const MeReal *row = p.A.data() + i * n;
      MeReal r = p.b[i];
      for (std::size_t j = 0; j < n; ++j)
        if (set[j] != detail::Free) r -= row[j] * lambda[j];
      rhs[a] = r;
    }
    x.resize(m);
    block.solve(rhs, x);
    for (std::size_t a = 0; a < m; ++a) lambda[static_cast<std::size_t>(freeRows[a])] = x[a];
  }

  /* See kea_friction_coupling.h. */
  std::span<const int> factorRows() const {
    return block.factored && freeRows == factoredRows ? std::span<const int>(freeRows) : std::span<const int>();
  }
  void solveWithFactor(std::span<const MeReal> in, std::span<MeReal> out) { block.solve(in, out); }
  void column(int row, std::span<const int> position, std::span<MeReal> out) const {
    const auto n = static_cast<std::size_t>(p.n);
    const MeReal *a = p.A.data() + static_cast<std::size_t>(row) * n;
    for (std::size_t c = 0; c < n; ++c)
      if (position[c] >= 0) out[static_cast<std::size_t>(position[c])] = a[c];
  }

  /* The free block (A + eps I)_FF, lower triangle, full rows. */
  void factorise() {
    const auto n = static_cast<std::size_t>(p.n);
    const std::size_t m = freeRows.size();
    block.begin(static_cast<int>(m));
    block.layout();
    for (std::size_t a = 0; a < m; ++a) {
      const MeReal *row = p.A.data() + static_cast<std::size_t>(freeRows[a]) * n;
      for (std::size_t c = 0; c <= a; ++c)
        block.value[block.at(static_cast<int>(a), static_cast<int>(c))] = row[static_cast<std::size_t>(freeRows[c])];
      block.value[block.at(static_cast<int>(a), static_cast<int>(a))] += eps;
    }
    block.factor();
    factoredRows = freeRows;
    ++factorizations;
  }
};

}  // namespace

KeaResult KeaSolveActiveSet(const LcpProblem &p, const KeaOptions &o) {
  static const char *const kName = "KeaSolveActiveSet";
  if (!detail::Validate(p, o, kName)) return detail::BadInputResult(p.n);
  DenseBackend backend{p, o.epsilon, {}, {}, {}, {}, {}, 0};
  detail::ActiveSetScratch scratch;
  KeaResult r;
  detail::ActiveSetCore(detail::Rows(p), o, kName, backend, scratch, r);
  r.factorizations = backend.factorizations;
  return r;
}

}  // namespace karma::kea
