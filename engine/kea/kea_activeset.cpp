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
 * is right); the iteration cap bounds it either way.
 *
 * A warm start (last step's lambda) gives the initial sets: rows at a finite
 * bound start clamped there, the rest free. A good guess usually needs one
 * or two linear solves. */
#include "kea_internal.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace karma::kea {
namespace {

using Mat = Eigen::Matrix<MeReal, Eigen::Dynamic, Eigen::Dynamic>;
using Vec = Eigen::Matrix<MeReal, Eigen::Dynamic, 1>;

enum RowSet : unsigned char { Free = 0, AtLo = 1, AtHi = 2 };

/* Whether `set` is one of the sets in `tried` (a linear scan: single
 * pivoting is the rare fallback and its history is short). */
bool Tried(const std::vector<std::vector<unsigned char>> &tried, const std::vector<unsigned char> &set) {
  for (const auto &t : tried) {
    bool same = true;
    for (std::size_t i = 0; i < set.size() && same; ++i) same = t[i] == set[i];
    if (same) return true;
  }
  return false;
}

/* Keeps the sets consistent with the frozen bounds: a row cannot be clamped
 * at an infinite bound, and a row with lo = hi is clamped at lo. */
void Normalise(std::vector<unsigned char> &set, const std::vector<MeReal> &lo, const std::vector<MeReal> &hi) {
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (lo[i] == hi[i]) set[i] = AtLo;
    else if (set[i] == AtLo && std::isinf(lo[i])) set[i] = Free;
    else if (set[i] == AtHi && std::isinf(hi[i])) set[i] = Free;
  }
}

/* Solves for the free rows with the clamped rows at their (frozen) bounds;
 * writes the whole lambda. */
void SolveFree(const LcpProblem &p, MeReal eps, const std::vector<unsigned char> &set,
               const std::vector<MeReal> &lo, const std::vector<MeReal> &hi, std::vector<MeReal> &lambda) {
  const auto n = static_cast<std::size_t>(p.n);
  std::vector<std::size_t> freeRows;
  for (std::size_t i = 0; i < n; ++i) {
    if (set[i] == AtLo) lambda[i] = lo[i];
    else if (set[i] == AtHi) lambda[i] = hi[i];
    else freeRows.push_back(i);
  }
  const auto m = static_cast<Eigen::Index>(freeRows.size());
  if (m == 0) return;
  Mat block(m, m);
  Vec rhs(m);
  for (Eigen::Index a = 0; a < m; ++a) {
    const std::size_t i = freeRows[static_cast<std::size_t>(a)];
    const MeReal *row = p.A.data() + i * n;
    for (Eigen::Index c = 0; c < m; ++c) block(a, c) = row[freeRows[static_cast<std::size_t>(c)]];
    block(a, a) += eps;
    MeReal r = p.b[i];
    for (std::size_t j = 0; j < n; ++j)
      if (set[j] != Free) r -= row[j] * lambda[j];
    rhs(a) = r;
  }
  Vec x;
  Eigen::LDLT<Mat> ldlt(block);
  if (ldlt.info() == Eigen::Success) x = ldlt.solve(rhs);
  if (x.size() != m || !x.allFinite()) {
    /* Not positive semi-definite, or breakdown: a least-squares solve. */
    x = block.completeOrthogonalDecomposition().solve(rhs);
  }
  for (Eigen::Index a = 0; a < m; ++a) lambda[freeRows[static_cast<std::size_t>(a)]] = x(a);
}

/* The set row i should move to, or its current set when it is feasible
 * (within `slack`). */
unsigned char Wanted(unsigned char set, MeReal lambda, MeReal w, MeReal lo, MeReal hi, MeReal slack) {
  switch (set) {
    case Free:
      if (lambda < lo - slack) return AtLo;
      if (lambda > hi + slack) return AtHi;
      return Free;
    case AtLo:
      return (lo < hi && w < -slack) ? Free : AtLo;
    default:
      return w > slack ? Free : AtHi;
  }
}

}  // namespace

