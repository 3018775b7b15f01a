/* kea_friction_coupling.h: the exact friction step of the active-set core
 * for a fixed active set (not installed).
 *
 * After a consistent inner solve, a friction row i clamped at a bound of
 * its box sits at sigma_i mu_i lambda_j(old) (sigma = -1 at lo, +1 at hi),
 * the normal impulse of the solve before; when its normal row j is free,
 * lambda_j has moved, and the plain fixed point re-solves with the bound
 * updated, converging linearly (several rounds for sliding contacts). With
 * the sets fixed the coupled problem is linear, and is solved here in one
 * step with the factorisation already made:
 *
 *   Tied rows T (clamped friction rows with a free normal), c_t = sigma mu.
 *   Changing lambda_T by delta changes the free rows by -Z delta, where
 *   Z = (A_FF)^-1 A_FT (one solve with the factor per tied row). The tie
 *   lambda_i + delta_t = c_t (lambda_j - (Z delta)_j) for every t gives the
 *   k x k system
 *       (I + C P Z) delta = g,   g_t = c_t lambda_j - lambda_i,
 *   (P picks row j_t of Z), the Sherman-Morrison-Woodbury form of the
 *   non-symmetric system in which the tied rows follow their normals. It is
 *   solved by Gaussian elimination with partial pivoting; then
 *   lambda_F -= Z delta, lambda_T += delta.
 *
 * A Backend supplies, besides the core's operations (kea_activeset_core.h):
 *   std::span<const int> factorRows();  the free rows in the factor's order
 *       (empty when no factorisation of the current free set is kept);
 *   void solveWithFactor(std::span<const MeReal> rhs, std::span<MeReal> x);
 *   void column(int row, std::span<const int> position, std::span<MeReal> out);
 *       out[position[c]] = A(row, c) for every c with position[c] >= 0
 *       (out zeroed by the caller).
 * Nothing here allocates once the scratch has grown. */
#ifndef KARMA_KEA_FRICTION_COUPLING_H
#define KARMA_KEA_FRICTION_COUPLING_H

#include "kea_internal.h"

#include <cmath>
#include <span>
#include <vector>

namespace karma::kea::detail {

/* The arrays of the coupled friction step. */
struct CouplingScratch {
  std::vector<int> position, tiedRow, tiedNormal;
  std::vector<MeReal> coef, gap, z, column, work, schur;
};

/* Most tied rows handled by one coupled step (k solves with the factor and
 * a k x k elimination); with more, the plain fixed point is cheaper. */
inline constexpr std::size_t kMaxTiedRows = 24;

/* Room for a coupled step on a problem of n rows (then it allocates
 * nothing). */
inline void ReserveCoupling(std::size_t n, CouplingScratch &s) {
  s.position.reserve(n);
  s.tiedRow.reserve(kMaxTiedRows);
  s.tiedNormal.reserve(kMaxTiedRows);
  s.coef.reserve(kMaxTiedRows);
  s.gap.reserve(kMaxTiedRows);
  s.z.reserve(n * kMaxTiedRows);
  s.column.reserve(n);
  s.work.reserve(n);
  s.schur.reserve(kMaxTiedRows * kMaxTiedRows);
}

/* Solves the k x k system m x = g in place (m row-major, g -> x) by
 * Gaussian elimination with partial pivoting; false when a pivot is zero or
 * not finite. */
inline bool SolveSmallDense(std::size_t k, std::vector<MeReal> &m, std::vector<MeReal> &g) {
  for (std::size_t col = 0; col < k; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < k; ++r)
      if (std::fabs(m[r * k + col]) > std::fabs(m[pivot * k + col])) pivot = r;
    const MeReal d = m[pivot * k + col];
    if (!(std::fabs(d) > 0) || !std::isfinite(d)) return false;
    if (pivot != col) {
      for (std::size_t c = 0; c < k; ++c) std::swap(m[pivot * k + c], m[col * k + c]);
      std::swap(g[pivot], g[col]);
    }
    for (std::size_t r = col + 1; r < k; ++r) {
      const MeReal f = m[r * k + col] / d;
      if (f == 0) continue;
      for (std::size_t c = col; c < k; ++c) m[r * k + c] -= f * m[col * k + c];
      g[r] -= f * g[col];
    }
  }
  for (std::size_t r = k; r-- > 0;) {
    MeReal v = g[r];
    for (std::size_t c = r + 1; c < k; ++c) v -= m[r * k + c] * g[c];
    g[r] = v / m[r * k + r];
  }
  return true;
}

