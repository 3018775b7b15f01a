/* kea_envelope_ldlt.h: an in-place LDL^T of a symmetric matrix stored by
 * its envelope (profile, or skyline), on caller-owned arrays (not
 * installed).
 *
 * Storage. Row i of the lower triangle is stored from its first nonzero
 * column first[i] to the diagonal: entries (i, first[i]) .. (i, i) at
 * value[start[i]] .. value[start[i] + i - first[i]], start[i + 1] =
 * start[i] + i - first[i] + 1. A dense matrix is the case first[i] = 0.
 *
 * Factorisation. A = L D L^T with L unit lower triangular and D diagonal,
 * without pivoting (Crout, row by row):
 *     u_ij = a_ij - sum_{k < j} u_ik l_jk     (u_ik = l_ik d_k),  j < i
 *     l_ij = u_ij / d_j,   d_i = a_ii - sum_{j < i} u_ij l_ij.
 * L has the same envelope as A (fill stays inside the profile: George & Liu,
 * "Computer Solution of Large Sparse Positive Definite Systems", ch. 4), so
 * it overwrites A in place, and the cost is sum_i (i - first[i])^2 / 2
 * instead of m^3 / 6: linear in m for a banded matrix (a chain, a stack
 * whose rows are ordered box by box). Without pivoting this is backward
 * stable for a positive definite matrix (as for Cholesky); a pivot d_i that
 * is not clearly positive (d_i <= kPivotFloor * a_ii, or a_ii <= 0) is a
 * breakdown: the matrix is (numerically) semi-definite or indefinite, and
 * the caller falls back to a least-squares solve.
 *
 * Order of the sums. Each u_ij is a_ij minus a four-lane dot product (term
 * k of the sum in partial sum k mod 4, the remainder in the first). The
 * forward solve's unknown y_i is rhs_i minus the same four-lane dot over
 * every term but the last, then minus the last, l_i,i-1 y_{i-1}; the
 * backward solve subtracts each solved unknown from the rows above it.
 * Both are recurrences: the last term of each sum was computed a moment
 * before, so what bounds their speed is the chain from that term to the
 * result, which these orders keep short; the eight-lane reductions of the
 * platform kernels (engine/platform/kernels.h) lengthen it, and measured
 * slower on every backend (docs/NOTES.md, "Envelope recurrences"). The
 * same code, and so the same bits, on every backend.
 *
 * Nothing here allocates. */
#ifndef KARMA_KEA_ENVELOPE_LDLT_H
#define KARMA_KEA_ENVELOPE_LDLT_H

#include "MePrecision.h"

#include <span>
#include <vector>

namespace karma::kea::detail {

/* A pivot below this fraction of its original diagonal entry is a breakdown
 * (the row is, to rounding, a combination of the rows before it). */
inline constexpr MeReal kPivotFloor = 64 * ME_REAL_EPSILON;

/* Factorises the m x m envelope matrix (first, start, value as above) in
 * place: value then holds L below the diagonal and D on it. Returns false
 * on breakdown (value is then partly overwritten).
 *
 * Row i of the factor depends on rows 0..i of the matrix only (Crout, row
 * by row). With fromRow > 0, rows 0..fromRow-1 of value must already hold
 * the factor of the same leading block (not broken down) and only rows
 * fromRow.. are factorised: the result is the same, bit for bit, as the
 * whole factorisation's. */
bool EnvelopeLdltFactor(int m, std::span<const int> first, std::span<const int> start, std::span<MeReal> value,
                        int fromRow = 0);

/* Solves L D L^T x = rhs with a factor from EnvelopeLdltFactor; x holds rhs
 * on entry and the solution on return (m values). */
void EnvelopeLdltSolve(int m, std::span<const int> first, std::span<const int> start, std::span<const MeReal> value,
                       std::span<MeReal> x);

/* A symmetric system solved through the envelope LDL^T, its arrays kept
 * from one solve to the next (they only grow). Use:
 *     begin(m); first[i] = ...; layout();  value[at(i, j)] = a_ij (j <= i);
 *     factor();  solve(rhs -> x)  (as many right-hand sides as needed)
 * When the factorisation breaks down, solve() falls back to a least-squares
 * solve (complete orthogonal decomposition, Eigen) of the original matrix:
 * the minimum-norm solution for a singular block, the exact one for an
 * indefinite but regular one. That rare path allocates. */
struct EnvelopeSystem {
  int m = 0;
  std::vector<int> first, start;
  std::vector<MeReal> value, original;
  bool factored = false; /* factor() ran on the current matrix */
  bool broken = false;   /* ... and broke down */

  /* Capacity for matrices of up to `rows` rows and `entries` envelope
   * entries (then begin/layout/factor allocate nothing). */
  void reserve(std::size_t rows, std::size_t entries);
  /* A new m x m matrix: first[] sized m (filled with 0 = dense rows). */
  void begin(int rows);
  /* Computes start[] from first[] and zeroes the envelope from row fromRow
   * on (rows before it keep their values: see factor). */
  void layout(int fromRow = 0);
  /* Index of entry (i, j), first[i] <= j <= i, in value. */
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(start[static_cast<std::size_t>(i)] + j - first[static_cast<std::size_t>(i)]);
  }
  /* Number of stored entries (the envelope's size). */
  std::size_t size() const { return static_cast<std::size_t>(start[static_cast<std::size_t>(m)]); }
  /* Factorises the matrix. With fromRow > 0, rows 0..fromRow-1 must be
   * those of the last factor(), which did not break down, of a matrix with
   * the same leading block and layout: they are kept, and the rest is
   * factorised (EnvelopeLdltFactor). */
  void factor(int fromRow = 0);
  /* x = A^-1 rhs (m values each; x must not alias rhs). */
  void solve(std::span<const MeReal> rhs, std::span<MeReal> x) const;
};

}  // namespace karma::kea::detail

#endif
