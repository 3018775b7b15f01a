/* avx2.cpp: the AVX2 backend (kernels.h). The eight partial sums of a
 * reduction are one 256-bit register of floats or two of doubles, term k in
 * lane k mod 8, added in ascending k as the reference does. The tail and the final
 * combination are the reference's own code. Products and sums stay separate
 * instructions (FMA would round once where the reference rounds twice), so
 * every result is the reference's to the bit. */
#include "backends.h"
#include "reference_inline.h"

#include <immintrin.h>

#define KARMA_AVX2 __attribute__((target("avx2")))

namespace karma::platform {
namespace {

/* x[at[0..]] lane by lane: on the machines measured (docs/PERFORMANCE.md)
 * the hardware gather was slower than separate loads. */
#if !KARMA_DOUBLE
KARMA_AVX2 __m256 Gather(const float *x, const int *at) {
  return _mm256_set_ps(x[at[7]], x[at[6]], x[at[5]], x[at[4]], x[at[3]], x[at[2]], x[at[1]], x[at[0]]);
}
#else
KARMA_AVX2 __m256d Gather(const double *x, const int *at) {
  return _mm256_set_pd(x[at[3]], x[at[2]], x[at[1]], x[at[0]]);
}
#endif

}  // namespace

KARMA_AVX2 MeReal Avx2Dot(const MeReal *a, const MeReal *b, int n) {
  MeReal s[kLanes];
  int k = 0;
#if !KARMA_DOUBLE
  __m256 acc = _mm256_setzero_ps();
  for (; k + kLanes <= n; k += kLanes)
    acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(a + k), _mm256_loadu_ps(b + k)));
  _mm256_storeu_ps(s, acc);
#else
  __m256d acc0 = _mm256_setzero_pd(), acc1 = _mm256_setzero_pd();
  for (; k + kLanes <= n; k += kLanes) {
    acc0 = _mm256_add_pd(acc0, _mm256_mul_pd(_mm256_loadu_pd(a + k), _mm256_loadu_pd(b + k)));
    acc1 = _mm256_add_pd(acc1, _mm256_mul_pd(_mm256_loadu_pd(a + k + 4), _mm256_loadu_pd(b + k + 4)));
  }
  _mm256_storeu_pd(s, acc0);
  _mm256_storeu_pd(s + 4, acc1);
#endif
  reference::AddTail(a, b, k, n, s);
  return reference::LaneSum(s);
}

KARMA_AVX2 MeReal Avx2GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  MeReal s[kLanes];
  int k = 0;
#if !KARMA_DOUBLE
  __m256 acc = _mm256_setzero_ps();
  for (; k + kLanes <= n; k += kLanes) {
    acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(value + k), Gather(x, index + k)));
  }
  _mm256_storeu_ps(s, acc);
#else
  __m256d acc0 = _mm256_setzero_pd(), acc1 = _mm256_setzero_pd();
  for (; k + kLanes <= n; k += kLanes) {
    acc0 = _mm256_add_pd(acc0, _mm256_mul_pd(_mm256_loadu_pd(value + k), Gather(x, index + k)));
    acc1 = _mm256_add_pd(acc1, _mm256_mul_pd(_mm256_loadu_pd(value + k + 4), Gather(x, index + k + 4)));
  }
  _mm256_storeu_pd(s, acc0);
  _mm256_storeu_pd(s + 4, acc1);
#endif
  reference::AddGatherTail(value, index, x, k, n, s);
  return reference::LaneSum(s);
}

namespace {

KARMA_AVX2 void Avx2SubtractScaled(MeReal alpha, const MeReal *x, MeReal *y, int n) {
  int k = 0;
#if !KARMA_DOUBLE
  const __m256 a = _mm256_set1_ps(alpha);
  for (; k + 8 <= n; k += 8)
    _mm256_storeu_ps(y + k, _mm256_sub_ps(_mm256_loadu_ps(y + k), _mm256_mul_ps(a, _mm256_loadu_ps(x + k))));
#else
  const __m256d a = _mm256_set1_pd(alpha);
  for (; k + 4 <= n; k += 4)
    _mm256_storeu_pd(y + k, _mm256_sub_pd(_mm256_loadu_pd(y + k), _mm256_mul_pd(a, _mm256_loadu_pd(x + k))));
#endif
  for (; k < n; ++k) y[k] -= alpha * x[k];
}

}  // namespace

const Kernels kAvx2Kernels = {"avx2", Avx2Dot, Avx2GatherDot, Avx2SubtractScaled};

}  // namespace karma::platform
