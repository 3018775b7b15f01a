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
 *       (A + eps I)_FF lambda_F = b_F - A_FC lambda_C (a backend keeps the
 *       factorisation of the last free set and only re-solves when the set
 *       is unchanged, as in the friction fixed point).
 *
 * Everything else is per row and costs O(n) per pivot step. */
#ifndef KARMA_KEA_ACTIVESET_CORE_H
#define KARMA_KEA_ACTIVESET_CORE_H

#include "kea_friction_coupling.h"
#include "kea_internal.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace karma::kea::detail {

enum RowSet : unsigned char { Free = 0, AtLo = 1, AtHi = 2 };

/* The arrays of one active-set solve, kept from one solve to the next (in
 * a KeaWorkspace) so that a solve no larger than an earlier one allocates
 * nothing. */
struct ActiveSetScratch {
  std::vector<MeReal> lo, hi, newLo, newHi, best, start, saved;
  std::vector<unsigned char> set;
  /* The sets tried during single pivoting, n bytes each, back to back. */
  std::vector<unsigned char> tried;
  CouplingScratch coupling;
};

/* Whether `set` is one of the sets in `tried` (a linear scan: single
 * pivoting is the rare fallback and its history is short). */
inline bool Tried(const std::vector<unsigned char> &tried, const std::vector<unsigned char> &set) {
  const std::size_t n = set.size();
  for (std::size_t at = 0; n > 0 && at + n <= tried.size(); at += n)
    if (std::equal(set.begin(), set.end(), tried.begin() + static_cast<std::ptrdiff_t>(at))) return true;
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

/* Whether the friction bounds newLo/newHi, computed from the current
 * lambda, agree with the solve made under lo/hi: every clamped row's bound
 * moved by at most `settle` (its value is the bound it was clamped at) and
 * every free row still lies inside its new box (within `slack`; a free
 * row's bounds do not enter the linear solve, only its feasibility). Then
 * lambda satisfies complementarity under the bounds of its own normal
 * impulses, and the fixed point is reached without another solve. */
inline bool FrictionBoundsAgree(const std::vector<unsigned char> &set, std::span<const MeReal> lambda,
                                const ActiveSetScratch &s, MeReal settle, MeReal slack) {
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (set[i] == Free) {
      if (lambda[i] < s.newLo[i] - slack || lambda[i] > s.newHi[i] + slack) return false;
    } else if (std::fabs(s.newLo[i] - s.lo[i]) > settle || std::fabs(s.newHi[i] - s.hi[i]) > settle) {
      return false;
    }
  }
  return true;
}

/* The initial sets from the initial lambda (a warm start or zeros): a row
 * at or beyond a finite bound, or within `slack` of it, starts clamped
 * there, the rest free. The slack matters for friction rows warm-started
 * from a solution: they sit on +-mu lambda_j of the normal impulse of the
 * solve before the last, which the bound from the final lambda_j misses by
 * up to the fixed point's settling tolerance. */
inline void InitialSets(std::span<const MeReal> lambda, MeReal slack, ActiveSetScratch &s) {
  const std::size_t n = lambda.size();
  s.set.assign(n, Free);
  for (std::size_t i = 0; i < n; ++i) {
    if (lambda[i] <= s.lo[i] + slack) s.set[i] = AtLo;
    else if (lambda[i] >= s.hi[i] - slack) s.set[i] = AtHi;
  }
}

/* The active-set method on a validated problem (rows) through `backend`,
 * with its arrays in `s`; the answer goes to `r`, whose vectors are reused.
 * `name` names the entry point in warnings. */
