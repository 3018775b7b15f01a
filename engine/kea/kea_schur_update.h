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
 * C is nonsingular exactly when (A + eps I)_FF is: its symmetric part is
 * diag(P, N), P the Schur complement of B in the extended block and
 * N = (B^-1)_RR (positive definite). A free set whose block is singular
 * (eps = 0 and a freed row that repeats free ones: redundant contacts)
 * makes P singular. C is factorised by LU with partial pivoting after a
 * symmetric scaling that gives its diagonal the units of 1: the added rows
 * by 1 / sqrt((A + eps I)_ss), the removed ones by 1 / sqrt(N_tt). A
 * scaled pivot at or below kUpdatePivotFloor (1/1024, far above
 * DenseLdlt's breakdown rule: a nearly singular change is left to a
 * factorisation, kea_schur_update.cpp), or a non-finite one, makes
 * prepare() fail and the caller factorise the block, which then breaks
 * down or not by its own rule.
 *
 * Cost, m0 = |F0|: prepare() makes k solves with B, |S| columns of A and
 * about k^2 m0 multiply-adds; each solve() one solve with B and about
 * 2 k m0. A dense refactorisation costs m^3 / 6, so the update pays for a
 * k small against m (kMaxRows). The answer is a fresh factorisation's up
 * to rounding, not bit for bit; an ill-conditioned B makes the correction
 * W z cancel digits, which the caller refines (SparseBackend::refine).
 *
 * Nothing allocates once reserve() has covered the problem and kMaxRows. */
#ifndef KARMA_KEA_SCHUR_UPDATE_H
#define KARMA_KEA_SCHUR_UPDATE_H

#include "MePrecision.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace karma::kea::detail {

class SchurUpdate {
 public:
  /* The most rows (added and removed) an update takes. */
  static constexpr int kMaxRows = 8;

  /* Room for problems of n rows and bases of up to `baseRows` rows. */
  void reserve(std::size_t n, std::size_t baseRows);

  /* Prepares the solve of the free rows `free` (ascending) of a problem of
   * n rows from the factor of the rows `base` (in its order), with eps on
   * the diagonal. column(row, position, out) writes, for each entry (row,
   * c) of A, A_row,c to out[position[c]] where position[c] >= 0 (A
   * symmetric: row `row` is column `row`); solveBase(in, out) solves with B
   * (m0 values, out may alias in). False when the free rows are the
   * base's, keep none of its rows, differ from them by more than maxRows
   * (at most kMaxRows) rows, or C breaks down; nothing is prepared then (order() may have
   * changed). */
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
  /* Sorts the free rows into kept (order_, keptAt_), added (the end of
   * order_) and removed (removedAt_) against basePosition_; k. */
  std::size_t classify(std::span<const int> base, std::span<const int> free);
  /* C from A_SS (the added rows' block of A + eps I, already in c_), aS_
   * and w_; its scale_. False when a diagonal it scales by is not
   * positive. */
  bool buildCapacitance();
  /* Scaled C = L U with the row interchanges in pivot_; false on
   * breakdown. */
  bool factorCapacitance();
  /* d <- C^-1 d. */
  void solveCapacitance(std::vector<MeReal> &d) const;
  MeReal dotBase(const MeReal *a, const MeReal *b) const;

  std::size_t m0_ = 0, added_ = 0, k_ = 0;
  std::vector<int> order_;
  std::vector<int> keptAt_;                       /* base position of order_[a], a < |K| */
  std::vector<int> removedAt_;                    /* base positions of the removed rows */
  std::vector<int> basePosition_, addedPosition_; /* by row, -1 elsewhere */
  std::vector<unsigned char> kept_;               /* by base position */
  std::vector<MeReal> aS_;                        /* |S| x m0: row j = A_{s_j, F0} */
  std::vector<MeReal> w_;                         /* k columns of m0: W */
  std::vector<MeReal> c_;                         /* k x k, row-major: C, then its scaled LU */
  std::vector<MeReal> scale_;                     /* C's symmetric scaling, k */
  std::vector<int> pivot_;
  mutable std::vector<MeReal> y_, d_;
};

template <class Column, class SolveBase>
bool SchurUpdate::prepare(std::span<const int> base, std::span<const int> free, std::size_t n, MeReal eps, int maxRows,
                          Column column, SolveBase solveBase) {
  const std::size_t m0 = base.size();
  basePosition_.resize(n, -1);
  addedPosition_.resize(n, -1);
  for (std::size_t i = 0; i < m0; ++i) basePosition_[static_cast<std::size_t>(base[i])] = static_cast<int>(i);
  const std::size_t k = classify(base, free);
  const std::size_t keptCount = keptAt_.size(), added = order_.size() - keptCount;
  const auto limit = static_cast<std::size_t>(std::clamp(maxRows, 0, kMaxRows));
  const bool takes = k > 0 && k <= limit && keptCount > 0;
  if (takes) {
    m0_ = m0;
    added_ = added;
    k_ = k;
    /* A_SF0 by rows and W = B^-1 [A_F0S  E_R] by columns; then the added
     * rows' block of A + eps I into C's leading block. */
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
    c_.assign(k * k, MeReal(0));
    for (std::size_t j = 0; j < added; ++j) {
      column(order_[keptCount + j], std::span<const int>(addedPosition_), std::span<MeReal>(c_.data() + j * k, added));
      c_[j * k + j] += eps;
    }
  }
  for (int r : base) basePosition_[static_cast<std::size_t>(r)] = -1;
  for (std::size_t j = 0; j < added; ++j) addedPosition_[static_cast<std::size_t>(order_[keptCount + j])] = -1;
  return takes && buildCapacitance() && factorCapacitance();
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
  solveCapacitance(d_); /* z, unscaled */
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
