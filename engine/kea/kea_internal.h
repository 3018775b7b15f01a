/* kea_internal.h: helpers shared by the Kea solver sources (not installed). */
#ifndef KARMA_KEA_INTERNAL_H
#define KARMA_KEA_INTERNAL_H

#include "kea_lcp.h"

#include <limits>
#include <span>
#include <vector>

namespace karma::kea::detail {

inline constexpr MeReal kInf = std::numeric_limits<MeReal>::infinity();

/* A bound with magnitude >= MEINFINITY becomes an IEEE infinity, so that
 * clamping and comparisons need no special cases. */
inline MeReal NormaliseBound(MeReal v) {
  if (v >= MEINFINITY) return kInf;
  if (v <= -MEINFINITY) return -kInf;
  return v;
}

/* The bounds of every row for a given lambda: the caller's (normalised) box,
 * or +-mu_i * max(lambda_j, 0) on friction rows. */
void ComputeBounds(const LcpProblem &p, std::span<const MeReal> lambda, std::vector<MeReal> &lo,
                   std::vector<MeReal> &hi);

/* Checks the problem and options; on failure warns and returns false. */
bool Validate(const LcpProblem &p, const KeaOptions &o, const char *function);

/* The BadInput result: zeros everywhere. */
KeaResult BadInputResult(int n);

/* Tolerance * (1 + max|b|): the residual below which the problem is solved. */
MeReal SolvedThreshold(const LcpProblem &p, const KeaOptions &o);

/* Emits the iteration-cap / cycle warnings when options.warnings is set. */
void WarnIterationLimit(const KeaOptions &o, const char *function, int iterations, MeReal residual);
void WarnCycle(const KeaOptions &o, const char *function, int iterations, MeReal residual);

}  // namespace karma::kea::detail

#endif
