/* kea_internal.h: helpers shared by the Kea solver sources (not installed). */
#ifndef KARMA_KEA_INTERNAL_H
#define KARMA_KEA_INTERNAL_H

#include "kea_lcp.h"

#include <algorithm>
#include <bit>
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

/* The room a workspace makes for n rows (or entries): n rounded up to a
 * power of two (0 for none). A workspace whose problems grow a few rows at
 * a time (a column that gains a landing box's rows each step) then
 * reallocates its arrays about log2 n times, not once per size. */
inline std::size_t Room(std::size_t n) { return n ? std::bit_ceil(n) : 0; }

/* Room(n) in v when it has less than n. A vector with room enough keeps its
 * buffer, so one that a solve swaps with another (the active set's saved
 * impulses and the caller's answer) is not reallocated at the next solve. */
template <class T>
void ReserveRoom(std::vector<T> &v, std::size_t n) {
  if (v.capacity() < n) v.reserve(Room(n));
}

/* The per-row part of a problem (everything but the matrix), shared by the
 * dense and the sparse problems. */
struct RowView {
  int n = 0;
  std::span<const MeReal> b, lo, hi;
  std::span<const int> findex;
  std::span<const MeReal> mu;
};
/* The backend of a solve's array kernels (KeaOptions::kernels). */
inline const platform::Kernels &KernelsOf(const KeaOptions &o) {
  return o.kernels ? *o.kernels : platform::DefaultKernels();
}

inline RowView Rows(const LcpProblem &p) { return {p.n, p.b, p.lo, p.hi, p.findex, p.mu}; }
inline RowView Rows(const SparseLcpProblem &p) { return {p.n, p.b, p.lo, p.hi, p.findex, p.mu}; }

/* The bounds of every row for a given lambda: the caller's (normalised) box,
 * or +-mu_i * max(lambda_j, 0) on friction rows. */
void ComputeBounds(const RowView &p, std::span<const MeReal> lambda, std::vector<MeReal> &lo, std::vector<MeReal> &hi);

/* The contract's residual max_i |lambda_i - clamp(lambda_i - w_i, lo_i, hi_i)|
 * for a given lambda and its w (bounds computed from lambda, row by row:
 * no allocation). */
MeReal ComplementarityResidual(const RowView &p, std::span<const MeReal> lambda, std::span<const MeReal> w);

/* max_a |v_a| (0 for none), or infinity when some v_a is NaN or infinite:
 * a residual's size that a non-finite component never passes. */
MeReal LargestOrInfinite(std::span<const MeReal> v);

/* lambda (resized to n) = the warm start, or zeros without one. The warm
 * start may be lambda itself (a caller re-solving from its last result). */
inline void InitialLambda(const KeaOptions &o, std::size_t n, std::vector<MeReal> &lambda) {
  if (!o.warmStart.empty() && o.warmStart.data() == lambda.data() && lambda.size() == n) return;
  lambda.assign(n, MeReal(0));
  if (!o.warmStart.empty()) std::copy(o.warmStart.begin(), o.warmStart.end(), lambda.begin());
}

/* Warns "<function>: bad input: <why>; ..." and returns false. */
bool Reject(const char *function, const char *why);

/* Checks the per-row arrays and the options (everything but the matrix,
 * whose size and finiteness the caller checks first); on failure warns and
 * returns false. */
bool ValidateRows(const RowView &p, const KeaOptions &o, const char *function);

/* Checks the dense problem and options; on failure warns and returns false. */
bool Validate(const LcpProblem &p, const KeaOptions &o, const char *function);

/* Checks the sparse problem (CSR structure: n + 1 ascending row starts from
 * 0, columns in range and strictly ascending within a row, every diagonal
 * present, finite values) and options; on failure warns and returns false. */
bool ValidateSparse(const SparseLcpProblem &p, const KeaOptions &o, const char *function);
/* The same checks for a problem whose CSR structure (rowStart, col) is
 * known to be one that passed ValidateSparse: only the values and rows. */
bool ValidateSparseValues(const SparseLcpProblem &p, const KeaOptions &o, const char *function);

/* The BadInput result: zeros everywhere. */
KeaResult BadInputResult(int n);

/* Tolerance * (1 + max|b|): the residual below which the problem is solved;
 * b must be finite (validated). */
MeReal SolvedThreshold(const RowView &p, const KeaOptions &o);

/* Emits the iteration-cap / cycle warnings when options.warnings is set. */
void WarnIterationLimit(const KeaOptions &o, const char *function, int iterations, MeReal residual);
void WarnCycle(const KeaOptions &o, const char *function, int iterations, MeReal residual);

}  // namespace karma::kea::detail

#endif
