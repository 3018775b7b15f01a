/* kea_schur_update.h: a solve with a free block that differs by a few rows
 * from the block a kept factorisation was made for, without refactorising
 * (not installed).
 *
 * Let B = (A + eps I)_F0F0 be factorised (the base; F0 its rows in the
 * factor's order) and F the current free rows: K = F and F0 (kept), S = F
 * minus F0 (added), R = F0 minus F (removed), k = |S| + |R|. The block
 * system (A + eps I)_FF x = r is solved through B and a k x k capacitance
 * matrix, the Schur-complement method of active-set quadratic programming
 * (Gill, Murray, Saunders & Wright, "A Schur-complement method for sparse
 * quadratic programming", 1990; Bartlett & Biegler, "QPSchur", 2006):
 *
 *   the base system is extended by the added rows, and the removed rows'
 *   unknowns are held at zero by multipliers mu (E_R: their unit columns):
 *       B y + A_F0S x_S + E_R mu = r~            (r~ = r on K, 0 on R)
 *       A_SF0 y + (A + eps I)_SS x_S = r_S
 *       E_R^T y = 0.
 *   With W = B^-1 [A_F0S  E_R] (k solves with B, once per free set) and
 *   y0 = B^-1 r~ (one per right-hand side), y = y0 - W z for z = (x_S, mu),
 *   and z solves C z = d:
 *       C = [ (A + eps I)_SS - A_SF0 W_S    -A_SF0 W_R ]   d = [ r_S - A_SF0 y0 ]
 *           [ W_S(R, :)                     W_R(R, :)  ]       [ y0(R)          ]
 *   (A_SF0 W_R = W_S(R, :)^T, since B is symmetric). Then x_K = y(K) and
 *   x_S is z's first part.
 *
 * The symmetric part of C is diag(P, N): P the Schur complement of B in
 * the extended block (positive definite when (A + eps I)_F0+S is) and
 * N = (B^-1)_RR (positive definite), so C is nonsingular. It is
 * factorised by LU with partial pivoting; a pivot at or below
 * kPivotFloor times C's largest entry, or a non-finite one, makes
 * prepare() fail and the caller refactorise.
 *
 * Cost, m0 = |F0|: prepare() makes k solves with B, |S| columns of A and
 * about k^2 m0 multiply-adds; each solve() one solve with B and about
 * 2 k m0. A dense refactorisation costs m^3 / 6, so the update pays for a
 * k small against m (kMaxRows). The answer is the same as a fresh
 * factorisation's up to rounding, not bit for bit.
 *
 * Nothing allocates once reserve() has covered the problem and kMaxRows. */
#ifndef KARMA_KEA_SCHUR_UPDATE_H
#define KARMA_KEA_SCHUR_UPDATE_H

#include "MePrecision.h"

#include <cstddef>
#include <span>
#include <vector>

namespace karma::kea::detail {

class SchurUpdate {
 public:
  /* The most rows (added and removed) an update takes by default. */
  static constexpr int kMaxRows = 8;

  /* Room for problems of n rows and bases of up to `baseRows` rows. */
  void reserve(std::size_t n, std::size_t baseRows);

  /* Prepares the solve of the free rows `free` (ascending) of a problem of
   * n rows from the factor of the rows `base` (in its order), with eps on
   * the diagonal. column(row, position, out) writes, for each entry (row,
   * c) of A, A_row,c to out[position[c]] where position[c] >= 0 (A
   * symmetric: row `row` is column `row`); solveBase(in, out) solves with B
   * (m0 values, out may alias in). False, and nothing prepared, when the
   * free rows are the base's, differ from them by more than maxRows rows,
   * or C breaks down. */
  template <class Column, class SolveBase>
  bool prepare(std::span<const int> base, std::span<const int> free, std::size_t n, MeReal eps, int maxRows,
               Column column, SolveBase solveBase);

  /* The free rows in the order solve() takes and gives them: the kept rows
   * in the base's order, then the added rows ascending. */
  const std::vector<int> &order() const { return order_; }

  /* x = (A + eps I)_FF^-1 rhs, both in order() (x must not alias rhs). */
  template <class SolveBase>
  void solve(std::span<const MeReal> rhs, std::span<MeReal> x, SolveBase solveBase) const;

 private:
  /* C = L U with the row interchanges in pivot_; false on breakdown. */
  bool factorCapacitance();
  /* d <- C^-1 d. */
  void solveCapacitance(std::vector<MeReal> &d) const;
  MeReal dotBase(const MeReal *a, const MeReal *b) const;

