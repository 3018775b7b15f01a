/* kea_lcp.cpp: the parts of the LCP contract shared by every solver:
 * validation, bounds (including friction coupling), the residual, and the
 * dispatching entry point. */
#include "kea_internal.h"
#include "lanes16.h"

#include "MeMessage.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <type_traits>
#include <cmath>

namespace karma::kea {
namespace detail {

void ComputeBounds(const RowView &p, std::span<const MeReal> lambda, std::vector<MeReal> &lo, std::vector<MeReal> &hi) {
  const auto n = static_cast<std::size_t>(p.n);
  lo.resize(n);
  hi.resize(n);
  const bool friction = !p.findex.empty();
  for (std::size_t i = 0; i < n; ++i) {
    const int j = friction ? p.findex[i] : -1;
    if (j >= 0) {
      const MeReal normal = std::max(lambda[static_cast<std::size_t>(j)], MeReal(0));
      const MeReal limit = p.mu[i] * normal;
      lo[i] = -limit;
      hi[i] = limit;
    } else {
      lo[i] = NormaliseBound(p.lo[i]);
      hi[i] = NormaliseBound(p.hi[i]);
    }
  }
}

namespace {

/* Whether no value is NaN or infinite: a value is not finite exactly when
 * its exponent bits are all ones (IEEE 754). Tested on the bits, with an
 * integer OR over the array, which the compiler runs in vector lanes. */
bool AllFinite(std::span<const MeReal> v) {
  using Bits = std::conditional_t<sizeof(MeReal) == sizeof(std::uint32_t), std::uint32_t, std::uint64_t>;
  static_assert(sizeof(Bits) == sizeof(MeReal));
  constexpr Bits kExponent = sizeof(Bits) == 4 ? Bits(0x7f800000u) : Bits(0x7ff0000000000000ull);
  Bits notFinite = 0;
  for (MeReal x : v) notFinite |= Bits((std::bit_cast<Bits>(x) & kExponent) == kExponent);
  return notFinite == 0;
}

}  // namespace

/* See kea_internal.h. A maximum is exact in any order, so lanes give the
 * scalar loop's value. */
MeReal LargestOrInfinite(std::span<const MeReal> v) {
  using platform::Lanes16;
  constexpr std::size_t kLanes = platform::kPerLanes16;
  const Lanes16 limit = Lanes16{} + ME_REAL_MAX;
  Lanes16 big{};
  auto finite = big == big; /* all lanes true; false for a NaN or an infinity seen */
  std::size_t a = 0;
  for (; a + kLanes <= v.size(); a += kLanes) {
    Lanes16 x = platform::LoadLanes16(v.data() + a);
    x = x < MeReal(0) ? -x : x;
    finite &= x <= limit;
    big = x > big ? x : big;
  }
  MeReal largest = 0;
  bool allFinite = true;
  for (std::size_t c = 0; c < kLanes; ++c) {
    largest = std::max(largest, big[c]);
    allFinite = allFinite && finite[c] != 0;
  }
  for (; a < v.size(); ++a) {
    allFinite = allFinite && std::isfinite(v[a]);
    largest = std::max(largest, std::fabs(v[a]));
  }
  return allFinite ? largest : std::numeric_limits<MeReal>::infinity();
}

MeReal ComplementarityResidual(const RowView &p, std::span<const MeReal> lambda, std::span<const MeReal> w) {
  const auto n = static_cast<std::size_t>(p.n);
  const bool friction = !p.findex.empty();
  MeReal worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int j = friction ? p.findex[i] : -1;
    MeReal lo, hi;
    if (j >= 0) {
      hi = p.mu[i] * std::max(lambda[static_cast<std::size_t>(j)], MeReal(0));
      lo = -hi;
    } else {
      lo = NormaliseBound(p.lo[i]);
      hi = NormaliseBound(p.hi[i]);
    }
    const MeReal projected = std::clamp(lambda[i] - w[i], lo, hi);
    worst = std::max(worst, std::fabs(lambda[i] - projected));
  }
  return worst;
}

bool Reject(const char *function, const char *why) {
  MeWarning(0, "%s: bad input: %s; returning lambda = 0", function, why);
  return false;
}

bool Validate(const LcpProblem &p, const KeaOptions &o, const char *function) {
  if (p.n < 0) return Reject(function, "negative row count");
  const auto n = static_cast<std::size_t>(p.n);
  if (p.A.size() != n * n) return Reject(function, "A does not hold n*n values");
  if (!AllFinite(p.A)) return Reject(function, "A contains NaN or infinity");
  return ValidateRows(Rows(p), o, function);
}

bool ValidateSparse(const SparseLcpProblem &p, const KeaOptions &o, const char *function) {
  if (p.n < 0) return Reject(function, "negative row count");
  const auto n = static_cast<std::size_t>(p.n);
  if (p.rowStart.size() != n + 1) return Reject(function, "CSR row starts do not hold n + 1 values");
  if (p.rowStart[0] != 0) return Reject(function, "CSR row starts do not begin at 0");
  for (std::size_t i = 0; i < n; ++i)
    if (p.rowStart[i + 1] < p.rowStart[i]) return Reject(function, "CSR row starts are not ascending");
  if (static_cast<std::size_t>(p.rowStart[n]) != p.col.size() || p.col.size() != p.val.size())
    return Reject(function, "CSR column and value arrays do not hold rowStart[n] values");
  /* One pass over the entries; a non-finite value is reported after every
   * structural fault. */
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i) {
    bool diagonal = false;
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k) {
      const int c = p.col[static_cast<std::size_t>(k)];
      if (c < 0 || c >= p.n) return Reject(function, "CSR column index out of range");
      if (k > p.rowStart[i] && c <= p.col[static_cast<std::size_t>(k) - 1])
        return Reject(function, "CSR columns are not strictly ascending within a row");
      if (static_cast<std::size_t>(c) == i) diagonal = true;
      finite = finite && (p.op || std::isfinite(p.val[static_cast<std::size_t>(k)]));
    }
    if (!diagonal) return Reject(function, "CSR row without its diagonal entry");
  }
  if (!finite) return Reject(function, "A contains NaN or infinity");
  return ValidateRows(Rows(p), o, function);
}

