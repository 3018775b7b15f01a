/* kea_pgs.cpp: projected Gauss-Seidel for the boxed LCP.
 *
 * One sweep visits the rows in order; row i takes the value that zeroes w_i
 * with every other lambda held, then is clamped into its bounds (friction
 * bounds read from the current normal lambda, which the sweep may just have
 * updated). For A + eps I positive definite this converges to the LCP
 * solution, linearly, at a rate that worsens with the conditioning of A, so
 * the number of sweeps is the cost/accuracy knob: a fixed small budget per
 * frame gives a cheap, approximate answer. The sweep stops early once the
 * contract's residual is below the solved threshold. */
#include "kea_internal.h"

#include <algorithm>
#include <cmath>

namespace karma::kea {

KeaResult KeaSolvePGS(const LcpProblem &p, const KeaOptions &o) {
  static const char *const kName = "KeaSolvePGS";
  if (!detail::Validate(p, o, kName)) return detail::BadInputResult(p.n);

  const auto n = static_cast<std::size_t>(p.n);
  const MeReal eps = o.epsilon;
  const int cap = o.maxIterations > 0 ? o.maxIterations : 50;
  const MeReal threshold = detail::SolvedThreshold(detail::Rows(p), o);

  KeaResult r;
  r.threshold = threshold;
  detail::InitialLambda(o, n, r.lambda);
  r.w.assign(n, MeReal(0));

  std::vector<MeReal> lo, hi;
  detail::ComputeBounds(detail::Rows(p), r.lambda, lo, hi);
  for (std::size_t i = 0; i < n; ++i) r.lambda[i] = std::clamp(r.lambda[i], lo[i], hi[i]);

  std::vector<MeReal> best = r.lambda;
  MeReal bestResidual = KeaResidual(p, eps, r.lambda);
  const bool friction = !p.findex.empty();
  int sweeps = 0;
  while (bestResidual > threshold && sweeps < cap) {
    for (std::size_t i = 0; i < n; ++i) {
      const MeReal diag = p.A[i * n + i] + eps;
      if (!(diag > 0)) continue; /* a null row: nothing to gain from it */
      const MeReal *row = p.A.data() + i * n;
      MeReal wi = -p.b[i] + eps * r.lambda[i];
      for (std::size_t j = 0; j < n; ++j) wi += row[j] * r.lambda[j];
      MeReal rowLo = lo[i], rowHi = hi[i];
      if (friction && p.findex[i] >= 0) {
        const MeReal limit = p.mu[i] * std::max(r.lambda[static_cast<std::size_t>(p.findex[i])], MeReal(0));
        rowLo = -limit;
        rowHi = limit;
      }
      r.lambda[i] = std::clamp(r.lambda[i] - wi / diag, rowLo, rowHi);
    }
    ++sweeps;
    const MeReal residual = KeaResidual(p, eps, r.lambda);
    if (residual < bestResidual) {
      bestResidual = residual;
      best = r.lambda;
    }
  }

  r.lambda = best;
  r.residual = KeaResidual(p, eps, r.lambda, r.w);
  r.iterations = sweeps;
  if (r.residual <= threshold) {
    r.status = KeaStatus::Solved;
  } else {
    r.status = KeaStatus::IterationLimit;
    detail::WarnIterationLimit(o, kName, sweeps, r.residual);
  }
  return r;
}

}  // namespace karma::kea
