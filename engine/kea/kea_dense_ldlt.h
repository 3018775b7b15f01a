/* kea_dense_ldlt.h: an LDL^T of a small dense symmetric block, in
 * outer-product order (not installed).
 *
 * Storage. Two m x m arrays, row-major, each row padded to a multiple of
 * kLanes values (stride): `upper`, whose upper triangle (entries (i, j),
 * j >= i) the caller fills, and `lower`, which receives L. After factor():
 *     upper[k][k] = d_k,   upper[k][c] = u_kc = l_ck d_k,   lower[c][k] = l_ck
 * (c > k; L unit lower triangular). The forward solve reads the rows of
 * `upper`, the backward solve the rows of `lower`: every loop runs along a
 * row.
 *
 * Factorisation, row by row (j ascending), with r_k = 1 / d_k:
 *     l_jk = u_kj r_k,   upper[j][c] <- upper[j][c] - l_jk u_kc   (k < j <= c,
 *     k ascending),  then d_j = upper[j][j],
 * the outer-product (right-looking) elimination of Golub & Van Loan,
 * "Matrix Computations", sec. 4.1, with the updates of one row gathered:
 * every entry receives the same subtractions in the same order, while row
 * j is held in registers (a fixed padded width) and the finished rows k
 * stream past. Unlike the envelope's Crout order (kea_envelope_ldlt.h),
 * where each entry ends a dot product whose last term was computed just
 * before, the updates are element by element: the compiler runs them in
 * vector lanes, and since no sum is reassociated the bits are those of the
 * scalar loop, on every backend and in every build. Row j's update starts
 * at column j rounded down to kLanes, so that it runs in whole lanes; the
 * columns it covers before j are scratch and are set back to zero, and the
 * padding stays zero. The cost is m^3 / 6 multiply-adds at most; a row k
 * that does not meet row j (l_jk exactly zero, so the update would
 * subtract zeros) is skipped, which leaves the same values (an exact zero
 * changes no sum) and makes the cost that of the block's fill in the order
 * the caller chose: rows of few nonzeros first (a car's contacts before its
 * joints, which all share the chassis) keep it low.
 *
 * Which rows meet (symbolic elimination). Row j's updates come from the
 * rows k < j with u_kj != 0. Without more knowledge every k is tested; a
 * caller that knows which entries of the upper triangle it fills (from its
 * sparse source: begin(rows, Pattern::Noted), then notePattern for each
 * off-diagonal entry) lets factor() find them first, from the pattern
 * alone, and keep them for the next block of that pattern
 * (Pattern::Kept). With P_k the columns c > k where u_kc may be nonzero
 * and p(k) = min P_k (row k's parent in the elimination tree),
 *     P_k = {c > k : a_kc noted}  union  (P_i - {k} for each i with p(i) = k)
 * (George & Liu, "Computer Solution of Large Sparse Positive Definite
 * Systems", sec. 5.4, row k of U for column k of L). Row j then visits
 * only the rows k with j in P_k, in ascending k (the order above). The
 * pattern holds every entry that can be nonzero, so a row left out would have
 * subtracted l_jk = 0 exactly and been skipped all the same: the bits are
 * those of the full test. Where few rows meet (a rag doll's tree) most of
 * the m^2 / 2 tests are skipped; the pattern is found from the caller's
 * bits in O(m) word operations and O(entries of U) bit sets. A caller
 * that says Kept promises the pattern of the last block whose pattern was
 * noted, of the same size (otherwise, or when no noted pattern has been
 * analysed since the last Unknown block, every pair is tested).
 *
 * Breakdown as in the envelope LDL^T: a pivot d_k <= kPivotFloor * (the
 * original a_kk), or a_kk <= 0, stops the factorisation and factor()
 * returns false; the caller takes another path. So does a pivot whose
 * reciprocal overflows (a subnormal d_k, possible only with eps = 0): with
 * r_k infinite every later l_jk would be infinite or NaN.
 *
 * Solve: L D L^T x = b as
 *     z_k = y_k r_k,  y_c <- y_c - u_kc z_k  (k ascending, c > k),
 *     x_k <- x_k - l_ck x_c                  (c descending, k < c),
 * again element by element along rows, in whole lanes on a padded copy:
 * each value is taken out as soon as it is final, so what a row's lanes do
 * to the values already taken out is never read. A group of kLanes columns
 * in which neither row of a pass holds a nonzero entry is skipped, as the
 * factor skips rows that do not meet: factor() notes, per row of `upper`
 * and of `lower`, the groups where it wrote one (upperGroups,
 * lowerGroups). Subtracting exact zeros leaves every finite value as it
 * was, up to the sign of a zero (-0 - (-0) is +0), as in the factor's
 * skip. The sparser the factor in the caller's order, the fewer groups a
 * pass visits.
 *
 * Nothing here allocates once reserve() has covered the block. */
