// quaternion.cpp: unit quaternions q = (w, x, y, z) as rotations.
//
// q = (cos(a/2), sin(a/2) n) turns by angle a about unit axis n. Its matrix
// R(q) follows MeMath.h: rows are the turned body axes, so R(q) is the
// transpose of the textbook column-vector matrix, and body v goes to world
// v R(q) (the Hamilton product q v q*).
//
// Composition: MeQuaternionMultiply(out, a, b) means "a, then b", so that
// R(out) = R(a) R(b) exactly like MeMatrix3Multiply; as a Hamilton product
// that is out = b a.
#include "math_detail.h"

using karma::me::detail::dot3;
using karma::me::detail::kHalf;
using karma::me::detail::kOne;
using karma::me::detail::kTwo;
using karma::me::detail::kZero;
using karma::me::detail::load3;
using karma::me::detail::Mat3;

extern "C" {

void MEAPI MeQuaternionMakeIdentity(MeVector4 q) { MeVector4Set(q, kOne, kZero, kZero, kZero); }

void MEAPI MeQuaternionMake(MeVector4 q, const MeVector3 axis, MeReal angle) {
  MeVector3 n = {axis[0], axis[1], axis[2]};
  if (MeVector3Normalize(n) == kZero || !MeVector3AllFinite(n)) {
    MeQuaternionMakeIdentity(q);
    return;
  }
  const MeReal s = MeSin(kHalf * angle);
  MeVector4Set(q, MeCos(kHalf * angle), s * n[0], s * n[1], s * n[2]);
}

void MEAPI MeQuaternionToR(MeMatrix3 R, const MeVector4 q) {
  const MeReal w = q[0], x = q[1], y = q[2], z = q[3];
  const MeReal n2 = w * w + x * x + y * y + z * z;
  if (!(n2 > kZero)) {
    MeMatrix3MakeIdentity(R);
    return;
  }
  const MeReal s = kTwo / n2;
  const MeReal xx = s * x * x, yy = s * y * y, zz = s * z * z;
  const MeReal xy = s * x * y, xz = s * x * z, yz = s * y * z;
  const MeReal wx = s * w * x, wy = s * w * y, wz = s * w * z;
  MeVector3Set(R[0], kOne - (yy + zz), xy + wz, xz - wy);
  MeVector3Set(R[1], xy - wz, kOne - (xx + zz), yz + wx);
  MeVector3Set(R[2], xz + wy, yz - wx, kOne - (xx + yy));
}

// Shepperd's method. From the entries of R(q) for a unit q:
//   4w^2 = 1 + tr,  4x^2 = 1 + R00 - R11 - R22  (and cyclically for y, z),
//   4wx = R12 - R21, 4wy = R20 - R02, 4wz = R01 - R10,
//   4xy = R01 + R10, 4xz = R02 + R20, 4yz = R12 + R21.
// Taking the square root of the largest of the four squares keeps the
// divisor >= 1/2, so the method is accurate for every rotation, including
// half turns where w = 0.
void MEAPI MeQuaternionFromR(MeVector4 q, MECONSTMATRIX MeMatrix3 Rin) {
  const Mat3 M = load3(Rin);
  const auto &R = M.m;
  const MeReal tr = R[0][0] + R[1][1] + R[2][2];
  MeReal w, x, y, z;
  if (tr >= R[0][0] && tr >= R[1][1] && tr >= R[2][2]) {
    const MeReal r = MeSqrt(kOne + tr);  // r = 2|w|
    const MeReal f = kHalf / r;
    w = kHalf * r;
    x = (R[1][2] - R[2][1]) * f;
    y = (R[2][0] - R[0][2]) * f;
    z = (R[0][1] - R[1][0]) * f;
  } else if (R[0][0] >= R[1][1] && R[0][0] >= R[2][2]) {
    const MeReal r = MeSqrt(kOne + R[0][0] - R[1][1] - R[2][2]);  // r = 2|x|
    const MeReal f = kHalf / r;
    x = kHalf * r;
    w = (R[1][2] - R[2][1]) * f;
    y = (R[0][1] + R[1][0]) * f;
    z = (R[0][2] + R[2][0]) * f;
  } else if (R[1][1] >= R[2][2]) {
    const MeReal r = MeSqrt(kOne - R[0][0] + R[1][1] - R[2][2]);  // r = 2|y|
    const MeReal f = kHalf / r;
    y = kHalf * r;
    w = (R[2][0] - R[0][2]) * f;
    x = (R[0][1] + R[1][0]) * f;
    z = (R[1][2] + R[2][1]) * f;
  } else {
    const MeReal r = MeSqrt(kOne - R[0][0] - R[1][1] + R[2][2]);  // r = 2|z|
    const MeReal f = kHalf / r;
    z = kHalf * r;
    w = (R[0][1] - R[1][0]) * f;
    x = (R[0][2] + R[2][0]) * f;
    y = (R[1][2] + R[2][1]) * f;
  }
  // q and -q are the same rotation; pick the one with w >= 0.
  if (w < kZero) {
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  MeVector4Set(q, w, x, y, z);
  MeQuaternionNormalize(q);  // absorbs a slightly non-orthonormal R
}

void MEAPI MeQuaternionToTM(MeMatrix4 tm, const MeVector4 q, const MeVector3 position) {
  MeMatrix3 R;
  MeQuaternionToR(R, q);
  MeMatrix4TMMakeFromRotationAndPosition(tm, R, position[0], position[1], position[2]);
}

void MEAPI MeQuaternionMultiply(MeVector4 out, const MeVector4 a, const MeVector4 b) {
  const MeReal aw = a[0], bw = b[0];
  const MeVector3 av = {a[1], a[2], a[3]};
  const MeVector3 bv = {b[1], b[2], b[3]};
  MeVector3 c;
  MeVector3Cross(c, bv, av);
  MeVector4Set(out, bw * aw - dot3(bv, av), bw * av[0] + aw * bv[0] + c[0], bw * av[1] + aw * bv[1] + c[1],
               bw * av[2] + aw * bv[2] + c[2]);
}

MeReal MEAPI MeQuaternionNormalize(MeVector4 q) {
  const MeReal len = MeVector4Normalize(q);
  if (!(len > kZero)) MeQuaternionMakeIdentity(q);
  return len;
}

void MEAPI MeQuaternionConjugate(MeVector4 out, const MeVector4 q) { MeVector4Set(out, q[0], -q[1], -q[2], -q[3]); }

MeBool MEAPI MeQuaternionInvert(MeVector4 out, const MeVector4 q) {
  const MeReal n2 = MeVector4Dot(q, q);
  if (!(n2 > kZero) || !std::isfinite(n2)) return FALSE;
  const MeReal r = kOne / n2;
  MeVector4Set(out, q[0] * r, -q[1] * r, -q[2] * r, -q[3] * r);
  return TRUE;
}

// Hamilton q v q* for unit q = (w, u): with t = 2 (u x v),
// v' = v + w t + u x t.
void MEAPI MeQuaternionRotateVector(MeVector3 out, const MeVector4 q, const MeVector3 v) {
  const MeVector3 u = {q[1], q[2], q[3]};
  const MeVector3 vv = {v[0], v[1], v[2]};
  MeVector3 t, ut;
  MeVector3Cross(t, u, vv);
  MeVector3Scale(t, kTwo);
  MeVector3Cross(ut, u, t);
  MeVector3Set(out, vv[0] + q[0] * t[0] + ut[0], vv[1] + q[0] * t[1] + ut[1], vv[2] + q[0] * t[2] + ut[2]);
}

void MEAPI MeQuaternionInverseRotateVector(MeVector3 out, const MeVector4 q, const MeVector3 v) {
  MeVector4 c;
  MeQuaternionConjugate(c, q);
  MeQuaternionRotateVector(out, c, v);
}

MeBool MEAPI MeQuaternionIsUnit(const MeVector4 q, MeReal tol) {
  return (MeFabs(MeVector4Dot(q, q) - kOne) <= tol) ? TRUE : FALSE;
}

}  // extern "C"
