/* kea_activeset_core.h: the active-set method's logic, shared by the dense
 * (kea_activeset.cpp) and the sparse (kea_sparse.cpp) solvers (not
 * installed).
 *
 * The method itself (block principal pivoting, Murty's single-pivot
 * fallback, cycle detection, the friction fixed point, warm start, the
 * iteration cap) is described in kea_activeset.cpp. It only needs two things
 * from the matrix, supplied by a `Backend`:
 *
 *   MeReal residual(std::span<const MeReal> lambda, std::span<MeReal> w);
 *       writes w = (A + eps I) lambda - b (when w is not empty) and returns
 *       the contract's residual of lambda;
 *   void solveFree(const std::vector<unsigned char> &set,
 *                  const std::vector<MeReal> &lo, const std::vector<MeReal> &hi,
 *                  std::vector<MeReal> &lambda);
 *       sets the clamped rows to their bounds and solves the free block
 *       (A + eps I)_FF lambda_F = b_F - A_FC lambda_C.
 *
 * Everything else is per row and costs O(n) per pivot step. */
#ifndef KARMA_KEA_ACTIVESET_CORE_H
#define KARMA_KEA_ACTIVESET_CORE_H

#include "kea_internal.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace karma::kea::detail {

enum RowSet : unsigned char { Free = 0, AtLo = 1, AtHi = 2 };

/* Whether `set` is one of the sets in `tried` (a linear scan: single
 * pivoting is the rare fallback and its history is short). */
inline bool Tried(const std::vector<std::vector<unsigned char>> &tried, const std::vector<unsigned char> &set) {
  for (const auto &t : tried)
    if (t == set) return true;
  return false;
}

/* Keeps the sets consistent with the frozen bounds: a row cannot be clamped
 * at an infinite bound, and a row with lo = hi is clamped at lo. */
inline void Normalise(std::vector<unsigned char> &set, const std::vector<MeReal> &lo,
                      const std::vector<MeReal> &hi) {
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (lo[i] == hi[i]) set[i] = AtLo;
    else if (set[i] == AtLo && std::isinf(lo[i])) set[i] = Free;
    else if (set[i] == AtHi && std::isinf(hi[i])) set[i] = Free;
  }
}

/* The set row i should move to, or its current set when it is feasible
 * (within `slack`). */
inline unsigned char Wanted(unsigned char set, MeReal lambda, MeReal w, MeReal lo, MeReal hi, MeReal slack) {
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

/* The active-set method on a validated problem (rows) through `backend`;
 * `name` names the entry point in warnings. */
template <class Backend>
KeaResult ActiveSetCore(const RowView &p, const KeaOptions &o, const char *name, Backend &backend) {
  const auto n = static_cast<std::size_t>(p.n);
  /* Friction's fixed point converges linearly: it gets a larger budget. */
  const int cap = o.maxIterations > 0 ? o.maxIterations : 10 * p.n + 20 + (p.findex.empty() ? 0 : 20 * p.n + 100);
  const MeReal threshold = SolvedThreshold(p, o);
  const MeReal slack = threshold / 2;
  /* Friction fixed-point rounds taken with the plain update lo, hi <- F(lambda);
   * later rounds are relaxed (see below). */
  constexpr int kPlainOuter = 10;
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
  ComputeBounds(p, r.lambda, lo, hi);
  std::vector<unsigned char> set(n, Free);
  for (std::size_t i = 0; i < n; ++i) {
    const MeReal l = std::clamp(r.lambda[i], lo[i], hi[i]);
    if (l <= lo[i]) set[i] = AtLo;
    else if (l >= hi[i]) set[i] = AtHi;
  }

  std::vector<MeReal> best = r.lambda;
  MeReal bestResidual = backend.residual(r.lambda, {});
  /* Whether best and bestResidual are r.lambda and its residual, with r.w
   * its w: then the final residual need not be computed again. */
  bool bestIsCurrent = false;
  int solves = 0;
  bool cycle = false, done = false;
  std::vector<MeReal> newLo, newHi;

  int outer = 0;
  while (!done && !cycle && solves < cap) {
    ++outer;
    /* Inner pivoting with the bounds frozen at lo/hi. */
    Normalise(set, lo, hi);
    std::vector<std::vector<unsigned char>> tried;
    std::size_t fewestInfeasible = n + 1;
    int blockTries = kBlockTries;
    bool consistent = false;
    while (solves < cap) {
      backend.solveFree(set, lo, hi, r.lambda);
      ++solves;
      const MeReal residual = backend.residual(r.lambda, r.w);
      bestIsCurrent = residual < bestResidual;
      if (bestIsCurrent) {
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
    ComputeBounds(p, r.lambda, newLo, newHi);
    /* The fixed point is iterated well below the solved threshold, so that
     * friction rows end (nearly) exactly on their final bounds; the floor
     * keeps rounding from looping to the cap. */
    MeReal lambdaMax = 0;
    for (MeReal l : r.lambda) lambdaMax = std::max(lambdaMax, std::fabs(l));
    const MeReal settle = std::max(slack / 100, 64 * ME_REAL_EPSILON * (1 + lambdaMax));
    bool moved = false;
    for (std::size_t i = 0; i < n; ++i)
      if (std::fabs(newLo[i] - lo[i]) > settle || std::fabs(newHi[i] - hi[i]) > settle) moved = true;
    /* A fixed point not reached after kPlainOuter rounds is usually a
     * 2-cycle (the bounds flip between two values and the solver runs to
     * its cap: 40000 solves seen in pile1000). From then on the update is
     * relaxed by half: lo <- lo + (F(lambda)_lo - lo) / 2 (same for hi),
     * which damps the flip. The stopping test above is unchanged (F(lambda)
     * against the bounds used), so a fixed point is still one. */
    if (outer > kPlainOuter) {
      for (std::size_t i = 0; i < n; ++i) {
        newLo[i] = lo[i] + (newLo[i] - lo[i]) / 2;
        newHi[i] = hi[i] + (newHi[i] - hi[i]) / 2;
      }
    }
    lo.swap(newLo);
    hi.swap(newHi);
    if (!moved) done = true;
  }

  if (bestIsCurrent) {
    r.residual = bestResidual;
  } else {
    r.lambda = best;
    r.residual = backend.residual(r.lambda, r.w);
  }
  r.iterations = solves;
  if (r.residual <= threshold) {
    r.status = KeaStatus::Solved;
  } else if (cycle) {
    r.status = KeaStatus::CycleDetected;
    WarnCycle(o, name, solves, r.residual);
  } else {
    r.status = KeaStatus::IterationLimit;
    WarnIterationLimit(o, name, solves, r.residual);
  }
  return r;
}

}  // namespace karma::kea::detail

#endif
