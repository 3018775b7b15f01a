// transform.cpp: rigid transforms (TMs) stored in an MeMatrix4.
//
//   tm = | R 0 |   R: rows 0..2 = body axes in world coordinates
//        | t 1 |   t: row 3 = body origin in world coordinates
//
// A body point p maps to the world point p R + t; a direction v maps to v R.
// The inverse is | R^T 0 ; -t R^T 1 |. Every function builds its result
// in locals before writing, so outputs may alias inputs. TMGetPosition,
// TMTransform and TMRotate are inline in MeMathInline.h.
#include "math_detail.h"

using karma::me::detail::dot3;
using karma::me::detail::kOne;
using karma::me::detail::kZero;
using karma::me::detail::Mat3;
using karma::me::detail::rotationOf;

namespace {

// Writes [R 0; t 1] into tm.
void storeTM(MeMatrix4 tm, const Mat3 &R, const MeReal t[3]) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) tm[i][j] = R.m[i][j];
    tm[i][3] = kZero;
  }
  for (int j = 0; j < 3; ++j) tm[3][j] = t[j];
  tm[3][3] = kOne;
}

// out = v R (row vector times the rotation block).
void rowTimes(MeReal out[3], const MeReal v[3], const Mat3 &R) {
  for (int j = 0; j < 3; ++j) out[j] = v[0] * R.m[0][j] + v[1] * R.m[1][j] + v[2] * R.m[2][j];
}

// out = v R^T, i.e. out[i] = R[i] . v.
void rowTimesTranspose(MeReal out[3], const MeReal v[3], const Mat3 &R) {
  for (int i = 0; i < 3; ++i) out[i] = dot3(R.m[i], v);
}

}  // namespace

extern "C" {

void MEAPI MeMatrix4TMMakeIdentity(MeMatrix4 tm) { MeMatrix4MakeIdentity(tm); }

void MEAPI MeMatrix4TMMakeFromRotationAndPosition(MeMatrix4 tm, MECONSTMATRIX MeMatrix3 R, MeReal x, MeReal y,
                                                  MeReal z) {
  const MeReal t[3] = {x, y, z};
  storeTM(tm, karma::me::detail::load3(R), t);
}

void MEAPI MeMatrix4TMSetPosition(MeMatrix4 tm, MeReal x, MeReal y, MeReal z) {
  tm[3][0] = x;
  tm[3][1] = y;
  tm[3][2] = z;
}

void MEAPI MeMatrix4TMSetPositionVector(MeMatrix4 tm, const MeVector3 p) {
  MeMatrix4TMSetPosition(tm, p[0], p[1], p[2]);
}

void MEAPI MeMatrix4TMSetRotation(MeMatrix4 tm, MECONSTMATRIX MeMatrix3 R) {
  const Mat3 r = karma::me::detail::load3(R);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) tm[i][j] = r.m[i][j];
    tm[i][3] = kZero;
  }
}

void MEAPI MeMatrix4TMGetRotation(MeMatrix3 R, MECONSTMATRIX MeMatrix4 tm) {
  karma::me::detail::store3(R, rotationOf(tm));
}

// [Ra 0; ta 1] [Rb 0; tb 1] = [Ra Rb 0; ta Rb + tb 1]
void MEAPI MeMatrix4TMCompose(MeMatrix4 out, MECONSTMATRIX MeMatrix4 a, MECONSTMATRIX MeMatrix4 b) {
  const Mat3 ra = rotationOf(a), rb = rotationOf(b);
  Mat3 r{};
  for (int i = 0; i < 3; ++i) rowTimes(r.m[i], ra.m[i], rb);
  MeReal t[3];
  rowTimes(t, a[3], rb);
  for (int j = 0; j < 3; ++j) t[j] += b[3][j];
  storeTM(out, r, t);
}

void MEAPI MeMatrix4TMInverse(MeMatrix4 out, MECONSTMATRIX MeMatrix4 tm) {
  const Mat3 r = rotationOf(tm);
  Mat3 rt{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rt.m[i][j] = r.m[j][i];
  MeReal t[3];
  rowTimesTranspose(t, tm[3], r);  // t R^T
  for (int j = 0; j < 3; ++j) t[j] = -t[j];
  storeTM(out, rt, t);
}

MeBool MEAPI MeMatrix4IsTM(MECONSTMATRIX MeMatrix4 tm, MeReal tol) {
  MeMatrix3 R;
  MeMatrix4TMGetRotation(R, tm);
  if (!MeMatrix3IsRotation(R, tol)) return FALSE;
  for (int i = 0; i < 3; ++i)
    if (!(MeFabs(tm[i][3]) <= tol)) return FALSE;
  if (!(MeFabs(tm[3][3] - kOne) <= tol)) return FALSE;
  if (!std::isfinite(tm[3][0]) || !std::isfinite(tm[3][1]) || !std::isfinite(tm[3][2])) return FALSE;
  return TRUE;
}

}  // extern "C"
