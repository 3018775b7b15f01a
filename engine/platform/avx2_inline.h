/* avx2_inline.h: AVX2 reductions as inline functions (not installed), for
 * avx2.cpp and avx512.cpp (whose float reductions are these: eight float
 * lanes are one 256-bit register either way, sixteen would change the
 * order).
 *
 * The eight partial sums of a reduction (kernels.h) are one 256-bit
 * register of floats or two of doubles, term k in lane k mod 8, added in
 * ascending k. The last n mod 8 terms are one masked step: the masked-off
 * lanes load zeros and add 0 * 0 = +0, which leaves a partial sum
 * unchanged, because a partial sum that starts at +0 can never be -0 (in
 * round-to-nearest x + y is -0 only when both are -0). The partial sums are
 * combined in the register, in LaneSum's order
 *     ((s0 + s4) + (s2 + s6)) + ((s1 + s5) + (s3 + s7)).
 * Products and sums stay separate instructions (FMA would round once where
 * the reference rounds twice): every result is the reference's to the bit.
 *
 * Include only from files compiled for a target that has AVX2. */
#ifndef KARMA_PLATFORM_AVX2_INLINE_H
#define KARMA_PLATFORM_AVX2_INLINE_H

#include "reference_inline.h"

#include <immintrin.h>

#define KARMA_AVX2 __attribute__((target("avx2")))
#define KARMA_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace karma::platform::avx2 {

/* Index runs: a sparse row's columns come in runs of consecutive indices
 * (a contact group's rows are numbered together), where the x values a
 * gather needs lie side by side and one vector load fetches them. */
/* Whether at[0..7] are at[0], at[0] + 1, .., at[0] + 7. */
KARMA_AVX2_INLINE bool Consecutive8(const int *at) {
  const __m256i want = _mm256_add_epi32(_mm256_set1_epi32(at[0]), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
  const __m256i got = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(at));
  return _mm256_movemask_epi8(_mm256_cmpeq_epi32(want, got)) == -1;
}

/* Whether at[0..3] are at[0], at[0] + 1, .., at[0] + 3. */
KARMA_AVX2_INLINE bool Consecutive4(const int *at) {
  const __m128i want = _mm_add_epi32(_mm_set1_epi32(at[0]), _mm_setr_epi32(0, 1, 2, 3));
  const __m128i got = _mm_loadu_si128(reinterpret_cast<const __m128i *>(at));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(want, got)) == 0xffff;
}

#if !KARMA_DOUBLE
/* Lanes l < count set (all ones), the rest clear. */
KARMA_AVX2_INLINE __m256i FirstLanes(int count) {
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(count), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

KARMA_AVX2_INLINE float LaneSum(__m256 s) {
  const __m128 t = _mm_add_ps(_mm256_castps256_ps128(s), _mm256_extractf128_ps(s, 1)); /* s_l + s_{l+4} */
  const __m128 u = _mm_add_ps(t, _mm_movehl_ps(t, t));                                 /* t0 + t2, t1 + t3 */
  return _mm_cvtss_f32(_mm_add_ss(u, _mm_shuffle_ps(u, u, 1)));
}

/* x[at[0..7]] lane by lane: on the machines measured (docs/PERFORMANCE.md)
 * the hardware gather was slower than separate loads. */
KARMA_AVX2_INLINE __m256 Gather(const float *x, const int *at) {
  return _mm256_set_ps(x[at[7]], x[at[6]], x[at[5]], x[at[4]], x[at[3]], x[at[2]], x[at[1]], x[at[0]]);
}

/* x[at[0..7]], as one load where the indices are consecutive (a run of
 * columns, as a sparse row's contact group is: SparseRowsTimes), else lane
 * by lane. The same values in the same lanes either way. */
KARMA_AVX2_INLINE __m256 GatherRun(const float *x, const int *at) {
  return Consecutive8(at) ? _mm256_loadu_ps(x + at[0]) : Gather(x, at);
}

KARMA_AVX2_INLINE float Dot(const float *a, const float *b, int n) {
  __m256 acc = _mm256_setzero_ps();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes)
    acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(a + k), _mm256_loadu_ps(b + k)));
  if (k < n) {
    const __m256i m = FirstLanes(n - k);
    acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_maskload_ps(a + k, m), _mm256_maskload_ps(b + k, m)));
  }
  return LaneSum(acc);
}

/* x[at[l]] for l < count (count < 8), zero in the other lanes, lane by lane. */
KARMA_AVX2_INLINE __m256 GatherFirst(const float *x, const int *at, int count) {
  switch (count) {
    case 1:
      return _mm256_setr_ps(x[at[0]], 0, 0, 0, 0, 0, 0, 0);
    case 2:
      return _mm256_setr_ps(x[at[0]], x[at[1]], 0, 0, 0, 0, 0, 0);
    case 3:
      return _mm256_setr_ps(x[at[0]], x[at[1]], x[at[2]], 0, 0, 0, 0, 0);
    case 4:
      return _mm256_setr_ps(x[at[0]], x[at[1]], x[at[2]], x[at[3]], 0, 0, 0, 0);
    case 5:
      return _mm256_setr_ps(x[at[0]], x[at[1]], x[at[2]], x[at[3]], x[at[4]], 0, 0, 0);
    case 6:
      return _mm256_setr_ps(x[at[0]], x[at[1]], x[at[2]], x[at[3]], x[at[4]], x[at[5]], 0, 0);
    case 7:
      return _mm256_setr_ps(x[at[0]], x[at[1]], x[at[2]], x[at[3]], x[at[4]], x[at[5]], x[at[6]], 0);
    default:
      return _mm256_setzero_ps();
  }
}

