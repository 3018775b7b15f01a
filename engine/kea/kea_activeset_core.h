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
 *       the contract's residual of lambda; w may carry the rounding of an
 *       iterative solve's recursion, far below the solved threshold
 *       (SparseBackend::acceptRecursive);
 *   void solveFree(const std::vector<unsigned char> &set,
 *                  const std::vector<MeReal> &lo, const std::vector<MeReal> &hi,
 *                  std::vector<MeReal> &lambda);
 *       sets the clamped rows to their bounds and solves the free block
 *       (A + eps I)_FF lambda_F = b_F - A_FC lambda_C (a backend keeps the
 *       factorisation of the last free set and only re-solves when the set
 *       is unchanged, as in the friction fixed point);
 *   bool refine(std::vector<MeReal> &lambda, std::span<const MeReal> w);
 *       called after each solveFree with w = (A + eps I) lambda - b of its
 *       answer, and again after each call that returned true: a backend
 *       whose solve may have missed its accuracy (a Schur-complement
 *       update, kea_schur_update.h) corrects the free rows of lambda from w
 *       and returns true (w is then out of date); false leaves lambda as it
 *       is. It returns true a bounded number of times per solveFree (and
 *       per coupled friction step, kea_friction_coupling.h).
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

/* KeaOptions::acceptWarmStart keeps a warm start whose residual is at most
 * the solved threshold divided by KeaOptions::warmAcceptDivisor; this is
 * its default, by name. Not the threshold itself: when every call may keep its
 * warm start, at rest the kept impulses err by up to the threshold step
 * after step (each kept warm start is the last one, checked against a
 * slightly changed problem), and in single precision that error turns a
 * resting box by more than the auto-disable thresholds allow: a heap of
 * 200 boxes never slept (at a divisor of 1 and of 4), a box on four
 * contacts sank 1 mm in 2 s, and a joint's reported torque was 0.4 % off.
 * At a sixteenth none of that happens (the tests that measure them pass),
 * while most resting steps of topple and of the car still keep their warm
 * start (docs/NOTES.md, "Warm starts that are already answers"). */
inline constexpr MeReal kWarmAcceptDivisor = KeaOptions{}.warmAcceptDivisor;

/* The warm-start check (KeaOptions::acceptWarmStart) costs one product with
 * A and saves, when it accepts, at least a triangular solve and the product
 * that checks it (a factorisation, when the solve would have made one). A
 * workspace checks while the running mean of its checks' outcomes (1:
 * accepted) is at least kWarmCheckFloor; the mean starts at
 * kWarmAcceptedPrior, moves by kWarmLearningRate toward each outcome, and
 * each check skipped moves it back toward the prior by kWarmRecoveryRate,
 * so that a workspace whose checks failed tries again now and then (a rag
 * doll whose limbs keep turning: about one check in sixteen solves). */
inline constexpr MeReal kWarmAcceptedPrior = MeReal(0.5);
inline constexpr MeReal kWarmCheckFloor = MeReal(0.25);
inline constexpr MeReal kWarmLearningRate = MeReal(0.25);
inline constexpr MeReal kWarmRecoveryRate = MeReal(1) / 64;

/* The arrays of one active-set solve, kept from one solve to the next (in
 * a KeaWorkspace) so that a solve no larger than an earlier one allocates
 * nothing, and what the warm-start checks have taught. */
