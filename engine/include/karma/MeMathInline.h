/* MeMathInline.h: the small MeVector3 operations and the products of a
 * vector with a 3x3 matrix or a TM, defined in the header so that a call
 * costs no more than its arithmetic. Included by MeMath.h; do
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

/* out = m * v with v a column: out[i] = sum_j m[i][j] v[j].
 * For a rotation R this takes a WORLD vector into BODY coordinates. */
ME_MATH_INLINE void MEAPI MeMatrix3MultiplyVector(MeVector3 out, MECONSTMATRIX MeMatrix3 m, const MeVector3 v) {
  MeVector3Set(out, MeVector3Dot(m[0], v), MeVector3Dot(m[1], v), MeVector3Dot(m[2], v));
}

/* out = m^T * v = v * m with v a row: out[j] = sum_i v[i] m[i][j].
 * For a rotation R this takes a BODY vector into WORLD coordinates. */
ME_MATH_INLINE void MEAPI MeMatrix3TransposeMultiplyVector(MeVector3 out, MECONSTMATRIX MeMatrix3 m,
                                                          const MeVector3 v) {
  const MeReal x = v[0], y = v[1], z = v[2];
  MeVector3Set(out, x * m[0][0] + y * m[1][0] + z * m[2][0], x * m[0][1] + y * m[1][1] + z * m[2][1],
               x * m[0][2] + y * m[1][2] + z * m[2][2]);
}

/* out = t, the translation (row 3) of a TM */
ME_MATH_INLINE void MEAPI MeMatrix4TMGetPosition(MeVector3 out, MECONSTMATRIX MeMatrix4 tm) {
  MeVector3Set(out, tm[3][0], tm[3][1], tm[3][2]);
}

/* out = v R: a body-frame direction into world coordinates (no translation) */
ME_MATH_INLINE void MEAPI MeMatrix4TMRotate(MeVector3 out, MECONSTMATRIX MeMatrix4 tm, const MeVector3 v) {
  const MeReal x = v[0], y = v[1], z = v[2];
  MeVector3Set(out, x * tm[0][0] + y * tm[1][0] + z * tm[2][0], x * tm[0][1] + y * tm[1][1] + z * tm[2][1],
               x * tm[0][2] + y * tm[1][2] + z * tm[2][2]);
}

/* out = p R + t: a body-frame point into world coordinates */
ME_MATH_INLINE void MEAPI MeMatrix4TMTransform(MeVector3 out, MECONSTMATRIX MeMatrix4 tm, const MeVector3 p) {
  const MeReal x = p[0], y = p[1], z = p[2];
  MeVector3Set(out, x * tm[0][0] + y * tm[1][0] + z * tm[2][0] + tm[3][0],
               x * tm[0][1] + y * tm[1][1] + z * tm[2][1] + tm[3][1],
               x * tm[0][2] + y * tm[1][2] + z * tm[2][2] + tm[3][2]);
}

/* out = v R^T: a world direction into body coordinates */
ME_MATH_INLINE void MEAPI MeMatrix4TMInverseRotate(MeVector3 out, MECONSTMATRIX MeMatrix4 tm, const MeVector3 v) {
  MeVector3Set(out, MeVector3Dot(tm[0], v), MeVector3Dot(tm[1], v), MeVector3Dot(tm[2], v));
}

/* out = (p - t) R^T: a world point into body coordinates */
ME_MATH_INLINE void MEAPI MeMatrix4TMInverseTransform(MeVector3 out, MECONSTMATRIX MeMatrix4 tm, const MeVector3 p) {
  const MeVector3 d = {p[0] - tm[3][0], p[1] - tm[3][1], p[2] - tm[3][2]};
  MeVector3Set(out, MeVector3Dot(tm[0], d), MeVector3Dot(tm[1], d), MeVector3Dot(tm[2], d));
}

ME_EXTERN_C_END

#endif /* KARMA_MEMATHINLINE_H */