KARMA_AVX2_INLINE float GatherDot(const float *value, const int *index, const float *x, int n) {
  __m256 acc = _mm256_setzero_ps();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes)
    acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(value + k), GatherRun(x, index + k)));
  if (k < n)
    acc = _mm256_add_ps(
        acc, _mm256_mul_ps(_mm256_maskload_ps(value + k, FirstLanes(n - k)), GatherFirst(x, index + k, n - k)));
  return LaneSum(acc);
}

#else
/* Lanes l < count set (all ones), the rest clear; count may be <= 0. */
KARMA_AVX2_INLINE __m256i FirstLanes(int count) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(count), _mm256_setr_epi64x(0, 1, 2, 3));
}

/* lo holds s0..s3, hi s4..s7. */
KARMA_AVX2_INLINE double LaneSum(__m256d lo, __m256d hi) {
  const __m256d t = _mm256_add_pd(lo, hi);                                              /* s_l + s_{l+4} */
  const __m128d u = _mm_add_pd(_mm256_castpd256_pd128(t), _mm256_extractf128_pd(t, 1)); /* t0 + t2, t1 + t3 */
  return _mm_cvtsd_f64(_mm_add_sd(u, _mm_unpackhi_pd(u, u)));
}

KARMA_AVX2_INLINE __m256d Gather(const double *x, const int *at) {
  return _mm256_set_pd(x[at[3]], x[at[2]], x[at[1]], x[at[0]]);
}

/* x[at[0..3]], as one load where the indices are consecutive (see the
 * float GatherRun), else lane by lane. */
KARMA_AVX2_INLINE __m256d GatherRun(const double *x, const int *at) {
  return Consecutive4(at) ? _mm256_loadu_pd(x + at[0]) : Gather(x, at);
}

/* Lanes 0-3 in lo, 4-7 in hi. */
KARMA_AVX2_INLINE double Dot(const double *a, const double *b, int n) {
  __m256d lo = _mm256_setzero_pd(), hi = _mm256_setzero_pd();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) {
    lo = _mm256_add_pd(lo, _mm256_mul_pd(_mm256_loadu_pd(a + k), _mm256_loadu_pd(b + k)));
    hi = _mm256_add_pd(hi, _mm256_mul_pd(_mm256_loadu_pd(a + k + 4), _mm256_loadu_pd(b + k + 4)));
  }
  if (k < n) {
    const __m256i m0 = FirstLanes(n - k), m1 = FirstLanes(n - k - 4);
    lo = _mm256_add_pd(lo, _mm256_mul_pd(_mm256_maskload_pd(a + k, m0), _mm256_maskload_pd(b + k, m0)));
    hi = _mm256_add_pd(hi, _mm256_mul_pd(_mm256_maskload_pd(a + k + 4, m1), _mm256_maskload_pd(b + k + 4, m1)));
  }
  return LaneSum(lo, hi);
}

/* The masked-off lanes of a tail gather read nothing. */
KARMA_AVX2_INLINE __m256d GatherFirst(const double *x, const int *at, __m256i m) {
  const __m128i lanes = _mm_castps_si128(_mm256_castps256_ps128(
      _mm256_permutevar8x32_ps(_mm256_castsi256_ps(m), _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0))));
  return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), x, _mm_maskload_epi32(at, lanes), _mm256_castsi256_pd(m), 8);
}

KARMA_AVX2_INLINE double GatherDot(const double *value, const int *index, const double *x, int n) {
  __m256d acc0 = _mm256_setzero_pd(), acc1 = _mm256_setzero_pd();
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) {
    acc0 = _mm256_add_pd(acc0, _mm256_mul_pd(_mm256_loadu_pd(value + k), GatherRun(x, index + k)));
    acc1 = _mm256_add_pd(acc1, _mm256_mul_pd(_mm256_loadu_pd(value + k + 4), GatherRun(x, index + k + 4)));
  }
  if (k < n) {
    const __m256i m0 = FirstLanes(n - k), m1 = FirstLanes(n - k - 4);
    acc0 = _mm256_add_pd(acc0, _mm256_mul_pd(_mm256_maskload_pd(value + k, m0), GatherFirst(x, index + k, m0)));
    acc1 = _mm256_add_pd(acc1, _mm256_mul_pd(_mm256_maskload_pd(value + k + 4, m1), GatherFirst(x, index + k + 4, m1)));
  }
  return LaneSum(acc0, acc1);
}

#endif

}  // namespace karma::platform::avx2

#endif
