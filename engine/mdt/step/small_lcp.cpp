// small_lcp.cpp: the small exact LCP of small_lcp.h.
#include "small_lcp.h"

namespace karma::mdt {

namespace {

constexpr int kStride = kSmallLcpMax;

// Solves A_FF x_F = y_F in place (Gaussian elimination without pivoting,
// A being symmetric positive definite), F given by `mask` over k rows.
bool solveSubset(const MeReal *A, int k, unsigned mask, MeReal *y) {
  int idx[kSmallLcpMax], n = 0;
  for (int i = 0; i < k; ++i)
    if (mask & (1u << i)) idx[n++] = i;
  MeReal M[kSmallLcpMax][kSmallLcpMax + 1];
  for (int a = 0; a < n; ++a) {
    for (int c = 0; c < n; ++c) M[a][c] = A[idx[a] * kStride + idx[c]];
    M[a][n] = y[idx[a]];
  }
  for (int a = 0; a < n; ++a) {
    if (!(M[a][a] > 0)) return false;
    for (int r = a + 1; r < n; ++r) {
      const MeReal f = M[r][a] / M[a][a];
      for (int c = a; c <= n; ++c) M[r][c] -= f * M[a][c];
    }
  }
  for (int a = n - 1; a >= 0; --a) {
    MeReal v = M[a][n];
    for (int c = a + 1; c < n; ++c) v -= M[a][c] * y[idx[c]];
    y[idx[a]] = v / M[a][a];
  }
  return true;
}

// x for free set `mask` (clamped rows at lo); false when the elimination
// breaks down.
bool solveSet(const MeReal *A, const MeReal *q, const MeReal *lo, int k, unsigned mask, MeReal *x) {
  for (int i = 0; i < k; ++i) {
    x[i] = q[i];
    if (!(mask & (1u << i))) continue;
    for (int j = 0; j < k; ++j)
      if (!(mask & (1u << j))) x[i] -= A[i * kStride + j] * lo[j];
  }
  for (int i = 0; i < k; ++i)
    if (!(mask & (1u << i))) x[i] = lo[i];
  return solveSubset(A, k, mask, x);
}

// The set each row of solveSet's x wants: a free row stays free while
// x_i >= lo_i, a clamped row stays clamped while w_i >= 0. x fits the LCP
// when this is `mask` itself.
unsigned wantedSet(const MeReal *A, const MeReal *q, const MeReal *lo, int k, unsigned mask, const MeReal *x) {
  unsigned wanted = 0;
  for (int i = 0; i < k; ++i) {
    bool free;
    if (mask & (1u << i)) {
      free = x[i] >= lo[i];
    } else {
      MeReal wi = -q[i];
      for (int j = 0; j < k; ++j) wi += A[i * kStride + j] * x[j];
      free = !(wi >= 0);
    }
    wanted |= free ? 1u << i : 0u;
  }
  return wanted;
}

// x for free set `mask`; true if it fits the LCP.
bool trySet(const MeReal *A, const MeReal *q, const MeReal *lo, int k, unsigned mask, MeReal *x) {
  return solveSet(A, q, lo, k, mask, x) && wantedSet(A, q, lo, k, mask, x) == mask;
}

// The free rows of each set of at most kSmallLcpMax rows.
constexpr unsigned char kFreeRows[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
static_assert(kSmallLcpMax <= 4);

// The sets after the full one, in SolveSmallLcp's order.
bool tryPartialSets(const MeReal *A, const MeReal *q, const MeReal *lo, int k, MeReal *x) {
  const unsigned all = (1u << k) - 1;
  for (int freeCount = k - 1; freeCount >= 0; --freeCount) {
    for (unsigned mask = all;; --mask) {
      if (kFreeRows[mask] == freeCount && trySet(A, q, lo, k, mask, x)) return true;
      if (mask == 0) break;
    }
  }
  return false;
}

}  // namespace

bool SolveSmallLcp(const MeReal *A, const MeReal *q, const MeReal *lo, int k, MeReal *x) {
  if (trySet(A, q, lo, k, (1u << k) - 1, x)) return true;
  return tryPartialSets(A, q, lo, k, x);
}

void EliminateSmallLcpFullSet(const MeReal *A, int k, SmallLcpFullSet &full) {
  full.ok = true;
  for (int a = 0; a < k; ++a)
    for (int c = 0; c < k; ++c) full.m[a][c] = A[a * kStride + c];
  // solveSubset's elimination without the right-hand side column; the
  // multiplier f of row r at step a is kept in m[r][a].
  for (int a = 0; a < k; ++a) {
    if (!(full.m[a][a] > 0)) {
      full.ok = false;
      return;
    }
    for (int r = a + 1; r < k; ++r) {
      const MeReal f = full.m[r][a] / full.m[a][a];
      for (int c = a + 1; c < k; ++c) full.m[r][c] -= f * full.m[a][c];
      full.m[r][a] = f;
    }
  }
  for (int c = 0; c < k; ++c) {
    MeReal y[kSmallLcpMax] = {};
    y[c] = 1;
    for (int a = 0; a < k; ++a)
      for (int r = a + 1; r < k; ++r) y[r] -= full.m[r][a] * y[a];
    for (int a = k - 1; a >= 0; --a) {
      MeReal v = y[a];
      for (int b = a + 1; b < k; ++b) v -= full.m[a][b] * full.inverse[b][c];
      full.inverse[a][c] = v / full.m[a][a];
    }
  }
}

bool SolveSmallLcpAfterFull(const MeReal *A, const MeReal *q, const MeReal *lo, int k, unsigned guess, MeReal *x) {
  const unsigned all = (1u << k) - 1;
  guess &= all;
  // Block pivots from the guess (each row moves to the set it wants), a
  // few at most: for a face that lifts or lands they find the set in one
  // or two solves where the fixed order tries up to 2^k.
  unsigned mask = guess;
  for (int round = 0; round < kSmallLcpMax && mask != all; ++round) {
    if (!solveSet(A, q, lo, k, mask, x)) break;
    const unsigned wanted = wantedSet(A, q, lo, k, mask, x);
    if (wanted == mask) return true;
    mask = wanted;
  }
  return tryPartialSets(A, q, lo, k, x);
}

bool SolveSmallLcp(const MeReal *A, const SmallLcpFullSet &full, const MeReal *q, const MeReal *lo, int k, MeReal *x) {
  if (full.ok) {
    // trySet with every row free: x = A^-1 q, fitting when x >= lo.
    MeReal y[kSmallLcpMax];
    for (int i = 0; i < k; ++i) y[i] = q[i];
    for (int a = 0; a < k; ++a)
      for (int r = a + 1; r < k; ++r) y[r] -= full.m[r][a] * y[a];
    for (int a = k - 1; a >= 0; --a) {
      MeReal v = y[a];
      for (int c = a + 1; c < k; ++c) v -= full.m[a][c] * x[c];
      x[a] = v / full.m[a][a];
    }
    bool fits = true;
    for (int i = 0; i < k; ++i) fits = fits && x[i] >= lo[i];
    if (fits) return true;
  }
  return tryPartialSets(A, q, lo, k, x);
}

}  // namespace karma::mdt