struct ActiveSetScratch {
  std::vector<MeReal> lo, hi, newLo, newHi, best, start, saved;
  std::vector<unsigned char> set;
  /* The sets tried during single pivoting, n bytes each, back to back. */
  std::vector<unsigned char> tried;
  CouplingScratch coupling;
  MeReal warmAccepted = kWarmAcceptedPrior; /* running mean, see kWarmCheckFloor */
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
inline void Normalise(std::vector<unsigned char> &set, const std::vector<MeReal> &lo, const std::vector<MeReal> &hi) {
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (lo[i] == hi[i])
      set[i] = AtLo;
    else if (set[i] == AtLo && std::isinf(lo[i]))
      set[i] = Free;
    else if (set[i] == AtHi && std::isinf(hi[i]))
      set[i] = Free;
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

/* Room in s for a problem of n rows (ReserveRoom, kea_internal.h), with the
 * friction coupling's arrays when the problem has friction. */
inline void ReserveActiveSet(std::size_t n, bool friction, ActiveSetScratch &s) {
  for (std::vector<MeReal> *v : {&s.lo, &s.hi, &s.newLo, &s.newHi, &s.best, &s.start}) ReserveRoom(*v, n);
  ReserveRoom(s.set, n);
  /* Room for a few single-pivot sets; a longer history grows the array. */
  ReserveRoom(s.tried, 4 * n);
  if (friction) {
    ReserveRoom(s.saved, n);
    ReserveCoupling(Room(n), s.coupling);
  }
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
    if (lambda[i] <= s.lo[i] + slack)
      s.set[i] = AtLo;
    else if (lambda[i] >= s.hi[i] - slack)
      s.set[i] = AtHi;
  }
}

/* One run of the active-set method on a validated problem (rows) through
 * `backend`, with its arrays in `s`; the answer goes to `r`, whose vectors
 * are reused. `name` names the entry point in warnings. */
template <class Backend>
class ActiveSetRun {
 public:
  ActiveSetRun(const RowView &p, const KeaOptions &o, const char *name, Backend &backend, ActiveSetScratch &s,
               KeaResult &r)
      : p_(p),
        o_(o),
        name_(name),
        backend_(backend),
        s_(s),
        r_(r),
        n_(static_cast<std::size_t>(p.n)),
        /* Friction's fixed point converges linearly: it gets a larger budget. */
        cap_(o.maxIterations > 0 ? o.maxIterations : 10 * p.n + 20 + (p.findex.empty() ? 0 : 20 * p.n + 100)),
        threshold_(SolvedThreshold(p, o)),
        slack_(threshold_ / 2) {}

  void run() {
    if (!start()) return;
    if (acceptedWarmStart()) {
      finish();
      return;
    }
    bool done = false;
    int outer = 0;
    while (!done && !cycle_ && solves_ < cap_) {
      ++outer;
      if (!pivotToConsistency()) break;
      done = frictionRound(outer);
    }
    finish();
  }

 private:
  /* Friction fixed-point rounds taken with the plain update lo, hi <- F(lambda);
   * later rounds are relaxed (see frictionRound). */
  static constexpr int kPlainOuter = 10;
  static constexpr int kBlockTries = 3; /* Judice-Pires: block steps allowed without progress */
  static constexpr int kCouplingTries = 3;

  /* The initial lambda, bounds and sets; false when there is nothing to
   * solve (n = 0). */
  bool start() {
    InitialLambda(o_, n_, r_.lambda);
    r_.w.assign(n_, MeReal(0));
    r_.iterations = 0;
    r_.warmStartAccepted = false;
    r_.frictionRounds = 0;
    r_.residual = 0;
    r_.threshold = threshold_;
    if (n_ == 0) {
      r_.status = KeaStatus::Solved;
      return false;
    }
    ReserveActiveSet(n_, !p_.findex.empty(), s_);
    ComputeBounds(p_, r_.lambda, s_.lo, s_.hi);
    InitialSets(r_.lambda, slack_, s_);
    s_.newLo.resize(n_);
    s_.newHi.resize(n_);
    /* The starting point counts as an iterate too, but its residual (a
     * product with A) is only needed when no iterate reaches the solved
     * threshold, so it is scored at the end, if at all, unless the
     * warm-start check has scored it already (startScored_). */
    s_.start = r_.lambda;
    s_.best = r_.lambda;
    return true;
  }

  /* KeaOptions::acceptWarmStart: whether the warm start meets the solved
   * threshold over o_.warmAcceptDivisor as it is (then it is the answer, with
   * no solve). Scored when the workspace expects the check to pay
   * (kWarmCheckFloor); a check that fails leaves the warm start scored as
   * the best iterate so far, which finish() need not score again. */
  bool acceptedWarmStart() {
    if (!o_.acceptWarmStart || o_.warmStart.empty()) return false;
    MeReal &mean = s_.warmAccepted;
    if (mean < kWarmCheckFloor) {
      mean += kWarmRecoveryRate * (kWarmAcceptedPrior - mean);
      return false;
    }
    score();
    startScored_ = true;
    r_.warmStartAccepted = bestResidual_ <= threshold_ / o_.warmAcceptDivisor;
    mean += kWarmLearningRate * ((r_.warmStartAccepted ? MeReal(1) : MeReal(0)) - mean);
    return r_.warmStartAccepted;
  }

  /* w and the residual of the current lambda; keeps the best iterate. */
  void score() {
    const MeReal residual = backend_.residual(r_.lambda, r_.w);
    bestIsCurrent_ = residual < bestResidual_;
    if (bestIsCurrent_) {
      bestResidual_ = residual;
      s_.best = r_.lambda;
    }
  }