template <class Backend>
void ActiveSetCore(const RowView &p, const KeaOptions &o, const char *name, Backend &backend, ActiveSetScratch &s,
                   KeaResult &r) {
  const auto n = static_cast<std::size_t>(p.n);
  /* Friction's fixed point converges linearly: it gets a larger budget. */
  const int cap = o.maxIterations > 0 ? o.maxIterations : 10 * p.n + 20 + (p.findex.empty() ? 0 : 20 * p.n + 100);
  const MeReal threshold = SolvedThreshold(p, o);
  const MeReal slack = threshold / 2;
  /* Friction fixed-point rounds taken with the plain update lo, hi <- F(lambda);
   * later rounds are relaxed (see below). */
  constexpr int kPlainOuter = 10;
  constexpr int kBlockTries = 3; /* Judice-Pires: block steps allowed without progress */
  constexpr int kCouplingTries = 3;

  r.lambda.assign(n, MeReal(0));
  r.w.assign(n, MeReal(0));
  r.iterations = 0;
  r.frictionRounds = 0;
  r.residual = 0;
  if (n == 0) {
    r.status = KeaStatus::Solved;
    return;
  }
  if (!o.warmStart.empty()) std::copy(o.warmStart.begin(), o.warmStart.end(), r.lambda.begin());

  ComputeBounds(p, r.lambda, s.lo, s.hi);
  InitialSets(r.lambda, slack, s);
  s.newLo.resize(n);
  s.newHi.resize(n);
  /* Room for a few single-pivot sets; a longer history grows the array. */
  s.tried.reserve(4 * n);
  if (!p.findex.empty()) {
    s.saved.reserve(n);
    ReserveCoupling(n, s.coupling);
  }
  std::vector<unsigned char> &set = s.set;

  /* The best iterate so far. The starting point counts too, but its
   * residual (a product with A) is only needed when no iterate reaches the
   * solved threshold, so it is scored at the end, if at all. */
  s.start = r.lambda;
  s.best = r.lambda;
  MeReal bestResidual = kInf;
  /* Whether best and bestResidual are r.lambda and its residual, with r.w
   * its w: then the final residual need not be computed again. */
  bool bestIsCurrent = false;
  int solves = 0;
  bool cycle = false, done = false;
  /* Coupled friction steps that may still fail (see below). */
  int couplingTries = kCouplingTries;

  int outer = 0;
  while (!done && !cycle && solves < cap) {
    ++outer;
    /* Inner pivoting with the bounds frozen at lo/hi. */
    Normalise(set, s.lo, s.hi);
    s.tried.clear();
    std::size_t fewestInfeasible = n + 1;
    int blockTries = kBlockTries;
    bool consistent = false;
    while (solves < cap) {
      backend.solveFree(set, s.lo, s.hi, r.lambda);
      ++solves;
      const MeReal residual = backend.residual(r.lambda, r.w);
      bestIsCurrent = residual < bestResidual;
      if (bestIsCurrent) {
        bestResidual = residual;
        s.best = r.lambda;
      }
      std::size_t infeasible = 0, last = n;
      for (std::size_t i = 0; i < n; ++i)
        if (Wanted(set[i], r.lambda[i], r.w[i], s.lo[i], s.hi[i], slack) != set[i]) {
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
        for (std::size_t i = 0; i < n; ++i) set[i] = Wanted(set[i], r.lambda[i], r.w[i], s.lo[i], s.hi[i], slack);
      } else {
        s.tried.insert(s.tried.end(), set.begin(), set.end());
        set[last] = Wanted(set[last], r.lambda[last], r.w[last], s.lo[last], s.hi[last], slack);
        if (Tried(s.tried, set)) {
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
    ComputeBounds(p, r.lambda, s.newLo, s.newHi);
    /* Clamped friction rows are iterated well below the solved threshold,
     * so that they end (nearly) exactly on their final bounds; the floor
     * keeps rounding from looping to the cap. */
    MeReal lambdaMax = 0;
    for (MeReal l : r.lambda) lambdaMax = std::max(lambdaMax, std::fabs(l));
    const MeReal settle = std::max(slack / 100, 64 * ME_REAL_EPSILON * (1 + lambdaMax));
    if (FrictionBoundsAgree(set, r.lambda, s, settle, slack)) {
      done = true;
      break;
    }
    ++r.frictionRounds;
    /* The tied rows' exact step (kea_friction_coupling.h), unless a row's
     * box has just opened (its set is guessed again below). It is kept
     * only when the sets stay consistent under the bounds of the coupled
     * lambda (the fixed point is then reached); otherwise lambda goes back
     * and the plain update below is taken (the set is not the final one,
     * and the plain rounds approach the boundary the coupled step jumped
     * over; keeping the jump can cycle). After kCouplingTries such
     * failures the solve continues with plain rounds only. */
    bool opened = false;
    for (std::size_t i = 0; i < n; ++i)
      opened = opened || (set[i] != Free && s.lo[i] == s.hi[i] && s.newLo[i] < s.newHi[i]);
    if (couplingTries > 0 && !opened && solves < cap) {
      s.saved = r.lambda;
      if (CoupleFriction(p, set, backend, s.coupling, r.lambda)) {
        ++solves;
        ComputeBounds(p, r.lambda, s.newLo, s.newHi);
        for (std::size_t i = 0; i < n; ++i) {
          if (set[i] == AtLo) r.lambda[i] = s.newLo[i];
          else if (set[i] == AtHi) r.lambda[i] = s.newHi[i];
        }
        const MeReal residual = backend.residual(r.lambda, r.w);
        bestIsCurrent = residual < bestResidual;
        if (bestIsCurrent) {
          bestResidual = residual;
          s.best = r.lambda;
        }
        bool agree = true;
        for (std::size_t i = 0; i < n && agree; ++i)
          agree = Wanted(set[i], r.lambda[i], r.w[i], s.newLo[i], s.newHi[i], slack) == set[i];
        if (agree) {
          done = true;
          break;
        }
        r.lambda.swap(s.saved);
        bestIsCurrent = false;
        --couplingTries;
        ComputeBounds(p, r.lambda, s.newLo, s.newHi);
      } else {
        r.lambda.swap(s.saved); /* a step that did not apply may have moved some rows */
      }
    }
    /* A fixed point not reached after kPlainOuter rounds is usually a
     * 2-cycle (the bounds flip between two values and the solver runs to
     * its cap: 40000 solves seen in pile1000). From then on the update is
     * relaxed by half: lo <- lo + (F(lambda)_lo - lo) / 2 (same for hi),
     * which damps the flip. The stopping test above is unchanged (F(lambda)
     * against the bounds used), so a fixed point is still one. */
    if (outer > kPlainOuter) {
      for (std::size_t i = 0; i < n; ++i) {
        s.newLo[i] = s.lo[i] + (s.newLo[i] - s.lo[i]) / 2;
        s.newHi[i] = s.hi[i] + (s.newHi[i] - s.hi[i]) / 2;
      }
    }
    /* A friction row clamped only because its normal impulse was zero (lo =
     * hi = 0) says nothing about the row: now that its box has opened, it
     * starts the next round free (a resting contact's friction usually
     * is). */
    for (std::size_t i = 0; i < n; ++i)
      if (set[i] != Free && s.lo[i] == s.hi[i] && s.newLo[i] < s.newHi[i]) set[i] = Free;
    s.lo.swap(s.newLo);
    s.hi.swap(s.newHi);
  }

  if (bestResidual > threshold) {
    const MeReal startResidual = backend.residual(s.start, {});
    if (startResidual < bestResidual) {
      bestResidual = startResidual;
      s.best = s.start;
      bestIsCurrent = false;
    }
  }
  if (bestIsCurrent) {
    r.residual = bestResidual;
  } else {
    r.lambda = s.best;
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
}

}  // namespace karma::kea::detail

#endif
