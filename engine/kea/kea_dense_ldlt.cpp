/* kea_dense_ldlt.cpp: the dense outer-product LDL^T (see kea_dense_ldlt.h). */
#include "kea_dense_ldlt.h"

#include "kea_envelope_ldlt.h"
#include "lanes16.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

namespace karma::kea::detail {
namespace {

/* y[c] = (y[c] - s0 * x0[c]) - s1 * x1[c] on whole groups of kLanes
 * values (count a multiple of kLanes), one element at a time, in lanes, no
 * remainder loop: each element rounded as by a pass with row 0 and then
 * one with row 1. */
void SubtractTwoScaledLanes(MeReal *__restrict y, const MeReal *__restrict x0, MeReal s0, const MeReal *__restrict x1,
                            MeReal s1, std::size_t count) {
  using platform::LoadLanes16;
  static_assert(DenseLdlt::kLanes % platform::kPerLanes16 == 0);
  for (std::size_t c = 0; c < count; c += platform::kPerLanes16)
    platform::StoreLanes16(y + c, (LoadLanes16(y + c) - s0 * LoadLanes16(x0 + c)) - s1 * LoadLanes16(x1 + c));
}

/* Row j of the factorisation, columns from .. from + Width - 1 (from = j
 * rounded down to kLanes, from + Width = the stride): every update
 *     a_jc <- a_jc - l_jk u_kc,   l_jk = u_kj r_k,   k in meet (ascending;
 * every k < j for which u_kj may be nonzero), the row held in `acc`
 * (registers, for a fixed Width) while the finished rows k stream past.
 * Writes l_jk to lowerJ[k] (zero for the rows not in meet), notes
 * the group of each nonzero l_jk in *lowerGroupsJ and, for each nonzero
 * u_kj (a finished entry of row k), the group of column j in
 * upperGroups[k]: every u_kc with c > k is read here once. A row
 * wider than sixteen 16-byte registers is updated where it lies: a copy
 * would live in memory all the same, and GCC makes the copies `rep movs`,
 * whose start-up made a 75-row factorisation 8 % slower (docs/NOTES.md,
 * "String instructions in hot loops"). */
template <std::size_t Width>
void EliminateRow(MeReal *rowJ, const MeReal *upper, std::size_t stride, std::size_t j, const DenseLdlt::RowBits &meet,
                  const MeReal *reciprocal, MeReal *lowerJ, DenseLdlt::GroupMask *upperGroups,
                  DenseLdlt::GroupMask *lowerGroupsJ) {
  constexpr bool kInPlace = Width * sizeof(MeReal) > 16 * 16;
  constexpr auto kLanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  const std::size_t from = stride - Width;
  const DenseLdlt::GroupMask groupJ = DenseLdlt::GroupMask(1) << (j / kLanes);
  DenseLdlt::GroupMask lowerMask = 0;
  MeReal local[kInPlace ? 1 : Width];
  MeReal *const acc = kInPlace ? rowJ + from : local;
  if constexpr (!kInPlace)
    for (std::size_t c = 0; c < Width; ++c) acc[c] = rowJ[from + c];
  std::fill(lowerJ, lowerJ + j, MeReal(0));
  for (std::size_t w = 0; w < meet.size(); ++w)
    for (std::uint64_t bits = meet[w]; bits != 0; bits &= bits - 1) {
      const std::size_t k = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
      const MeReal *rowK = upper + k * stride;
      const MeReal u = rowK[j];
      if (u != 0) upperGroups[k] |= groupJ;
      const MeReal l = u * reciprocal[k];
      lowerJ[k] = l;
      if (l == 0) continue; /* rows k and j do not interact: nothing to subtract */
      lowerMask |= DenseLdlt::GroupMask(1) << (k / kLanes);
      for (std::size_t c = 0; c < Width; ++c) acc[c] = acc[c] - l * rowK[from + c];
    }
  *lowerGroupsJ = lowerMask;
  if constexpr (!kInPlace)
    for (std::size_t c = 0; c < Width; ++c) rowJ[from + c] = acc[c];
  for (std::size_t c = from; c < j; ++c) rowJ[c] = 0; /* the scratch columns stay zero */
}

/* EliminateRow at the width of `groups` groups of kLanes (1 ..
 * kMaxRows / kLanes): a run-time width picks its compiled instance. */
template <std::size_t... Groups>
void EliminateRowOf(std::size_t groups, std::index_sequence<Groups...>, MeReal *rowJ, const MeReal *upper,
                    std::size_t stride, std::size_t j, const DenseLdlt::RowBits &meet, const MeReal *reciprocal,
                    MeReal *lowerJ, DenseLdlt::GroupMask *upperGroups, DenseLdlt::GroupMask *lowerGroupsJ) {
  constexpr auto kLanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  (void)((groups == Groups + 1 && (EliminateRow<(Groups + 1) * kLanes>(rowJ, upper, stride, j, meet, reciprocal, lowerJ,
                                                                       upperGroups, lowerGroupsJ),
                                   true)) ||
         ...);
}

/* The symbolic elimination of the header ("Which rows meet"): widens each
 * pattern[k] to P_k, handing it on to its parent p(k) = min P_k, and sets
 * bit k of meets[c] for every c in P_k. */
void MeetingRows(std::size_t m, std::vector<DenseLdlt::RowBits> &pattern, std::vector<DenseLdlt::RowBits> &meets) {
  meets.assign(m, DenseLdlt::RowBits{});
  for (std::size_t k = 0; k < m; ++k) {
    const DenseLdlt::RowBits &bits = pattern[k];
    const std::size_t word = bits[0] != 0 ? 0 : 1;
    if (bits[word] == 0) continue;
    const std::size_t parent = word * 64 + static_cast<std::size_t>(std::countr_zero(bits[word]));
    DenseLdlt::RowBits &up = pattern[parent];
    for (std::size_t w = 0; w < bits.size(); ++w) up[w] |= bits[w];
    up[parent / 64] &= ~(std::uint64_t(1) << (parent % 64)); /* P_k - {p(k)}: all of it lies past p(k) */
    for (std::size_t w = 0; w < bits.size(); ++w)
      for (std::uint64_t x = bits[w]; x != 0; x &= x - 1)
        DenseLdlt::SetRowBit(meets[w * 64 + static_cast<std::size_t>(std::countr_zero(x))], k);
  }
}

/* meets[j] = every row before j. */
void AllRowsMeet(std::size_t m, std::vector<DenseLdlt::RowBits> &meets) {
  meets.resize(m);
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t w = 0; w < meets[j].size(); ++w) {
      const std::size_t below = j > 64 * w ? std::min<std::size_t>(j - 64 * w, 64) : 0;
      meets[j][w] = below == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << below) - 1;
    }
}