#ifndef KARMA_KEA_DENSE_LDLT_H
#define KARMA_KEA_DENSE_LDLT_H

#include "MePrecision.h"

#include <array>
#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

namespace karma::kea::detail {

struct DenseLdlt {
  /* Rows are padded to a multiple of this many values. */
  static constexpr int kLanes = 8;
  /* The largest block factor() takes: topple's six-box stack (72 rows)
   * factorises faster here than by the envelope (docs/NOTES.md, "Small
   * kernels of the exact path"). */
  static constexpr int kMaxRows = 96;

  int m = 0, stride = 0;
  std::vector<MeReal> upper, lower;
  std::vector<MeReal> reciprocal; /* r_k = 1 / d_k */
  /* Bit g of row k's mask: the row has a nonzero entry in columns
   * g kLanes .. (g + 1) kLanes - 1, past its diagonal in `upper`
   * (u_kc, c > k), before it in `lower` (l_kc, c < k). */
  using GroupMask = std::uint32_t;
  static_assert(kMaxRows / kLanes <= 32, "a group per bit");
  std::vector<GroupMask> upperGroups, lowerGroups;
  std::vector<MeReal> diagonal; /* the original a_kk, for the pivot floor */
  /* Per row k, the columns c > k where the block may be nonzero (bit c),
   * as noted by the caller; factor() widens each row's to the factor's
   * (P_k above). */
  using RowBits = std::array<std::uint64_t, 2>;
  static_assert(kMaxRows <= 128, "a column per bit");
  /* Sets bit c (0 <= c < 128) of `bits`. */
  static void SetRowBit(RowBits &bits, std::size_t c) { bits[c / 64] |= std::uint64_t(1) << (c % 64); }
  std::vector<RowBits> pattern;
  /* Per row j, the rows k < j that may meet it (bit k: j in P_k). */
  std::vector<RowBits> meets;
  /* What begin() was told of the block's pattern. */
  enum class Pattern {
    Unknown, /* every pair of rows may meet */
    Noted,   /* the caller marks each entry it fills (notePattern) */
    Kept,    /* that of the last noted block, of the same size */
  };
  Pattern known = Pattern::Unknown; /* set by begin() */
  /* Whether `meets` holds the analysis of a noted pattern (what Kept
   * reuses). */
  bool meetsNoted = false;
  /* solve()'s scratch, one padded row (so solve() is const but not safe to
   * call from two threads on one factor). */
  mutable std::vector<MeReal> work;
  /* Room for blocks of up to `rows` rows. */
  void reserve(std::size_t rows);
  /* A new m x m block, zero wherever factor() and solve() read: row j from
   * column j rounded down to kLanes (which covers the upper triangle).
   * `told` says how factor() learns which rows meet (Pattern; see "Which
   * rows meet"). */
  void begin(int rows, Pattern told = Pattern::Unknown);
  /* Entry (i, j) may be nonzero; 0 <= i < j < m (after begin(m,
   * Pattern::Noted)). */
  void notePattern(int i, int j) {
    assert(0 <= i && i < j && j < m);
    SetRowBit(pattern[static_cast<std::size_t>(i)], static_cast<std::size_t>(j));
  }
  /* Entry (i, j) of the upper triangle, j >= i. */
  MeReal &at(int i, int j) {
    return upper[static_cast<std::size_t>(i) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(j)];
  }
  /* Factorises the block whose upper triangle the caller filled; false on
   * breakdown (the arrays, the group masks included, are then partly
   * overwritten, and solve() must not be called until a factor() has
   * succeeded). */
  bool factor();
  /* x = A^-1 rhs (m values each; x may alias rhs). */
  void solve(std::span<const MeReal> rhs, std::span<MeReal> x) const;
};

}  // namespace karma::kea::detail

#endif