/* The coupled friction step on lambda for the sets `set` (see above),
 * after first moving the clamped friction rows whose normal is clamped to
 * their (known) new bounds. Returns false when it does not apply (no kept
 * factorisation, nothing to move, more than kMaxTiedRows tied rows, a
 * singular k x k system); lambda may then have been partly updated, and
 * the caller restores it. */
template <class Backend>
bool CoupleFriction(const RowView &p, const std::vector<unsigned char> &set, Backend &backend, CouplingScratch &s,
                    std::vector<MeReal> &lambda) {
  const auto n = static_cast<std::size_t>(p.n);
  const std::span<const int> rows = backend.factorRows();
  const std::size_t m = rows.size();
  if (m == 0 || p.findex.empty()) return false;
  s.position.assign(n, -1);
  for (std::size_t a = 0; a < m; ++a) s.position[static_cast<std::size_t>(rows[a])] = static_cast<int>(a);
  /* First the clamped friction rows whose normal is clamped too: their new
   * bound is known, sigma mu max(lambda_j, 0); moving them there by d
   * moves the free rows by -(A_FF)^-1 A_FD d (one solve for all). */
  s.column.assign(m, MeReal(0));
  s.work.resize(m);
  bool fixedMoves = false;
  for (std::size_t i = 0; i < n; ++i) {
    const int j = p.findex[i];
    if (j < 0 || set[i] == 0 /* Free */ || s.position[static_cast<std::size_t>(j)] >= 0) continue;
    const MeReal bound =
        (set[i] == 1 /* AtLo */ ? -1 : 1) * p.mu[i] * std::max(lambda[static_cast<std::size_t>(j)], MeReal(0));
    const MeReal d = bound - lambda[i];
    if (d == 0) continue;
    std::fill(s.work.begin(), s.work.end(), MeReal(0));
    backend.column(static_cast<int>(i), s.position, s.work);
    for (std::size_t a = 0; a < m; ++a) s.column[a] += d * s.work[a];
    lambda[i] = bound;
    fixedMoves = true;
  }
  if (fixedMoves) {
    backend.solveWithFactor(s.column, s.work);
    for (std::size_t a = 0; a < m; ++a) lambda[static_cast<std::size_t>(rows[a])] -= s.work[a];
  }

  s.tiedRow.clear();
  s.tiedNormal.clear();
  s.coef.clear();
  s.gap.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const int j = p.findex[i];
    if (j < 0 || set[i] == 0 /* Free */ || s.position[static_cast<std::size_t>(j)] < 0) continue;
    if (s.tiedRow.size() == kMaxTiedRows) return false;
    const MeReal c = (set[i] == 1 /* AtLo */ ? -1 : 1) * p.mu[i];
    s.tiedRow.push_back(static_cast<int>(i));
    s.tiedNormal.push_back(j);
    s.coef.push_back(c);
    s.gap.push_back(c * lambda[static_cast<std::size_t>(j)] - lambda[i]);
  }
  const std::size_t k = s.tiedRow.size();
  if (k == 0) return fixedMoves;

  /* Z, column t = (A_FF)^-1 A_F,i_t, column-major m x k. */
  s.z.resize(m * k);
  s.column.resize(m);
  for (std::size_t t = 0; t < k; ++t) {
    std::fill(s.column.begin(), s.column.end(), MeReal(0));
    backend.column(s.tiedRow[t], s.position, s.column);
    backend.solveWithFactor(s.column, std::span<MeReal>(s.z.data() + t * m, m));
  }
  /* I + C P Z, row-major k x k. */
  s.schur.assign(k * k, MeReal(0));
  for (std::size_t t = 0; t < k; ++t) {
    const auto pj = static_cast<std::size_t>(s.position[static_cast<std::size_t>(s.tiedNormal[t])]);
    for (std::size_t u = 0; u < k; ++u) s.schur[t * k + u] = s.coef[t] * s.z[u * m + pj];
    s.schur[t * k + t] += 1;
  }
  if (!SolveSmallDense(k, s.schur, s.gap)) return false; /* gap now holds delta */
  for (std::size_t t = 0; t < k; ++t) {
    const MeReal delta = s.gap[t];
    const MeReal *zt = s.z.data() + t * m;
    for (std::size_t a = 0; a < m; ++a) lambda[static_cast<std::size_t>(rows[a])] -= zt[a] * delta;
  }
  for (std::size_t t = 0; t < k; ++t) lambda[static_cast<std::size_t>(s.tiedRow[t])] += s.gap[t];
  return true;
}

}  // namespace karma::kea::detail

#endif
