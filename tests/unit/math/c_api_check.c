/* c_api_check.c: MeMath.h used from C11. This file is compiled as ISO C11
 * with -Wpedantic -Werror (see CMakeLists.txt), so the header must declare
 * a C-compatible API and calls with ordinary, non-const vectors, matrices
 * and MeMatrix4Ptr must not warn. It also runs a few guide-style calls and
 * returns the number of wrong results. */
#include <stdlib.h>

#include "MeMath.h"

int karma_math_c_api_check(void);

static int near(MeReal a, MeReal b) { return MeFabs(a - b) <= (MeReal)1e-4; }

int karma_math_c_api_check(void) {
  int bad = 0;
  MeVector3 pos, startPos = {1, 2, 3}, offset = {(MeReal)0.5, 0, -1}, dir, normal = {0, 0, 1}, haxis = {0, 1, 0};
  MeVector3Ptr xAxis;
  MeMatrix3 R, Rt, RR;
  MeMatrix4 tm, tm2;
  MeMatrix4Ptr heapTM;
  MeVector4 q;
  float color[4];

  MeVector3Add(pos, startPos, offset);
  bad += !near(pos[0], (MeReal)1.5);
  MeVector3Cross(dir, normal, haxis); /* z x y = -x */
  MeVector3Normalize(dir);
  bad += !near(dir[0], -1);
  bad += !near(MeFabs(MeVector3Dot(normal, haxis)), 0);
  MeVector3Scale(pos, (MeReal)0.5);
  bad += !near(pos[0], (MeReal)0.75);

  MeMatrix3FromEulerAngles(R, (MeReal)0.1, (MeReal)0.2, (MeReal)0.3);
  MeMatrix3Transpose(Rt, R);
  MeMatrix3Multiply(RR, R, Rt);
  bad += !MeMatrix3IsOrthonormal(R, (MeReal)1e-4);
  bad += !near(RR[1][1], 1);
  bad += !MeMatrix3Inverse(RR, R);
  bad += !near(MeMatrix3Determinant(R), 1);

  MeMatrix4TMMakeIdentity(tm);
  MeMatrix4TMSetPosition(tm, 0, 0, 1);
  MeMatrix4TMSetRotation(tm, R);
  MeMatrix4TMGetRotation(Rt, tm);
  MeMatrix4Copy(tm2, tm);
  MeMatrix4TMCompose(tm2, tm, tm2);
  MeMatrix4TMInverse(tm2, tm2);
  bad += !MeMatrix4IsTM(tm2, (MeReal)1e-4);

  heapTM = (MeMatrix4Ptr)malloc(sizeof(MeMatrix4));
  if (!heapTM) return bad + 1;
  MeMatrix4TMMakeIdentity(heapTM);
  MeMatrix4Copy(heapTM, tm);
  xAxis = (MeVector3Ptr)heapTM; /* row 0: the body x axis */
  bad += !near(MeVector3Dot(xAxis, R[0]), 1);
  MeMatrix4TMTransform(pos, heapTM, startPos);
  MeMatrix4TMInverseTransform(pos, heapTM, pos);
  bad += !near(pos[2], 3);
  free(heapTM);

  MeQuaternionFromR(q, R);
  MeQuaternionToR(RR, q);
  bad += !near(RR[2][1], R[2][1]);
  MeQuaternionToTM(tm, q, startPos);
  MeQuaternionFiniteRotation(q, normal, (MeReal)0.01);

  MeHSVtoRGB(((MeReal)3 / (MeReal)10) * 360, 1, 1, color);
  color[3] = 1;
  bad += !(color[0] >= 0.0f && color[0] <= 1.0f);
  return bad;
}