KeaResult KeaSolveActiveSet(const LcpProblem &p, const KeaOptions &o) {
  static const char *const kName = "KeaSolveActiveSet";
  if (!detail::Validate(p, o, kName)) return detail::BadInputResult(p.n);

  const auto n = static_cast<std::size_t>(p.n);
  const MeReal eps = o.epsilon;
  /* Friction's fixed point converges linearly: it gets a larger budget. */
  const int cap = o.maxIterations > 0 ? o.maxIterations : 10 * p.n + 20 + (p.findex.empty() ? 0 : 20 * p.n + 100);
  const MeReal threshold = detail::SolvedThreshold(p, o);
  const MeReal slack = threshold / 2;
  constexpr int kBlockTries = 3; /* Judice-Pires: block steps allowed without progress */

  KeaResult r;
  r.lambda.assign(n, MeReal(0));
  r.w.assign(n, MeReal(0));
  if (n == 0) {
    r.status = KeaStatus::Solved;
    return r;
  }
  if (!o.warmStart.empty()) std::copy(o.warmStart.begin(), o.warmStart.end(), r.lambda.begin());

  std::vector<MeReal> lo, hi;
  detail::ComputeBounds(p, r.lambda, lo, hi);
  std::vector<unsigned char> set(n, Free);
  for (std::size_t i = 0; i < n; ++i) {
    const MeReal l = std::clamp(r.lambda[i], lo[i], hi[i]);
    if (l <= lo[i]) set[i] = AtLo;
    else if (l >= hi[i]) set[i] = AtHi;
  }

  std::vector<MeReal> best = r.lambda;
  MeReal bestResidual = KeaResidual(p, eps, r.lambda);
  int solves = 0;
  bool cycle = false, done = false;
  std::vector<MeReal> newLo, newHi;

  while (!done && !cycle && solves < cap) {
    /* Inner pivoting with the bounds frozen at lo/hi. */
    Normalise(set, lo, hi);
    std::vector<std::vector<unsigned char>> tried;
    std::size_t fewestInfeasible = n + 1;
    int blockTries = kBlockTries;
    bool consistent = false;
    while (solves < cap) {
      SolveFree(p, eps, set, lo, hi, r.lambda);
      ++solves;
      const MeReal residual = KeaResidual(p, eps, r.lambda, r.w);
      if (residual < bestResidual) {
        bestResidual = residual;
        best = r.lambda;
      }
      std::size_t infeasible = 0, last = n;
      for (std::size_t i = 0; i < n; ++i)
        if (Wanted(set[i], r.lambda[i], r.w[i], lo[i], hi[i], slack) != set[i]) {
          ++infeasible;
          last = i;
        }
      if (infeasible == 0) {
        consistent = true;
        break;
      }
      if (infeasible < fewestInfeasible || blockTries > 0) {
        if (infeasible < fewestInfeasible) {
          fewestInfeasible = infeasible;
          blockTries = kBlockTries;
        } else {
          --blockTries;
        }
        for (std::size_t i = 0; i < n; ++i) set[i] = Wanted(set[i], r.lambda[i], r.w[i], lo[i], hi[i], slack);
      } else {
        tried.push_back(set);
        set[last] = Wanted(set[last], r.lambda[last], r.w[last], lo[last], hi[last], slack);
        if (Tried(tried, set)) {
          cycle = true;
          break;
        }
      }
    }
    if (!consistent) break;

    /* Friction: refresh the bounds from the new normal lambdas. */
    if (p.findex.empty()) {
      done = true;
      break;
    }
    detail::ComputeBounds(p, r.lambda, newLo, newHi);
    /* The fixed point is iterated well below the solved threshold, so that
     * friction rows end (nearly) exactly on their final bounds; the floor
     * keeps rounding from looping to the cap. */
    MeReal lambdaMax = 0;
    for (MeReal l : r.lambda) lambdaMax = std::max(lambdaMax, std::fabs(l));
    const MeReal settle = std::max(slack / 100, 64 * ME_REAL_EPSILON * (1 + lambdaMax));
    bool moved = false;
    for (std::size_t i = 0; i < n; ++i)
      if (std::fabs(newLo[i] - lo[i]) > settle || std::fabs(newHi[i] - hi[i]) > settle) moved = true;
    lo.swap(newLo);
    hi.swap(newHi);
    if (!moved) done = true;
  }

  r.lambda = best;
  r.residual = KeaResidual(p, eps, r.lambda, r.w);
  r.iterations = solves;
  if (r.residual <= threshold) {
    r.status = KeaStatus::Solved;
  } else if (cycle) {
    r.status = KeaStatus::CycleDetected;
    detail::WarnCycle(o, kName, solves, r.residual);
  } else {
    r.status = KeaStatus::IterationLimit;
    detail::WarnIterationLimit(o, kName, solves, r.residual);
  }
  return r;
}

}  // namespace karma::kea