bool ValidateSparseValues(const SparseLcpProblem &p, const KeaOptions &o, const char *function) {
  if (!p.op && !AllFinite(p.val)) return Reject(function, "A contains NaN or infinity");
  return ValidateRows(Rows(p), o, function);
}

bool ValidateRows(const RowView &p, const KeaOptions &o, const char *function) {
  if (p.n < 0) return Reject(function, "negative row count");
  const auto n = static_cast<std::size_t>(p.n);
  if (p.b.size() != n || p.lo.size() != n || p.hi.size() != n)
    return Reject(function, "b, lo or hi does not hold n values");
  if (!p.findex.empty() && p.findex.size() != n) return Reject(function, "findex is neither empty nor n values");
  if (!o.warmStart.empty() && o.warmStart.size() != n)
    return Reject(function, "warm start is neither empty nor n values");
  if (!AllFinite(p.b)) return Reject(function, "b contains NaN or infinity");
  if (!AllFinite(o.warmStart)) return Reject(function, "warm start contains NaN or infinity");
  if (!(o.epsilon >= 0) || !std::isfinite(o.epsilon)) return Reject(function, "epsilon is negative or NaN");
  if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance)) return Reject(function, "tolerance is negative or NaN");
  if (o.maxIterations < 0) return Reject(function, "maxIterations is negative");
  if (!(o.warmAcceptDivisor >= 1)) return Reject(function, "warmAcceptDivisor is below 1 or NaN");
  /* One pass: the first faulty row is reported (a friction row's findex
   * before its mu). */
  const bool muFits = p.mu.size() == n;
  for (std::size_t i = 0; i < n; ++i) {
    const int j = p.findex.empty() ? -1 : p.findex[i];
    if (j >= 0) {
      if (j >= p.n || static_cast<std::size_t>(j) == i) return Reject(function, "findex out of range");
      if (p.findex[static_cast<std::size_t>(j)] >= 0) return Reject(function, "findex points at another friction row");
      if (!muFits) return Reject(function, "friction rows need n values of mu");
      if (!(p.mu[i] >= 0 && std::isfinite(p.mu[i]))) return Reject(function, "mu is negative, NaN or infinite");
      continue;
    }
    if (j < -1) return Reject(function, "findex out of range");
    const MeReal lo = p.lo[i], hi = p.hi[i];
    if (std::isnan(lo) || std::isnan(hi)) return Reject(function, "a bound is NaN");
    if (lo > hi) return Reject(function, "lo > hi");
    if (NormaliseBound(lo) == kInf || NormaliseBound(hi) == -kInf)
      return Reject(function, "lo is +infinity or hi is -infinity");
  }
  return true;
}

