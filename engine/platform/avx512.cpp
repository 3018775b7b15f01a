/* avx512.cpp: the AVX-512F backend (kernels.h). Doubles: the eight partial
 * sums of a reduction are one 512-bit register, term k in lane k mod 8, the
 * last n mod 8 terms one masked step (avx2_inline.h says why masked-off
 * lanes change nothing). Floats: eight lanes are a 256-bit register
 * (sixteen would change the reference's order), so the reductions are
 * avx2_inline.h's. No FMA: every result is the reference's to the bit. */
#include "avx2_inline.h"
#include "backends.h"

#define KARMA_AVX512 __attribute__((target("avx512f")))
#define KARMA_AVX512_INLINE __attribute__((target("avx512f"), always_inline)) inline

namespace karma::platform {
namespace {

#if KARMA_DOUBLE
KARMA_AVX512_INLINE __mmask8 FirstLanes(int count) { return static_cast<__mmask8>((1u << count) - 1); }

KARMA_AVX512_INLINE double LaneSum(__m512d s) {
  /* The halves through the zero-masked extract: GCC 12 warns that the plain
   * extract (and the cast, made of it) reads an undefined register. */
  const __m256d lower = _mm512_maskz_extractf64x4_pd(0xF, s, 0), upper = _mm512_maskz_extractf64x4_pd(0xF, s, 1);
  const __m256d t = _mm256_add_pd(lower, upper);                                        /* s_l + s_{l+4} */
  const __m128d u = _mm_add_pd(_mm256_castpd256_pd128(t), _mm256_extractf128_pd(t, 1)); /* t0 + t2, t1 + t3 */
  return _mm_cvtsd_f64(_mm_add_sd(u, _mm_unpackhi_pd(u, u)));
}

KARMA_AVX512_INLINE double Dot512(const double *a, const double *b, int n) {
  __m512d acc = _mm512_setzero_pd();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes)
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_loadu_pd(a + k), _mm512_loadu_pd(b + k)));
  if (k < n) {
    const __mmask8 m = FirstLanes(n - k);
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_maskz_loadu_pd(m, a + k), _mm512_maskz_loadu_pd(m, b + k)));
  }
  return LaneSum(acc);
}

/* x[index[k]] lane by lane, or one load for a run of consecutive indices,
 * as in avx2_inline.h; the tail is one masked
 * hardware gather (the masked-off lanes read nothing). */
KARMA_AVX512_INLINE double GatherDot512(const double *value, const int *index, const double *x, int n) {
  const int *i = index;
  __m512d acc = _mm512_setzero_pd();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) {
    const __m512d xk = avx2::Consecutive8(i + k) ? _mm512_loadu_pd(x + i[k])
                                                 : _mm512_set_pd(x[i[k + 7]], x[i[k + 6]], x[i[k + 5]], x[i[k + 4]],
                                                                 x[i[k + 3]], x[i[k + 2]], x[i[k + 1]], x[i[k]]);
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_loadu_pd(value + k), xk));
  }
  if (k < n) {
    const __mmask8 m = FirstLanes(n - k);
    const __m256i first = _mm256_cmpgt_epi32(_mm256_set1_epi32(n - k), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    const __m256i at = _mm256_maskload_epi32(index + k, first);
    const __m512d xs = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), m, at, x, 8);
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_maskz_loadu_pd(m, value + k), xs));
  }
  return LaneSum(acc);
}

#else
KARMA_AVX512_INLINE float Dot512(const float *a, const float *b, int n) { return avx2::Dot(a, b, n); }

KARMA_AVX512_INLINE float GatherDot512(const float *value, const int *index, const float *x, int n) {
  return avx2::GatherDot(value, index, x, n);
}
#endif

KARMA_AVX512 MeReal Avx512Dot(const MeReal *a, const MeReal *b, int n) { return Dot512(a, b, n); }

KARMA_AVX512 MeReal Avx512GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  return GatherDot512(value, index, x, n);
}

#define KARMA_ROUTINE_TARGET KARMA_AVX512
#define KARMA_ROUTINE_GATHER_DOT GatherDot512
#include "routines.inc"

}  // namespace

const Kernels kAvx512Kernels = {"avx512", Avx512Dot, Avx512GatherDot, RoutineSparseRowsTimes};

}  // namespace karma::platform
