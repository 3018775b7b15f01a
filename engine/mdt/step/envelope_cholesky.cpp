// envelope_cholesky.cpp: see envelope_cholesky.h. Row by row (the
// "bordered" form): for j < i, L_ij = (K_ij - sum_k L_ik L_jk) / L_jj over
// k from max(first[i], first[j]) to j - 1, then L_ii = sqrt(K_ii - sum_k L_ik^2).
#include "envelope_cholesky.h"

#include <algorithm>
#include <cmath>

namespace karma::mdt {

namespace {
constexpr MeReal kPivotFloor = 64 * ME_REAL_EPSILON;
}  // namespace

bool envelopeCholesky(EnvelopeMatrix &K) {
  const int n = K.size();
  for (int i = 0; i < n; ++i) {
    const int fi = K.first[(size_t)i];
    for (int j = fi; j <= i; ++j) {
      const MeReal kij = K.at(i, j);
      MeReal s = kij;
      for (int k = std::max(fi, K.first[(size_t)j]); k < j; ++k) s -= K.at(i, k) * K.at(j, k);
      if (j < i) {
        K.at(i, j) = s / K.at(j, j);
      } else {
        if (!(kij > 0) || !(s > kPivotFloor * kij) || !std::isfinite(s)) return false;
        K.at(i, i) = std::sqrt(s);
      }
    }
  }
  return true;
}

void envelopeCholeskySolve(EnvelopeMatrix &L, std::span<MeReal> b) {
  const int n = L.size();
  for (int i = 0; i < n; ++i) {  // L y = b
    MeReal s = b[(size_t)i];
    for (int k = L.first[(size_t)i]; k < i; ++k) s -= L.at(i, k) * b[(size_t)k];
    b[(size_t)i] = s / L.at(i, i);
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T x = y, column by column
    b[(size_t)i] /= L.at(i, i);
    for (int k = L.first[(size_t)i]; k < i; ++k) b[(size_t)k] -= L.at(i, k) * b[(size_t)i];
  }
}

}  // namespace karma::mdt