  /* Inner pivoting with the bounds frozen at lo/hi, until the sets are
   * consistent (true) or a cycle or the cap stops it (false). */
  bool pivotToConsistency() {
    std::vector<unsigned char> &set = s_.set;
    Normalise(set, s_.lo, s_.hi);
    s_.tried.clear();
    std::size_t fewestInfeasible = n_ + 1;
    int blockTries = kBlockTries;
    while (solves_ < cap_) {
      backend_.solveFree(set, s_.lo, s_.hi, r_.lambda);
      ++solves_;
      score();
      while (backend_.refine(r_.lambda, r_.w)) score();
      std::size_t infeasible = 0, last = n_;
      for (std::size_t i = 0; i < n_; ++i)
        if (wanted(i, s_.lo, s_.hi) != set[i]) {
          ++infeasible;
          last = i;
        }
      if (infeasible == 0) return true;
      if (infeasible < fewestInfeasible || blockTries > 0) {
        if (infeasible < fewestInfeasible) {
          fewestInfeasible = infeasible;
          blockTries = kBlockTries;
          s_.tried.clear(); /* a new low: the sets tried before it may lead elsewhere now */
        } else {
          --blockTries;
        }
        for (std::size_t i = 0; i < n_; ++i) set[i] = wanted(i, s_.lo, s_.hi);
      } else {
        s_.tried.insert(s_.tried.end(), set.begin(), set.end());
        set[last] = wanted(last, s_.lo, s_.hi);
        if (Tried(s_.tried, set)) {
          cycle_ = true;
          return false;
        }
      }
    }
    return false;
  }

  unsigned char wanted(std::size_t i, const std::vector<MeReal> &lo, const std::vector<MeReal> &hi) const {
    return Wanted(s_.set[i], r_.lambda[i], r_.w[i], lo[i], hi[i], slack_);
  }

  /* After a consistent inner solve: true when the friction bounds agree
   * with it (the solve is done), else the bounds for the next round. */
  bool frictionRound(int outer) {
    if (p_.findex.empty()) return true;
    ComputeBounds(p_, r_.lambda, s_.newLo, s_.newHi);
    /* Clamped friction rows are iterated well below the solved threshold,
     * so that they end (nearly) exactly on their final bounds; the floor
     * keeps rounding from looping to the cap. */
    MeReal lambdaMax = 0;
    for (MeReal l : r_.lambda) lambdaMax = std::max(lambdaMax, std::fabs(l));
    const MeReal settle = std::max(slack_ / 100, 64 * ME_REAL_EPSILON * (1 + lambdaMax));
    if (FrictionBoundsAgree(s_.set, r_.lambda, s_, settle, slack_)) return true;
    ++r_.frictionRounds;
    if (coupledStep()) return true;
    plainUpdate(outer);
    return false;
  }

  /* The tied rows' exact step (kea_friction_coupling.h), unless a row's
   * box has just opened (its set is guessed again in plainUpdate). It is
   * kept only when the sets stay consistent under the bounds of the coupled
   * lambda (the fixed point is then reached: true); otherwise lambda goes
   * back and the plain update follows (the set is not the final one, and
   * the plain rounds approach the boundary the coupled step jumped over;
   * keeping the jump can cycle). After kCouplingTries such failures the
   * solve continues with plain rounds only. */
  bool coupledStep() {
    const std::vector<unsigned char> &set = s_.set;
    bool opened = false;
    for (std::size_t i = 0; i < n_; ++i)
      opened = opened || (set[i] != Free && s_.lo[i] == s_.hi[i] && s_.newLo[i] < s_.newHi[i]);
    if (couplingTries_ <= 0 || opened || solves_ >= cap_) return false;
    s_.saved = r_.lambda;
    if (!CoupleFriction(p_, set, backend_, s_.coupling, r_.lambda)) {
      r_.lambda.swap(s_.saved); /* a step that did not apply may have moved some rows */
      return false;
    }
    ++solves_;
    ComputeBounds(p_, r_.lambda, s_.newLo, s_.newHi);
    for (std::size_t i = 0; i < n_; ++i) {
      if (set[i] == AtLo)
        r_.lambda[i] = s_.newLo[i];
      else if (set[i] == AtHi)
        r_.lambda[i] = s_.newHi[i];
    }
    score();
    while (backend_.refine(r_.lambda, r_.w)) score();
    bool agree = true;
    for (std::size_t i = 0; i < n_ && agree; ++i) agree = wanted(i, s_.newLo, s_.newHi) == set[i];
    if (agree) return true;
    r_.lambda.swap(s_.saved);
    bestIsCurrent_ = false;
    --couplingTries_;
    ComputeBounds(p_, r_.lambda, s_.newLo, s_.newHi);
    return false;
  }

