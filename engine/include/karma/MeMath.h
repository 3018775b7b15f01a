/* MeMath.h: small fixed-size linear algebra for Karma: 3- and 4-vectors,
 * 3x3 matrices, 4x4 rigid transforms (TMs), quaternions, Euler angles and an
 * HSV colour helper. Plain C API, usable from C11 and C++.
 *
 * Conventions (they follow MePrecision.h):
 *  - Vectors are ROW vectors. Matrices are row-major arrays.
 *  - A rotation matrix R has the body axes as its ROWS: R[i] is body axis i
 *    written in world coordinates. A body-frame vector v therefore maps to
 *    world as  w = v * R  (w[j] = sum_i v[i] R[i][j]), and back as
 *    v = R * w  (v[i] = sum_j R[i][j] w[j]), since R^-1 = R^T.
 *  - Products compose left to right: A * B means "apply A, then B".
 *  - A TM (MeMatrix4) stores R in rows 0..2 with column 3 = 0, and the
 *    translation t in row 3 with tm[3][3] = 1; a point maps as p' = p*R + t.
 *  - Quaternions are MeVector4 (w, x, y, z); the unit quaternion for a turn
 *    of angle a about unit axis n is (cos(a/2), sin(a/2) n). A +90 degree
 *    turn about z carries body x onto world y, so its R[0] is (0, 1, 0).
 *  - Angles are in radians (except MeHSVtoRGB's hue, in degrees).
 *  - Every output may alias any input: results are built in temporaries
 *    and stored last.
 *  - Functions never divide by zero: degenerate input (zero vector, zero
 *    axis, singular matrix) gives the defined result documented per call.
 *
 * Matrix inputs are declared MECONSTMATRIX. In C++ (and C23) that is
 * `const`. In C11 it is empty, because ISO C before C23 does not convert
 * `MeReal (*)[n]` to `const MeReal (*)[n]` implicitly and -Wpedantic warns
 * on every call made with an ordinary matrix; the functions still never
 * write to those inputs. */
#ifndef KARMA_MEMATH_H
#define KARMA_MEMATH_H

#include "MeCall.h"
#include "MePrecision.h"

#if defined(__cplusplus) || (defined(__STDC_VERSION__) && __STDC_VERSION__ > 201710L)
#  define MECONSTMATRIX const
#else
#  define MECONSTMATRIX
#endif

ME_EXTERN_C_BEGIN

/* ---- MeVector3 ---------------------------------------------------------- */

/* Set, Copy, Add, Subtract, Scale, MultiplyScalar, MultiplyAdd, Negate,
 * Dot, Cross, MagnitudeSqr, Magnitude, Normalize and AllFinite are defined
 * inline in MeMathInline.h, included at the end of this header. */

/* returns |a - b| */
MEPUBLIC MeReal MEAPI MeVector3Distance(const MeVector3 a, const MeVector3 b);
/* returns |a - b|^2 */
MEPUBLIC MeReal MEAPI MeVector3DistanceSqr(const MeVector3 a, const MeVector3 b);
/* TRUE when every component is exactly zero */
MEPUBLIC MeBool MEAPI MeVector3IsZero(const MeVector3 v);
/* p, q = unit vectors spanning the plane normal to n, with p x q = n/|n|
 * (so p, q, n/|n| is a right-handed orthonormal basis); a zero n counts as z.
 * n comes first, as in Karma. */
MEPUBLIC void MEAPI MeVector3PlaneSpace(const MeVector3 n, MeVector3 p, MeVector3 q);

/* ---- MeVector4 ---------------------------------------------------------- */