  std::size_t m0_ = 0, added_ = 0, k_ = 0;
  std::vector<int> order_;
  std::vector<int> keptAt_;    /* base position of order_[a], a < |K| */
  std::vector<int> removedAt_; /* base positions of the removed rows */
  std::vector<int> basePosition_, addedPosition_; /* by row, -1 elsewhere */
  std::vector<unsigned char> kept_;               /* by base position */
  std::vector<MeReal> aS_;                        /* |S| x m0: row j = A_{s_j, F0} */
  std::vector<MeReal> w_;                         /* k columns of m0: W */
  std::vector<MeReal> c_;                         /* k x k, row-major: C, then its LU */
  std::vector<int> pivot_;
  mutable std::vector<MeReal> y_, d_;
};

template <class Column, class SolveBase>
bool SchurUpdate::prepare(std::span<const int> base, std::span<const int> free, std::size_t n, MeReal eps,
                          int maxRows, Column column, SolveBase solveBase) {
  const std::size_t m0 = base.size();
  basePosition_.resize(n, -1);
  addedPosition_.resize(n, -1);
  kept_.assign(m0, 0);
  for (std::size_t i = 0; i < m0; ++i) basePosition_[static_cast<std::size_t>(base[i])] = static_cast<int>(i);
  order_.clear();
  std::size_t keptCount = 0, added = 0;
  for (int r : free) {
    const int at = basePosition_[static_cast<std::size_t>(r)];
    if (at >= 0) {
      kept_[static_cast<std::size_t>(at)] = 1;
      ++keptCount;
    } else {
      ++added;
    }
  }
  const std::size_t k = added + (m0 - keptCount);
  if (k == 0 || k > static_cast<std::size_t>(maxRows) || keptCount == 0) {
    for (int r : base) basePosition_[static_cast<std::size_t>(r)] = -1;
    return false;
  }
  m0_ = m0;
  added_ = added;
  k_ = k;
  keptAt_.clear();
  removedAt_.clear();
  for (std::size_t i = 0; i < m0; ++i) {
    if (kept_[i]) {
      order_.push_back(base[i]);
      keptAt_.push_back(static_cast<int>(i));
    } else {
      removedAt_.push_back(static_cast<int>(i));
    }
  }
  for (int r : free)
    if (basePosition_[static_cast<std::size_t>(r)] < 0) {
      addedPosition_[static_cast<std::size_t>(r)] = static_cast<int>(order_.size() - keptCount);
      order_.push_back(r);
    }
  /* A_{S F0} by rows, then W = B^-1 [A_F0S  E_R] by columns. */
  aS_.assign(added * m0, MeReal(0));
  w_.assign(k * m0, MeReal(0));
  for (std::size_t j = 0; j < added; ++j) {
    const std::span<MeReal> row(aS_.data() + j * m0, m0);
    column(order_[keptCount + j], std::span<const int>(basePosition_), row);
    solveBase(std::span<const MeReal>(row), std::span<MeReal>(w_.data() + j * m0, m0));
  }
  for (std::size_t t = 0; t < removedAt_.size(); ++t) {
    MeReal *wt = w_.data() + (added + t) * m0;
    wt[removedAt_[t]] = 1;
    solveBase(std::span<const MeReal>(wt, m0), std::span<MeReal>(wt, m0));
  }
  /* C: the added rows' block of A (its diagonal plus eps) less A_SF0 W,
   * then the removed rows' entries of W. */
  c_.assign(k * k, MeReal(0));
  for (std::size_t j = 0; j < added; ++j) {
    column(order_[keptCount + j], std::span<const int>(addedPosition_), std::span<MeReal>(c_.data() + j * k, added));
    c_[j * k + j] += eps;
    for (std::size_t c = 0; c < k; ++c) c_[j * k + c] -= dotBase(aS_.data() + j * m0, w_.data() + c * m0);
  }
  for (std::size_t t = 0; t < removedAt_.size(); ++t)
    for (std::size_t c = 0; c < k; ++c)
      c_[(added + t) * k + c] = w_[c * m0 + static_cast<std::size_t>(removedAt_[t])];
  for (int r : base) basePosition_[static_cast<std::size_t>(r)] = -1;
  for (std::size_t j = 0; j < added; ++j) addedPosition_[static_cast<std::size_t>(order_[keptCount + j])] = -1;
  return factorCapacitance();
}

template <class SolveBase>
void SchurUpdate::solve(std::span<const MeReal> rhs, std::span<MeReal> x, SolveBase solveBase) const {
  const std::size_t keptCount = keptAt_.size();
  y_.assign(m0_, MeReal(0));
  for (std::size_t a = 0; a < keptCount; ++a) y_[static_cast<std::size_t>(keptAt_[a])] = rhs[a];
  solveBase(std::span<const MeReal>(y_), std::span<MeReal>(y_));
  d_.resize(k_);
  for (std::size_t j = 0; j < added_; ++j) d_[j] = rhs[keptCount + j] - dotBase(aS_.data() + j * m0_, y_.data());
  for (std::size_t t = 0; t < removedAt_.size(); ++t) d_[added_ + t] = y_[static_cast<std::size_t>(removedAt_[t])];
  solveCapacitance(d_);
  for (std::size_t c = 0; c < k_; ++c) {
    const MeReal zc = d_[c];
    const MeReal *wc = w_.data() + c * m0_;
    for (std::size_t i = 0; i < m0_; ++i) y_[i] -= wc[i] * zc;
  }
  for (std::size_t a = 0; a < keptCount; ++a) x[a] = y_[static_cast<std::size_t>(keptAt_[a])];
  for (std::size_t j = 0; j < added_; ++j) x[keptCount + j] = d_[j];
}

}  // namespace karma::kea::detail

#endif