/* SubtractTwoScaledLanes on the groups of kLanes values whose bits are set
 * in `groups` (bit g: values g kLanes .. (g + 1) kLanes - 1). */
void SubtractTwoScaledGroups(MeReal *__restrict y, const MeReal *__restrict x0, MeReal s0, const MeReal *__restrict x1,
                             MeReal s1, DenseLdlt::GroupMask groups) {
  constexpr auto kLanes = static_cast<std::size_t>(DenseLdlt::kLanes);
  while (groups != 0) {
    const auto at = static_cast<std::size_t>(std::countr_zero(groups)) * kLanes;
    groups &= groups - 1;
    SubtractTwoScaledLanes(y + at, x0 + at, s0, x1 + at, s1, kLanes);
  }
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
  upperGroups.reserve(rows);
  lowerGroups.reserve(rows);
  work.reserve(Padded(rows));
  diagonal.reserve(rows);
  pattern.reserve(rows);
  meets.reserve(rows);
}

void DenseLdlt::begin(int rows, Pattern told) {
  m = rows;
  known = told;
  if (told == Pattern::Noted) pattern.assign(static_cast<std::size_t>(rows), RowBits{});
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
  upperGroups.assign(n, 0);
  lowerGroups.resize(n);
  if (known == Pattern::Noted) {
    MeetingRows(n, pattern, meets);
    meetsNoted = true;
  } else if (known == Pattern::Unknown || !meetsNoted || meets.size() != n) {
    AllRowsMeet(n, meets);
    meetsNoted = false;
  }
  for (std::size_t j = 0; j < n; ++j) {
    MeReal *rowJ = upper.data() + j * s;
    diagonal[j] = rowJ[j];
    const std::size_t groups = (s - j / lanes * lanes) / lanes;
    EliminateRowOf(groups, std::make_index_sequence<kMaxRows / kLanes>(), rowJ, upper.data(), s, j, meets[j],
                   reciprocal.data(), lower.data() + j * s, upperGroups.data(), &lowerGroups[j]);
    const MeReal d = rowJ[j];
    if (!(diagonal[j] > 0) || !(d > kPivotFloor * diagonal[j])) return false;
    reciprocal[j] = MeReal(1) / d;
    if (!std::isfinite(reciprocal[j])) return false; /* a subnormal pivot (see the header) */
  }
  return true;
}