/* v = (a, b, c, d) */
MEPUBLIC void MEAPI MeVector4Set(MeVector4 v, MeReal a, MeReal b, MeReal c, MeReal d);
/* out = in */
MEPUBLIC void MEAPI MeVector4Copy(MeVector4 out, const MeVector4 in);
/* returns a . b over four components */
MEPUBLIC MeReal MEAPI MeVector4Dot(const MeVector4 a, const MeVector4 b);
/* returns |v| over four components */
MEPUBLIC MeReal MEAPI MeVector4Magnitude(const MeVector4 v);
/* v = v / |v| in place; returns the old |v|. A zero vector stays zero (returns 0). */
MEPUBLIC MeReal MEAPI MeVector4Normalize(MeVector4 v);

/* ---- MeMatrix3 ---------------------------------------------------------- */

/* m = I */
MEPUBLIC void MEAPI MeMatrix3MakeIdentity(MeMatrix3 m);
/* out = in */
MEPUBLIC void MEAPI MeMatrix3Copy(MeMatrix3 out, MECONSTMATRIX MeMatrix3 in);
/* out = a * b (out[i][j] = sum_k a[i][k] b[k][j]); for rotations: apply a, then b */
MEPUBLIC void MEAPI MeMatrix3Multiply(MeMatrix3 out, MECONSTMATRIX MeMatrix3 a, MECONSTMATRIX MeMatrix3 b);
/* out = m^T */
MEPUBLIC void MEAPI MeMatrix3Transpose(MeMatrix3 out, MECONSTMATRIX MeMatrix3 m);
/* returns det m = m[0] . (m[1] x m[2]) */
MEPUBLIC MeReal MEAPI MeMatrix3Determinant(MECONSTMATRIX MeMatrix3 m);
/* out = m^-1 (adjugate / det); returns TRUE. When m is singular, i.e.
 * |det m| <= ME_REAL_EPSILON * |m[0]| |m[1]| |m[2]| or det is not finite,
 * returns FALSE and leaves out unchanged. */
MEPUBLIC MeBool MEAPI MeMatrix3Inverse(MeMatrix3 out, MECONSTMATRIX MeMatrix3 m);
/* MultiplyVector (out = m v) and TransposeMultiplyVector (out = m^T v) are
 * defined inline in MeMathInline.h. */
/* R = turn by angle about x: rows (1,0,0), (0,c,s), (0,-s,c) */
MEPUBLIC void MEAPI MeMatrix3MakeRotationX(MeMatrix3 R, MeReal angle);
/* R = turn by angle about y: rows (c,0,-s), (0,1,0), (s,0,c) */
MEPUBLIC void MEAPI MeMatrix3MakeRotationY(MeMatrix3 R, MeReal angle);
/* R = turn by angle about z: rows (c,s,0), (-s,c,0), (0,0,1) */
MEPUBLIC void MEAPI MeMatrix3MakeRotationZ(MeMatrix3 R, MeReal angle);
/* R = turn by angle about axis (normalised here; a zero axis gives I):
 * R = c I + (1-c) n n^T - s [n]x, i.e. the transpose of Rodrigues' matrix. */
MEPUBLIC void MEAPI MeMatrix3FromAxisAngle(MeMatrix3 R, const MeVector3 axis, MeReal angle);
/* TRUE when every entry of R R^T - I is within tol of zero */
MEPUBLIC MeBool MEAPI MeMatrix3IsOrthonormal(MECONSTMATRIX MeMatrix3 R, MeReal tol);
/* TRUE when R is orthonormal within tol and det R > 0 (a proper rotation) */
MEPUBLIC MeBool MEAPI MeMatrix3IsRotation(MECONSTMATRIX MeMatrix3 R, MeReal tol);
/* R from Euler angles yaw psi, pitch theta, roll phi (z-x-z), with c = cos, s = sin:
 *  R[0] = ( c psi c phi - c theta s phi s psi,  c psi s phi + c theta c phi s psi, s psi s theta)
 *  R[1] = (-s psi c phi - c theta s phi c psi, -s psi s phi + c theta c phi c psi, c psi s theta)
 *  R[2] = ( s theta s phi,                     -s theta c phi,                     c theta) */