  /* The plain fixed-point update lo, hi <- F(lambda) = newLo, newHi.
   *
   * A fixed point not reached after kPlainOuter rounds is usually a
   * 2-cycle (the bounds flip between two values and the solver runs to its
   * cap: 40000 solves seen in pile1000). From then on the update is relaxed
   * by half: lo <- lo + (F(lambda)_lo - lo) / 2 (same for hi), which damps
   * the flip. The stopping test is unchanged (F(lambda) against the bounds
   * used), so a fixed point is still one. Infinite bounds (rows without
   * friction, whose bounds never move) are kept: inf + (inf - inf) / 2
   * would be NaN, and a normal row whose upper bound is NaN can never leave
   * its lower bound (lo < hi is false).
   *
   * A friction row clamped only because its normal impulse was zero (lo =
   * hi = 0) says nothing about the row: now that its box has opened, it
   * starts the next round free (a resting contact's friction usually is). */
  void plainUpdate(int outer) {
    if (outer > kPlainOuter) {
      for (std::size_t i = 0; i < n_; ++i) {
        if (std::isfinite(s_.lo[i])) s_.newLo[i] = s_.lo[i] + (s_.newLo[i] - s_.lo[i]) / 2;
        if (std::isfinite(s_.hi[i])) s_.newHi[i] = s_.hi[i] + (s_.newHi[i] - s_.hi[i]) / 2;
      }
    }
    for (std::size_t i = 0; i < n_; ++i)
      if (s_.set[i] != Free && s_.lo[i] == s_.hi[i] && s_.newLo[i] < s_.newHi[i]) s_.set[i] = Free;
    s_.lo.swap(s_.newLo);
    s_.hi.swap(s_.newHi);
  }

  /* The starting point becomes the best iterate when no iterate reached
   * the solved threshold and its residual is smaller than theirs. A start
   * already scored is already in bestResidual_ (score() keeps the least),
   * so scoring it again could not change the best: it is skipped. */
  void considerStart() {
    if (startScored_ || bestResidual_ <= threshold_) return;
    const MeReal startResidual = backend_.residual(s_.start, {});
    if (startResidual < bestResidual_) {
      bestResidual_ = startResidual;
      s_.best = s_.start;
      bestIsCurrent_ = false;
    }
  }

  /* The best iterate (the starting point included), its w and residual,
   * the status and its warning. */
  void finish() {
    considerStart();
    if (bestIsCurrent_) {
      r_.residual = bestResidual_;
    } else {
      r_.lambda = s_.best;
      r_.residual = backend_.residual(r_.lambda, r_.w);
    }
    r_.iterations = solves_;
    if (r_.residual <= threshold_) {
      r_.status = KeaStatus::Solved;
    } else if (cycle_) {
      r_.status = KeaStatus::CycleDetected;
      WarnCycle(o_, name_, solves_, r_.residual);
    } else {
      r_.status = KeaStatus::IterationLimit;
      WarnIterationLimit(o_, name_, solves_, r_.residual);
    }
  }

  const RowView &p_;
  const KeaOptions &o_;
  const char *name_;
  Backend &backend_;
  ActiveSetScratch &s_;
  KeaResult &r_;
  const std::size_t n_;
  const int cap_;
  const MeReal threshold_, slack_;
  int solves_ = 0;
  bool cycle_ = false;
  MeReal bestResidual_ = kInf;
  /* Whether best and bestResidual_ are r.lambda and its residual, with r.w
   * its w: then the final residual need not be computed again. */
  bool bestIsCurrent_ = false;
  /* Whether the starting point has been scored (by acceptedWarmStart). */
  bool startScored_ = false;
  /* Coupled friction steps that may still fail (see coupledStep). */
  int couplingTries_ = kCouplingTries;
};

/* The active-set method (see ActiveSetRun). */
template <class Backend>
void ActiveSetCore(const RowView &p, const KeaOptions &o, const char *name, Backend &backend, ActiveSetScratch &s,
                   KeaResult &r) {
  ActiveSetRun<Backend>(p, o, name, backend, s, r).run();
}

}  // namespace karma::kea::detail

#endif
