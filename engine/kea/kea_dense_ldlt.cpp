/* kea_dense_ldlt.cpp: the dense outer-product LDL^T (see kea_dense_ldlt.h). */
#include "kea_dense_ldlt.h"

#include "kea_envelope_ldlt.h"

#include <algorithm>
#include <utility>

namespace karma::kea::detail {
namespace {

/* y[c] -= s * x[c] on whole groups of kLanes values (count a multiple of
 * kLanes): one element at a time, in lanes, no remainder loop. */
void SubtractScaledLanes(MeReal *__restrict y, const MeReal *__restrict x, MeReal s, std::size_t count) {
  constexpr auto kLanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  for (std::size_t c = 0; c < count; c += kLanes)
    for (std::size_t l = 0; l < kLanes; ++l) y[c + l] = y[c + l] - s * x[c + l];
}

/* Row j of the factorisation, columns from .. from + Width - 1 (from = j
 * rounded down to kLanes, from + Width = the stride): every update
 *     a_jc <- a_jc - l_jk u_kc,   l_jk = u_kj r_k,   k = 0 .. j - 1
 * in ascending k, the row held in `acc` (registers, for a fixed Width)
 * while the finished rows k stream past. Writes l_jk to lowerJ[k]. */
template <std::size_t Width>
void EliminateRow(MeReal *rowJ, const MeReal *upper, std::size_t stride, std::size_t j, const MeReal *reciprocal,
                  MeReal *lowerJ) {
  const std::size_t from = stride - Width;
  MeReal acc[Width];
  for (std::size_t c = 0; c < Width; ++c) acc[c] = rowJ[from + c];
  for (std::size_t k = 0; k < j; ++k) {
    const MeReal *rowK = upper + k * stride;
    const MeReal l = rowK[j] * reciprocal[k];
    lowerJ[k] = l;
    if (l == 0) continue; /* rows k and j do not interact: nothing to subtract */
    for (std::size_t c = 0; c < Width; ++c) acc[c] = acc[c] - l * rowK[from + c];
  }
  for (std::size_t c = 0; c < Width; ++c) rowJ[from + c] = acc[c];
  for (std::size_t c = from; c < j; ++c) rowJ[c] = 0; /* the scratch columns stay zero */
}

/* EliminateRow at the width of `groups` groups of kLanes (1 ..
 * kMaxRows / kLanes): a run-time width picks its compiled instance. */
template <std::size_t... Groups>
void EliminateRowOf(std::size_t groups, std::index_sequence<Groups...>, MeReal *rowJ, const MeReal *upper,
                    std::size_t stride, std::size_t j, const MeReal *reciprocal, MeReal *lowerJ) {
  constexpr auto kLanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  (void)((groups == Groups + 1 &&
          (EliminateRow<(Groups + 1) * kLanes>(rowJ, upper, stride, j, reciprocal, lowerJ), true)) ||
         ...);
}

std::size_t Padded(std::size_t rows) {
  const auto lanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  return (rows + lanes - 1) / lanes * lanes;
}

}  // namespace

void DenseLdlt::reserve(std::size_t rows) {
  upper.reserve(rows * Padded(rows));
  lower.reserve(rows * Padded(rows));
  reciprocal.reserve(rows);
  work.reserve(Padded(rows));
  diagonal.reserve(rows);
}

void DenseLdlt::begin(int rows) {
  m = rows;
  stride = static_cast<int>(Padded(static_cast<std::size_t>(rows)));
  const auto s = static_cast<std::size_t>(stride);
  const auto lanes = static_cast<std::size_t>(kLanes);
  upper.resize(static_cast<std::size_t>(m) * s);
  /* Only what factor() and solve() read: row j from column j rounded down
   * to kLanes (the columns before it are never read, and may hold an
   * earlier block's values). */
  for (std::size_t j = 0; j < static_cast<std::size_t>(m); ++j)
    std::fill(upper.begin() + static_cast<std::ptrdiff_t>(j * s + j / lanes * lanes),
              upper.begin() + static_cast<std::ptrdiff_t>((j + 1) * s), MeReal(0));
}

bool DenseLdlt::factor() {
  const auto n = static_cast<std::size_t>(m);
  const auto s = static_cast<std::size_t>(stride);
  const auto lanes = static_cast<std::size_t>(kLanes);
  if (m > kMaxRows) return false;
  lower.resize(n * s);
  reciprocal.resize(n);
  diagonal.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    MeReal *rowJ = upper.data() + j * s;
    diagonal[j] = rowJ[j];
    const std::size_t groups = (s - j / lanes * lanes) / lanes;
    EliminateRowOf(groups, std::make_index_sequence<kMaxRows / kLanes>(), rowJ, upper.data(), s, j, reciprocal.data(),
                   lower.data() + j * s);
    const MeReal d = rowJ[j];
    if (!(diagonal[j] > 0) || !(d > kPivotFloor * diagonal[j])) return false;
    reciprocal[j] = MeReal(1) / d;
  }
  return true;
}

void DenseLdlt::solve(std::span<const MeReal> rhs, std::span<MeReal> x) const {
  const auto n = static_cast<std::size_t>(m);
  const auto s = static_cast<std::size_t>(stride);
  const auto lanes = static_cast<std::size_t>(kLanes);
  if (n == 0) return;
  work.resize(s);
  std::copy(rhs.begin(), rhs.begin() + static_cast<std::ptrdiff_t>(n), work.begin());
  std::fill(work.begin() + static_cast<std::ptrdiff_t>(n), work.end(), MeReal(0));
  /* z_k = y_k r_k; y_c -= u_kc z_k for the rows below, in whole lanes from
   * column k + 1 rounded down: the columns up to k of work are spent (z_k
   * is in x), so what the scratch part of row k does to them is never read. */
  for (std::size_t k = 0; k < n; ++k) {
    const MeReal z = work[k] * reciprocal[k];
    x[k] = z;
    const std::size_t from = (k + 1) / lanes * lanes;
    SubtractScaledLanes(work.data() + from, upper.data() + k * s + from, z, s - from);
  }
  /* L^T x = z by rows of L from the bottom: x_c is final once the rows
   * below it have been subtracted; it is taken out before its own row runs
   * over columns c .. (c rounded up) - 1, which are spent. */
  std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), work.begin());
  for (std::size_t c = n; c-- > 1;) {
    const MeReal xc = work[c];
    x[c] = xc;
    SubtractScaledLanes(work.data(), lower.data() + c * s, xc, (c + lanes - 1) / lanes * lanes);
  }
  x[0] = work[0];
}

}  // namespace karma::kea::detail