MEPUBLIC void MEAPI MeMatrix3FromEulerAngles(MeMatrix3 R, MeReal psi, MeReal theta, MeReal phi);

/* ---- MeMatrix4: general 4x4 --------------------------------------------- */

/* m = I */
MEPUBLIC void MEAPI MeMatrix4MakeIdentity(MeMatrix4 m);
/* out = in */
MEPUBLIC void MEAPI MeMatrix4Copy(MeMatrix4 out, MECONSTMATRIX MeMatrix4 in);
/* out = a * b (out[i][j] = sum_k a[i][k] b[k][j]); for TMs: apply a, then b */
MEPUBLIC void MEAPI MeMatrix4Multiply(MeMatrix4 out, MECONSTMATRIX MeMatrix4 a, MECONSTMATRIX MeMatrix4 b);
/* out = m^T */
MEPUBLIC void MEAPI MeMatrix4Transpose(MeMatrix4 out, MECONSTMATRIX MeMatrix4 m);

/* ---- MeMatrix4: rigid transforms (TM) ------------------------------------ */

/* tm = I: no rotation, no translation */
MEPUBLIC void MEAPI MeMatrix4TMMakeIdentity(MeMatrix4 tm);
/* tm = [R 0; (x, y, z) 1] */
MEPUBLIC void MEAPI MeMatrix4TMMakeFromRotationAndPosition(MeMatrix4 tm, MECONSTMATRIX MeMatrix3 R, MeReal x, MeReal y,
                                                           MeReal z);
/* t = (x, y, z); the rotation rows are untouched */
MEPUBLIC void MEAPI MeMatrix4TMSetPosition(MeMatrix4 tm, MeReal x, MeReal y, MeReal z);
/* t = p */
MEPUBLIC void MEAPI MeMatrix4TMSetPositionVector(MeMatrix4 tm, const MeVector3 p);
/* TMGetPosition (out = t) is defined inline in MeMathInline.h. */
/* rows 0..2 = R with column 3 = 0; the translation is untouched */
MEPUBLIC void MEAPI MeMatrix4TMSetRotation(MeMatrix4 tm, MECONSTMATRIX MeMatrix3 R);
/* R = rows 0..2, columns 0..2 of tm */
MEPUBLIC void MEAPI MeMatrix4TMGetRotation(MeMatrix3 R, MECONSTMATRIX MeMatrix4 tm);
/* out = a * b, i.e. apply a, then b: R = Ra Rb, t = ta Rb + tb. With a the
 * child's TM relative to its parent and b the parent's world TM, out is the
 * child's world TM. Column 3 of out is exactly (0, 0, 0, 1). */
MEPUBLIC void MEAPI MeMatrix4TMCompose(MeMatrix4 out, MECONSTMATRIX MeMatrix4 a, MECONSTMATRIX MeMatrix4 b);
/* out = tm^-1 for a rigid tm: R' = R^T, t' = -t R^T */
MEPUBLIC void MEAPI MeMatrix4TMInverse(MeMatrix4 out, MECONSTMATRIX MeMatrix4 tm);
/* TMTransform (out = p R + t, a body point into the world), TMRotate
 * (out = v R, a body direction into the world) and their inverses
 * TMInverseTransform (out = (p - t) R^T) and TMInverseRotate (out = v R^T)
 * are defined inline in MeMathInline.h. */
/* TRUE when rows 0..2 form a proper rotation within tol and column 3 is
 * (0, 0, 0, 1) within tol */
MEPUBLIC MeBool MEAPI MeMatrix4IsTM(MECONSTMATRIX MeMatrix4 tm, MeReal tol);

/* ---- Quaternions (w, x, y, z) -------------------------------------------- */

