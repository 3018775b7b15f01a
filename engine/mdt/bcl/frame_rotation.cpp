// frame_rotation.cpp: exact relative rotation of attachment frames (see
// frame_rotation.h).
#include "frame_rotation.h"

#include <cmath>

namespace karma::mdt {

void frameRows(const MdtConstraint *c, int i, MeMatrix3 F) {
  attachmentAxis(c, i, F[0]);
  attachmentOrtho(c, i, F[1]);
  MeVector3Cross(F[2], F[0], F[1]);
}

void relativeQuaternion(const MdtConstraint *c, MeVector4 q) {
  MeMatrix3 F0, F1, R;
  frameRows(c, 0, F0);
  frameRows(c, 1, F1);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) R[r][k] = MeVector3Dot(F1[r], F0[k]);
  MeQuaternionFromR(q, R);  // w >= 0
}

void rotationVector(const MeVector4 q, MeVector3 out) {
  MeVector3 v = {q[1], q[2], q[3]};
  const MeReal s = MeVector3Magnitude(v);
  MeReal w = q[0];
  // The shorter way round: angle 2 atan2(|v|, |w|) in [0, pi].
  MeReal sign = 1;
  if (w < 0) {
    w = -w;
    sign = -1;
  }
  if (s < (MeReal)1e-12) {  // t n ~ 2 v for tiny angles
    MeVector3MultiplyScalar(out, v, 2 * sign);
    return;
  }
  const MeReal angle = 2 * std::atan2(s, w);
  MeVector3MultiplyScalar(out, v, sign * angle / s);
}

void frameToWorld(MECONSTMATRIX MeMatrix3 F, const MeVector3 local, MeVector3 out) {
  MeMatrix3TransposeMultiplyVector(out, F, local);
}

void relativeAngularVelocity(const MdtConstraint *c, MeVector3 out) {
  MeVector3Set(out, 0, 0, 0);
  if (c->body[1]) MeVector3Add(out, out, c->body[1]->angularVelocity);
  if (c->body[0]) MeVector3Subtract(out, out, c->body[0]->angularVelocity);
}

}  // namespace karma::mdt
