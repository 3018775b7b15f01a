/* kea_schur_update.cpp: the capacitance matrix's LU and the helpers of the
 * Schur-complement update (see kea_schur_update.h). */
#include "kea_schur_update.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace karma::kea::detail {

namespace {

/* A pivot of C at or below this times C's largest entry is a breakdown. */
constexpr MeReal kPivotFloor = 64 * ME_REAL_EPSILON;

}  // namespace

void SchurUpdate::reserve(std::size_t n, std::size_t baseRows) {
  const auto k = static_cast<std::size_t>(kMaxRows);
  basePosition_.reserve(n);
  addedPosition_.reserve(n);
  order_.reserve(baseRows + k);
  keptAt_.reserve(baseRows);
  removedAt_.reserve(k);
  kept_.reserve(baseRows);
  aS_.reserve(k * baseRows);
  w_.reserve(k * baseRows);
  c_.reserve(k * k);
  pivot_.reserve(k);
  y_.reserve(baseRows);
  d_.reserve(k);
}

MeReal SchurUpdate::dotBase(const MeReal *a, const MeReal *b) const {
  MeReal sum = 0;
  for (std::size_t i = 0; i < m0_; ++i) sum += a[i] * b[i];
  return sum;
}

/* Doolittle LU with partial pivoting (Golub & Van Loan, sec. 3.4), in
 * place: below the diagonal L's multipliers, on and above it U. */
bool SchurUpdate::factorCapacitance() {
  const std::size_t k = k_;
  MeReal largest = 0;
  for (MeReal v : c_) {
    if (!std::isfinite(v)) return false;
    largest = std::max(largest, std::fabs(v));
  }
  const MeReal floor = kPivotFloor * largest;
  pivot_.resize(k);
  for (std::size_t col = 0; col < k; ++col) {
    std::size_t best = col;
    for (std::size_t r = col + 1; r < k; ++r)
      if (std::fabs(c_[r * k + col]) > std::fabs(c_[best * k + col])) best = r;
    pivot_[col] = static_cast<int>(best);
    if (best != col)
      for (std::size_t c = 0; c < k; ++c) std::swap(c_[col * k + c], c_[best * k + c]);
    const MeReal p = c_[col * k + col];
    if (!(std::fabs(p) > floor)) return false;
    for (std::size_t r = col + 1; r < k; ++r) {
      const MeReal l = c_[r * k + col] / p;
      c_[r * k + col] = l;
      for (std::size_t c = col + 1; c < k; ++c) c_[r * k + c] -= l * c_[col * k + c];
    }
  }
  return true;
}

void SchurUpdate::solveCapacitance(std::vector<MeReal> &d) const {
  const std::size_t k = k_;
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
}

}  // namespace karma::kea::detail