void DenseLdlt::solve(std::span<const MeReal> rhs, std::span<MeReal> x) const {
  const auto n = static_cast<std::size_t>(m);
  const auto s = static_cast<std::size_t>(stride);
  if (n == 0) return;
  work.resize(s);
  std::copy(rhs.begin(), rhs.begin() + static_cast<std::ptrdiff_t>(n), work.begin());
  std::fill(work.begin() + static_cast<std::ptrdiff_t>(n), work.end(), MeReal(0));
  /* z_k = y_k r_k; y_c -= u_kc z_k for the rows below, in whole lanes from
   * column k + 1 rounded down: the columns up to k of work are spent (z_k
   * is in x), so what the scratch part of row k does to them is never read.
   * Rows k and k + 1 go in one pass: y_k+1 first receives row k's term
   * alone (what row k's pass would leave there), which gives z_k+1; then
   * every column receives row k's term and row k + 1's, in that order.
   * Columns that only row k's pass would cover are up to k + 1, spent too,
   * and row k + 1 is zero or scratch from there (begin()). Only the groups
   * where row k or row k + 1 has an entry past its diagonal are touched:
   * the others would subtract zeros from columns past k + 1, or scratch
   * from spent ones. */
  std::size_t k = 0;
  for (; k + 1 < n; k += 2) {
    const MeReal *rowK = upper.data() + k * s, *rowNext = rowK + s;
    const MeReal z = work[k] * reciprocal[k];
    const MeReal zNext = (work[k + 1] - z * rowK[k + 1]) * reciprocal[k + 1];
    x[k] = z;
    x[k + 1] = zNext;
    SubtractTwoScaledGroups(work.data(), rowK, z, rowNext, zNext, upperGroups[k] | upperGroups[k + 1]);
  }
  if (k < n) x[k] = work[k] * reciprocal[k];
  /* L^T x = z by rows of L from the bottom: x_c is final once the rows
   * below it have been subtracted; it is taken out before its own row runs
   * over columns c .. (c rounded up) - 1, which are spent. Rows c and c - 1
   * go in one pass, as above: x_c-1 receives row c's term alone first; only
   * the groups where either row has an entry before its diagonal. */
  std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), work.begin());
  std::size_t c = n - 1;
  for (; c >= 2; c -= 2) {
    const MeReal *rowC = lower.data() + c * s, *rowBefore = rowC - s;
    const MeReal xc = work[c];
    const MeReal xBefore = work[c - 1] - xc * rowC[c - 1];
    x[c] = xc;
    x[c - 1] = xBefore;
    SubtractTwoScaledGroups(work.data(), rowC, xc, rowBefore, xBefore, lowerGroups[c] | lowerGroups[c - 1]);
  }
  if (c == 1) {
    const MeReal x1 = work[1];
    x[1] = x1;
    x[0] = work[0] - x1 * lower[s];
  } else {
    x[0] = work[0];
  }
}

}  // namespace karma::kea::detail
