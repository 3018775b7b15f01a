/* MeMathInline.h: the small MeVector3 operations, defined in the header so
 * that a call costs no more than its arithmetic. Included by MeMath.h; do
 * not include it on its own.
 *
 * Each function here is also exported by the library under the same name
 * (engine/me/math/vector3.cpp compiles this same text with
 * ME_MATH_EXPORT_INLINES defined), so a program that takes a function's
 * address, or a language binding that links by symbol, gets the same
 * behaviour. The conventions of MeMath.h hold: every output may alias any
 * input (results are computed into locals and stored last), and sums run
 * in one fixed order (index 0 first), so the inline and the exported
 * definitions give bit-identical results under the same floating-point
 * settings. */
#ifndef KARMA_MEMATHINLINE_H
#define KARMA_MEMATHINLINE_H

#include <math.h>

#include "MeCall.h"
#include "MePrecision.h"

#ifdef ME_MATH_EXPORT_INLINES
#  define ME_MATH_INLINE MEPUBLIC
#else
#  define ME_MATH_INLINE static inline
#endif

ME_EXTERN_C_BEGIN

/* v = (x, y, z) */
ME_MATH_INLINE void MEAPI MeVector3Set(MeVector3 v, MeReal x, MeReal y, MeReal z) {
  v[0] = x;
  v[1] = y;
  v[2] = z;
}

/* out = in */
ME_MATH_INLINE void MEAPI MeVector3Copy(MeVector3 out, const MeVector3 in) {
  const MeReal x = in[0], y = in[1], z = in[2];
  MeVector3Set(out, x, y, z);
}

/* out = a + b */
ME_MATH_INLINE void MEAPI MeVector3Add(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[0] + b[0], a[1] + b[1], a[2] + b[2]);
}

/* out = a - b */
ME_MATH_INLINE void MEAPI MeVector3Subtract(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/* v = s * v (in place) */
ME_MATH_INLINE void MEAPI MeVector3Scale(MeVector3 v, MeReal s) {
  v[0] *= s;
  v[1] *= s;
  v[2] *= s;
}

/* out = s * v */
ME_MATH_INLINE void MEAPI MeVector3MultiplyScalar(MeVector3 out, const MeVector3 v, MeReal s) {
  MeVector3Set(out, v[0] * s, v[1] * s, v[2] * s);
}

/* v = v + s * a (in place) */
ME_MATH_INLINE void MEAPI MeVector3MultiplyAdd(MeVector3 v, MeReal s, const MeVector3 a) {
  MeVector3Set(v, v[0] + s * a[0], v[1] + s * a[1], v[2] + s * a[2]);
}

/* v = -v (in place) */
ME_MATH_INLINE void MEAPI MeVector3Negate(MeVector3 v) { MeVector3Set(v, -v[0], -v[1], -v[2]); }

/* returns a . b = sum_i a[i] b[i] */
ME_MATH_INLINE MeReal MEAPI MeVector3Dot(const MeVector3 a, const MeVector3 b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* out = a x b (right-handed: x cross y = z); (a x b)_i = a_j b_k - a_k b_j
 * for (i, j, k) cyclic */
ME_MATH_INLINE void MEAPI MeVector3Cross(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

/* returns |v|^2 = v . v */
ME_MATH_INLINE MeReal MEAPI MeVector3MagnitudeSqr(const MeVector3 v) { return MeVector3Dot(v, v); }

/* returns |v| */
ME_MATH_INLINE MeReal MEAPI MeVector3Magnitude(const MeVector3 v) { return MeSqrt(MeVector3Dot(v, v)); }

/* v = v / |v| in place; returns the old |v|. A zero vector stays zero (returns 0). */
ME_MATH_INLINE MeReal MEAPI MeVector3Normalize(MeVector3 v) {
  const MeReal len = MeSqrt(MeVector3Dot(v, v));
  if (len > (MeReal)0) MeVector3Scale(v, (MeReal)1 / len);
  return len;
}

/* TRUE when no component is NaN or infinite */
ME_MATH_INLINE MeBool MEAPI MeVector3AllFinite(const MeVector3 v) {
  return (isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) ? TRUE : FALSE;
}

ME_EXTERN_C_END

#endif /* KARMA_MEMATHINLINE_H */