KeaResult BadInputResult(int n) {
  KeaResult r;
  const auto size = static_cast<std::size_t>(std::max(n, 0));
  r.lambda.assign(size, MeReal(0));
  r.w.assign(size, MeReal(0));
  r.status = KeaStatus::BadInput;
  return r;
}

MeReal SolvedThreshold(const RowView &p, const KeaOptions &o) {
  /* b is finite here (validated), and a largest value is exact in any
   * order: LargestOrInfinite's lanes give the scalar loop's bits. */
  const MeReal bmax = LargestOrInfinite(p.b);
  const MeReal tol = o.tolerance > 0 ? o.tolerance : KeaDefaultTolerance();
  return tol * (MeReal(1) + bmax);
}

void WarnIterationLimit(const KeaOptions &o, const char *function, int iterations, MeReal residual) {
  if (o.warnings)
    MeWarning(0, "%s: maximum number of iterations exceeded (%d); residual %g, returning the best iterate", function,
              iterations, static_cast<double>(residual));
}

void WarnCycle(const KeaOptions &o, const char *function, int iterations, MeReal residual) {
  if (o.warnings)
    MeWarning(0, "%s: cycle has been detected after %d iterations; residual %g, returning the best iterate", function,
              iterations, static_cast<double>(residual));
}

}  // namespace detail

MeReal KeaDefaultTolerance() {
#if KARMA_DOUBLE
  return MeReal(1e-10);
#else
  return MeReal(1e-4);
#endif
}

const char *KeaStatusName(KeaStatus status) {
  switch (status) {
    case KeaStatus::Solved:
      return "Solved";
    case KeaStatus::IterationLimit:
      return "IterationLimit";
    case KeaStatus::CycleDetected:
      return "CycleDetected";
    case KeaStatus::BadInput:
      return "BadInput";
  }
  return "?";
}

MeReal KeaResidual(const LcpProblem &p, MeReal epsilon, std::span<const MeReal> lambda, std::span<MeReal> w) {
  const auto n = static_cast<std::size_t>(p.n);
  std::vector<MeReal> wl(n);
  for (std::size_t i = 0; i < n; ++i) {
    MeReal wi = -p.b[i] + epsilon * lambda[i];
    const MeReal *row = p.A.data() + i * n;
    for (std::size_t j = 0; j < n; ++j) wi += row[j] * lambda[j];
    wl[i] = wi;
  }
  if (w.size() == n) std::copy(wl.begin(), wl.end(), w.begin());
  return detail::ComplementarityResidual(detail::Rows(p), lambda, wl);
}

KeaResult KeaSolve(const LcpProblem &problem, const KeaOptions &options) {
  return options.method == KeaMethod::PGS ? KeaSolvePGS(problem, options) : KeaSolveActiveSet(problem, options);
}

}  // namespace karma::kea
