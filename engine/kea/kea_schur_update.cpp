/* kea_schur_update.cpp: the row bookkeeping and the capacitance matrix of
 * the Schur-complement update (see kea_schur_update.h). */
#include "kea_schur_update.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace karma::kea::detail {

namespace {

/* A pivot of the scaled C (its diagonal's units are 1) at or below this
 * refuses the update. A change this close to singular (freed rows that
 * nearly repeat free ones: redundant contacts) leaves the answer's split
 * among those rows to rounding, and the update's split differs from a
 * factorisation's: 1 cm cubes stacked drifted 2.8 mm with DenseLdlt's own
 * floor (64 eps) here and 0.46 mm, as when refactorising, with any floor
 * from 1e-4 up (HardCases.SmallCubesStack). Refusing costs only the
 * factorisation the pivot would have made anyway. */
constexpr MeReal kUpdatePivotFloor = MeReal(1) / 1024;

}  // namespace

void SchurUpdate::reserve(std::size_t n, std::size_t baseRows) {
  const auto k = static_cast<std::size_t>(kMaxRows);
  basePosition_.reserve(n);
  addedPosition_.reserve(n);
  order_.reserve(baseRows + n);
  keptAt_.reserve(baseRows);
  removedAt_.reserve(baseRows);
  kept_.reserve(baseRows);
  aS_.reserve(k * baseRows);
  w_.reserve(k * baseRows);
  c_.reserve(k * k);
  scale_.reserve(k);
  pivot_.reserve(k);
  y_.reserve(baseRows);
  d_.reserve(k);
}

std::size_t SchurUpdate::classify(std::span<const int> base, std::span<const int> free) {
  const std::size_t m0 = base.size();
  kept_.assign(m0, 0);
  order_.clear();
  keptAt_.clear();
  removedAt_.clear();
  std::size_t added = 0;
  for (int r : free) {
    const int at = basePosition_[static_cast<std::size_t>(r)];
    if (at >= 0)
      kept_[static_cast<std::size_t>(at)] = 1;
    else
      ++added;
  }
  for (std::size_t i = 0; i < m0; ++i) {
    if (kept_[i]) {
      order_.push_back(base[i]);
      keptAt_.push_back(static_cast<int>(i));
    } else {
      removedAt_.push_back(static_cast<int>(i));
    }
  }
  const std::size_t k = added + removedAt_.size();
  if (k > static_cast<std::size_t>(kMaxRows)) return k; /* refused: no positions to set */
  for (int r : free)
    if (basePosition_[static_cast<std::size_t>(r)] < 0) {
      addedPosition_[static_cast<std::size_t>(r)] = static_cast<int>(order_.size() - keptAt_.size());
      order_.push_back(r);
    }
  return k;
}

MeReal SchurUpdate::dotBase(const MeReal *a, const MeReal *b) const {
  MeReal sum = 0;
  for (std::size_t i = 0; i < m0_; ++i) sum += a[i] * b[i];
  return sum;
}

bool SchurUpdate::buildCapacitance() {
  const std::size_t k = k_, added = added_, m0 = m0_;
  scale_.resize(k);
  for (std::size_t j = 0; j < added; ++j) scale_[j] = c_[j * k + j]; /* (A + eps I)_ss */
  for (std::size_t j = 0; j < added; ++j)
    for (std::size_t c = 0; c < k; ++c) c_[j * k + c] -= dotBase(aS_.data() + j * m0, w_.data() + c * m0);
  for (std::size_t t = 0; t < removedAt_.size(); ++t)
    for (std::size_t c = 0; c < k; ++c) c_[(added + t) * k + c] = w_[c * m0 + static_cast<std::size_t>(removedAt_[t])];
  for (std::size_t t = 0; t < removedAt_.size(); ++t) scale_[added + t] = c_[(added + t) * k + added + t]; /* N_tt */
  for (MeReal &s : scale_) {
    if (!(s > 0) || !std::isfinite(s)) return false;
    s = MeReal(1) / std::sqrt(s);
  }
  for (std::size_t r = 0; r < k; ++r)
    for (std::size_t c = 0; c < k; ++c) c_[r * k + c] *= scale_[r] * scale_[c];
  return true;
}

/* Doolittle LU with partial pivoting (Golub & Van Loan, sec. 3.4) of the
 * scaled C, in place: below the diagonal L's multipliers, on and above it
 * U. */
bool SchurUpdate::factorCapacitance() {
  const std::size_t k = k_;
  for (MeReal v : c_)
    if (!std::isfinite(v)) return false;
  pivot_.resize(k);
  for (std::size_t col = 0; col < k; ++col) {
    std::size_t best = col;
    for (std::size_t r = col + 1; r < k; ++r)
      if (std::fabs(c_[r * k + col]) > std::fabs(c_[best * k + col])) best = r;
    pivot_[col] = static_cast<int>(best);
    if (best != col)
      for (std::size_t c = 0; c < k; ++c) std::swap(c_[col * k + c], c_[best * k + c]);
    const MeReal p = c_[col * k + col];
    if (!(std::fabs(p) > kUpdatePivotFloor)) return false;
    for (std::size_t r = col + 1; r < k; ++r) {
      const MeReal l = c_[r * k + col] / p;
      c_[r * k + col] = l;
      for (std::size_t c = col + 1; c < k; ++c) c_[r * k + c] -= l * c_[col * k + c];
    }
  }
  return true;
}

/* C z = d as (S C S) (S^-1 z) = S d, S = diag(scale_). */
void SchurUpdate::solveCapacitance(std::vector<MeReal> &d) const {
  const std::size_t k = k_;
  for (std::size_t r = 0; r < k; ++r) d[r] *= scale_[r];
  /* P C = L U, with the rows of L interchanged by every later pivot:
   * P d first, then the unit lower triangle. */
  for (std::size_t col = 0; col < k; ++col) std::swap(d[col], d[static_cast<std::size_t>(pivot_[col])]);
  for (std::size_t col = 0; col < k; ++col)
    for (std::size_t r = col + 1; r < k; ++r) d[r] -= c_[r * k + col] * d[col];
  for (std::size_t r = k; r-- > 0;) {
    MeReal sum = d[r];
    for (std::size_t c = r + 1; c < k; ++c) sum -= c_[r * k + c] * d[c];
    d[r] = sum / c_[r * k + r];
  }
  for (std::size_t r = 0; r < k; ++r) d[r] *= scale_[r];
}

}  // namespace karma::kea::detail