/* q = (1, 0, 0, 0) */
MEPUBLIC void MEAPI MeQuaternionMakeIdentity(MeVector4 q);
/* q = (cos(angle/2), sin(angle/2) axis/|axis|); a zero axis gives the identity */
MEPUBLIC void MEAPI MeQuaternionMake(MeVector4 q, const MeVector3 axis, MeReal angle);
/* R = rotation of q. Uses s = 2/|q|^2, so a non-unit q gives the rotation of
 * q/|q|; a zero q gives I. With (w,x,y,z):
 *  R[0] = (1 - s(yy+zz),  s(xy+wz),      s(xz-wy))
 *  R[1] = (s(xy-wz),      1 - s(xx+zz),  s(yz+wx))
 *  R[2] = (s(xz+wy),      s(yz-wx),      1 - s(xx+yy)) */
MEPUBLIC void MEAPI MeQuaternionToR(MeMatrix3 R, const MeVector4 q);
/* q = unit quaternion of rotation R, with w >= 0 (Shepperd: the square root is
 * taken of the largest of 1+trace, 1+2R00-trace, 1+2R11-trace, 1+2R22-trace) */
MEPUBLIC void MEAPI MeQuaternionFromR(MeVector4 q, MECONSTMATRIX MeMatrix3 R);
/* tm = [R(q) 0; position 1] */
MEPUBLIC void MEAPI MeQuaternionToTM(MeMatrix4 tm, const MeVector4 q, const MeVector3 position);
/* out = rotation "a, then b", so that R(out) = R(a) * R(b) like
 * MeMatrix3Multiply. In Hamilton notation out = b a:
 *  out.w = bw aw - bv . av,  out.v = bw av + aw bv + bv x av */
MEPUBLIC void MEAPI MeQuaternionMultiply(MeVector4 out, const MeVector4 a, const MeVector4 b);
/* q = q/|q| in place; returns the old |q|. A zero q becomes (1, 0, 0, 0). */
MEPUBLIC MeReal MEAPI MeQuaternionNormalize(MeVector4 q);
/* out = (w, -x, -y, -z): the inverse rotation of a unit q */
MEPUBLIC void MEAPI MeQuaternionConjugate(MeVector4 out, const MeVector4 q);
/* out = conj(q) / |q|^2; returns TRUE. A zero q returns FALSE, out unchanged. */
MEPUBLIC MeBool MEAPI MeQuaternionInvert(MeVector4 out, const MeVector4 q);
/* out = v R(q): a body vector into world coordinates (q unit) */
MEPUBLIC void MEAPI MeQuaternionRotateVector(MeVector3 out, const MeVector4 q, const MeVector3 v);
/* out = v R(q)^T: a world vector into body coordinates (q unit) */
MEPUBLIC void MEAPI MeQuaternionInverseRotateVector(MeVector3 out, const MeVector4 q, const MeVector3 v);
/* TRUE when | |q|^2 - 1 | <= tol */
MEPUBLIC MeBool MEAPI MeQuaternionIsUnit(const MeVector4 q, MeReal tol);
/* q = q, then the turn exp(h omega / 2): the orientation after time h of a
 * body spinning at constant angular velocity omega (WORLD coordinates) —
 * a turn of angle |omega| h about omega. Exact for constant omega; the
 * result is normalised. In Hamilton notation q' = (cos(|w|h/2),
 * sin(|w|h/2) w/|w|) q. */
MEPUBLIC void MEAPI MeQuaternionFiniteRotation(MeVector4 q, const MeVector3 omega, MeReal h);

/* ---- Colour --------------------------------------------------------------- */

/* rgb = hexcone HSV -> RGB. h in degrees, wrapped into [0, 360) (a non-finite
 * h counts as 0); s and v are clamped to [0, 1]. Writes rgb[0..2] only. */
MEPUBLIC void MEAPI MeHSVtoRGB(MeReal h, MeReal s, MeReal v, float rgb[3]);

ME_EXTERN_C_END

#include "MeMathInline.h"

#endif /* KARMA_MEMATH_H */
