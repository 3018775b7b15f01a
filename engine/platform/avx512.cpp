/* avx512.cpp: the AVX-512F backend (kernels.h). Doubles: the eight partial
 * sums of a reduction are one 512-bit register, term k in lane k mod 8.
 * Floats: eight lanes are a 256-bit register (sixteen would change the
 * reference's order), so the reductions are avx2.cpp's own functions, and
 * the array update uses 512-bit registers. No FMA: every result is the reference's to the
 * bit. */
#include "backends.h"
#include "reference_inline.h"

#include <immintrin.h>

#define KARMA_AVX512 __attribute__((target("avx512f")))

namespace karma::platform {
namespace {

#if KARMA_DOUBLE
KARMA_AVX512 MeReal Avx512Dot(const MeReal *a, const MeReal *b, int n) {
  MeReal s[kLanes];
  int k = 0;
  __m512d acc = _mm512_setzero_pd();
  for (; k + kLanes <= n; k += kLanes)
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_loadu_pd(a + k), _mm512_loadu_pd(b + k)));
  _mm512_storeu_pd(s, acc);
  reference::AddTail(a, b, k, n, s);
  return reference::LaneSum(s);
}

/* x[index[k]] lane by lane, as in avx2.cpp (no hardware gather). */
KARMA_AVX512 MeReal Avx512GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  MeReal s[kLanes];
  int k = 0;
  const int *i = index;
  __m512d acc = _mm512_setzero_pd();
  for (; k + kLanes <= n; k += kLanes) {
    const __m512d xk = _mm512_set_pd(x[i[k + 7]], x[i[k + 6]], x[i[k + 5]], x[i[k + 4]], x[i[k + 3]], x[i[k + 2]],
                                     x[i[k + 1]], x[i[k]]);
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_loadu_pd(value + k), xk));
  }
  _mm512_storeu_pd(s, acc);
  reference::AddGatherTail(value, index, x, k, n, s);
  return reference::LaneSum(s);
}
#endif

KARMA_AVX512 void Avx512SubtractScaled(MeReal alpha, const MeReal *x, MeReal *y, int n) {
  int k = 0;
#if !KARMA_DOUBLE
  const __m512 a = _mm512_set1_ps(alpha);
  for (; k + 16 <= n; k += 16)
    _mm512_storeu_ps(y + k, _mm512_sub_ps(_mm512_loadu_ps(y + k), _mm512_mul_ps(a, _mm512_loadu_ps(x + k))));
#else
  const __m512d a = _mm512_set1_pd(alpha);
  for (; k + 8 <= n; k += 8)
    _mm512_storeu_pd(y + k, _mm512_sub_pd(_mm512_loadu_pd(y + k), _mm512_mul_pd(a, _mm512_loadu_pd(x + k))));
#endif
  for (; k < n; ++k) y[k] -= alpha * x[k];
}

}  // namespace

#if KARMA_DOUBLE
const Kernels kAvx512Kernels = {"avx512", Avx512Dot, Avx512GatherDot, Avx512SubtractScaled};
#else
const Kernels kAvx512Kernels = {"avx512", Avx2Dot, Avx2GatherDot, Avx512SubtractScaled};
#endif

}  // namespace karma::platform
