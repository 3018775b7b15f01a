/* kea_envelope_ldlt.cpp: the envelope LDL^T (see kea_envelope_ldlt.h). */
#include "kea_envelope_ldlt.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace karma::kea::detail {
namespace {

/* sum_k a[k] b[k] in four interleaved partial sums, term k in sum k mod 4
 * for the whole groups of four, the rest of the terms in sum 0, combined
 * as (s0 + s1) + (s2 + s3). Short sums whose last term was computed a
 * moment ago are what the factorisation is made of: a few partial sums
 * keep the chain from that term to the result short (docs/NOTES.md,
 * "Envelope recurrences"). */
[[gnu::always_inline]] inline MeReal Dot4(const MeReal *a, const MeReal *b, int count) {
  MeReal s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < count; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

/* y[k] -= a[k] s, k < count. */
void SubtractScaled(MeReal *__restrict y, const MeReal *__restrict a, MeReal s, int count) {
  for (int k = 0; k < count; ++k) y[k] -= a[k] * s;
}

/* y[k] = (y[k] - a0[k] s0) - a1[k] s1, k < count: each element rounded
 * as by SubtractScaled with a0 and then with a1. */
void SubtractTwoScaled(MeReal *__restrict y, const MeReal *__restrict a0, MeReal s0, const MeReal *__restrict a1,
                       MeReal s1, int count) {
  for (int k = 0; k < count; ++k) y[k] = (y[k] - a0[k] * s0) - a1[k] * s1;
}

}  // namespace

bool EnvelopeLdltFactor(int m, std::span<const int> first, std::span<const int> start, std::span<MeReal> value,
                        int fromRow) {
  for (int i = fromRow; i < m; ++i) {
    const int fi = first[static_cast<std::size_t>(i)];
    MeReal *rowI = value.data() + start[static_cast<std::size_t>(i)]; /* rowI[j - fi] = entry (i, j) */
    /* u_ij = a_ij - sum_{k in both envelopes, k < j} u_ik l_jk */
    for (int j = fi; j < i; ++j) {
      const int fj = first[static_cast<std::size_t>(j)];
      const MeReal *rowJ = value.data() + start[static_cast<std::size_t>(j)];
      const int k0 = std::max(fi, fj);
      rowI[j - fi] -= Dot4(rowI + (k0 - fi), rowJ + (k0 - fj), j - k0);
    }
    /* l_ij = u_ij / d_j and d_i = a_ii - sum_j u_ij l_ij */
    const MeReal aii = rowI[i - fi];
    MeReal d = aii;
    for (int j = fi; j < i; ++j) {
      const MeReal dj = value[static_cast<std::size_t>(start[static_cast<std::size_t>(j + 1)] - 1)];
      const MeReal u = rowI[j - fi];
      const MeReal l = u / dj;
      rowI[j - fi] = l;
      d -= u * l;
    }
    if (!(aii > 0) || !(d > kPivotFloor * aii)) return false;
    rowI[i - fi] = d;
  }
  return true;
}

void EnvelopeLdltSolve(int m, std::span<const int> first, std::span<const int> start, std::span<const MeReal> value,
                       std::span<MeReal> x) {
  /* L y = rhs, row by row: y_i = (rhs_i - sum_{fi <= k < i-1} l_ik y_k) -
   * l_i,i-1 y_{i-1}, the sum in Dot4's partial sums. Only the last term
   * waits for the row before, so the chain from y_{i-1} to y_i is one
   * product and one difference; the rest of the sum runs ahead of it. */
  for (int i = 0; i < m; ++i) {
    const int fi = first[static_cast<std::size_t>(i)];
    if (fi == i) continue;
    const MeReal *rowI = value.data() + start[static_cast<std::size_t>(i)];
    const MeReal ahead = x[static_cast<std::size_t>(i)] - Dot4(rowI, x.data() + fi, i - 1 - fi);
    x[static_cast<std::size_t>(i)] = ahead - rowI[i - 1 - fi] * x[static_cast<std::size_t>(i) - 1];
  }
  /* D z = y */
  for (int i = 0; i < m; ++i)
    x[static_cast<std::size_t>(i)] /= value[static_cast<std::size_t>(start[static_cast<std::size_t>(i + 1)] - 1)];
  /* L^T x = z, by rows of L from the bottom: x_i is final once the rows
   * below it have been subtracted. Rows i and b = i - 1 go in one pass:
   * x_b first receives row i's term, then every x_k, k < b, that both rows
   * reach receives row i's term and row b's, in that order, as two passes
   * would; where only one row reaches, its term alone. */
  int i = m - 1;
  while (i > 0) {
    const int fi = first[static_cast<std::size_t>(i)];
    if (fi == i) { /* nothing left of the diagonal */
      --i;
      continue;
    }
    const MeReal *rowI = value.data() + start[static_cast<std::size_t>(i)];
    const MeReal xi = x[static_cast<std::size_t>(i)];
    const int b = i - 1;
    const int fb = first[static_cast<std::size_t>(b)];
    const MeReal *rowB = value.data() + start[static_cast<std::size_t>(b)];
    const MeReal xb = x[static_cast<std::size_t>(b)] - rowI[b - fi] * xi;
    x[static_cast<std::size_t>(b)] = xb;
    const int both = std::max(fi, fb);
    if (fi < fb)
      SubtractScaled(x.data() + fi, rowI, xi, fb - fi);
    else
      SubtractScaled(x.data() + fb, rowB, xb, fi - fb);
    SubtractTwoScaled(x.data() + both, rowI + (both - fi), xi, rowB + (both - fb), xb, b - both);
    i -= 2; /* rows i and b are done */
  }
}

void EnvelopeSystem::reserve(std::size_t rows, std::size_t entries) {
  first.reserve(rows);
  start.reserve(rows + 1);
  value.reserve(entries);
  original.reserve(entries);
}

void EnvelopeSystem::begin(int rows) {
  m = rows;
  first.assign(static_cast<std::size_t>(m), 0);
  factored = broken = false;
}

void EnvelopeSystem::layout(int fromRow) {
  start.resize(static_cast<std::size_t>(m) + 1);
  start[0] = 0;
  for (int i = 0; i < m; ++i)
    start[static_cast<std::size_t>(i) + 1] =
        start[static_cast<std::size_t>(i)] + i - first[static_cast<std::size_t>(i)] + 1;
  value.resize(size());
  std::fill(value.begin() + start[static_cast<std::size_t>(fromRow)], value.end(), MeReal(0));
  factored = broken = false;
}

void EnvelopeSystem::factor(int fromRow) {
  const auto from = static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(fromRow)]);
  original.resize(size());
  std::copy(value.begin() + from, value.begin() + static_cast<std::ptrdiff_t>(size()), original.begin() + from);
  broken = !EnvelopeLdltFactor(m, first, start, value, fromRow);
  factored = true;
}

void EnvelopeSystem::solve(std::span<const MeReal> rhs, std::span<MeReal> x) const {
  const auto size = static_cast<std::size_t>(m);
  if (!broken) {
    std::copy(rhs.begin(), rhs.begin() + static_cast<std::ptrdiff_t>(size), x.begin());
    EnvelopeLdltSolve(m, first, start, value, x);
    bool finite = true;
    for (std::size_t i = 0; i < size; ++i) finite = finite && std::isfinite(x[i]);
    if (finite) return;
  }
  /* Breakdown: least squares on the original (symmetric) matrix. */
  using Mat = Eigen::Matrix<MeReal, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<MeReal, Eigen::Dynamic, 1>;
  Mat a = Mat::Zero(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = first[static_cast<std::size_t>(i)]; j <= i; ++j) a(i, j) = a(j, i) = original[at(i, j)];
  const Vec b = Eigen::Map<const Vec>(rhs.data(), m);
  const Vec sol = a.completeOrthogonalDecomposition().solve(b);
  for (std::size_t i = 0; i < size; ++i)
    x[i] = std::isfinite(sol(static_cast<Eigen::Index>(i))) ? sol(static_cast<Eigen::Index>(i)) : MeReal(0);
}

}  // namespace karma::kea::detail
