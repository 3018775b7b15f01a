/* sse4.cpp: the SSE4.2 backend (kernels.h). The eight partial sums of a
 * reduction live in 128-bit registers (two of four floats, or four of two
 * doubles), term k in lane k mod 8, added in ascending k as the reference
 * does; the tail and the final combination are the reference's own code.
 * Products and sums are separate instructions (no FMA), so every result is
 * the reference's to the bit. */
#include "backends.h"
#include "reference_inline.h"

#include <immintrin.h>

#define KARMA_SSE4 __attribute__((target("sse4.2")))

namespace karma::platform {
namespace {

/* Adds a[k] b[k] for k < (n / 8) * 8 into the lanes s; returns that count. */
KARMA_SSE4 int AddVectorBody(const MeReal *a, const MeReal *b, int n, MeReal s[kLanes]) {
  int k = 0;
#if !KARMA_DOUBLE
  __m128 acc0 = _mm_setzero_ps(), acc1 = _mm_setzero_ps();
  for (; k + kLanes <= n; k += kLanes) {
    acc0 = _mm_add_ps(acc0, _mm_mul_ps(_mm_loadu_ps(a + k), _mm_loadu_ps(b + k)));
    acc1 = _mm_add_ps(acc1, _mm_mul_ps(_mm_loadu_ps(a + k + 4), _mm_loadu_ps(b + k + 4)));
  }
  _mm_storeu_ps(s, acc0);
  _mm_storeu_ps(s + 4, acc1);
#else
  __m128d acc[4] = {_mm_setzero_pd(), _mm_setzero_pd(), _mm_setzero_pd(), _mm_setzero_pd()};
  for (; k + kLanes <= n; k += kLanes)
    for (int q = 0; q < 4; ++q)
      acc[q] = _mm_add_pd(acc[q], _mm_mul_pd(_mm_loadu_pd(a + k + 2 * q), _mm_loadu_pd(b + k + 2 * q)));
  for (int q = 0; q < 4; ++q) _mm_storeu_pd(s + 2 * q, acc[q]);
#endif
  return k;
}

KARMA_SSE4 MeReal Sse4Dot(const MeReal *a, const MeReal *b, int n) {
  MeReal s[kLanes];
  const int k = AddVectorBody(a, b, n, s);
  reference::AddTail(a, b, k, n, s);
  return reference::LaneSum(s);
}

/* SSE has no gather: each lane's x value is loaded on its own. */
KARMA_SSE4 MeReal Sse4GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  MeReal s[kLanes];
  int k = 0;
  const int *i = index;
#if !KARMA_DOUBLE
  __m128 acc0 = _mm_setzero_ps(), acc1 = _mm_setzero_ps();
  for (; k + kLanes <= n; k += kLanes) {
    const __m128 x0 = _mm_set_ps(x[i[k + 3]], x[i[k + 2]], x[i[k + 1]], x[i[k]]);
    const __m128 x1 = _mm_set_ps(x[i[k + 7]], x[i[k + 6]], x[i[k + 5]], x[i[k + 4]]);
    acc0 = _mm_add_ps(acc0, _mm_mul_ps(_mm_loadu_ps(value + k), x0));
    acc1 = _mm_add_ps(acc1, _mm_mul_ps(_mm_loadu_ps(value + k + 4), x1));
  }
  _mm_storeu_ps(s, acc0);
  _mm_storeu_ps(s + 4, acc1);
#else
  __m128d acc[4] = {_mm_setzero_pd(), _mm_setzero_pd(), _mm_setzero_pd(), _mm_setzero_pd()};
  for (; k + kLanes <= n; k += kLanes)
    for (int q = 0; q < 4; ++q) {
      const int l = k + 2 * q;
      acc[q] = _mm_add_pd(acc[q], _mm_mul_pd(_mm_loadu_pd(value + l), _mm_set_pd(x[i[l + 1]], x[i[l]])));
    }
  for (int q = 0; q < 4; ++q) _mm_storeu_pd(s + 2 * q, acc[q]);
#endif
  reference::AddGatherTail(value, index, x, k, n, s);
  return reference::LaneSum(s);
}

#define KARMA_ROUTINE_TARGET KARMA_SSE4
#define KARMA_ROUTINE_GATHER_DOT Sse4GatherDot
#include "routines.inc"

}  // namespace

const Kernels kSse4Kernels = {"sse4", Sse4Dot, Sse4GatherDot, RoutineSparseRowsTimes};

}  // namespace karma::platform
