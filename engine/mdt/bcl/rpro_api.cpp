// rpro_api.cpp: the RPRO joint's accessors and mutators.
#include "joint_input.h"
#include "rpro.h"

using namespace karma::mdt;

namespace {

bool ok(const MdtRPROJoint *j, const char *fn) { return checkType(j, kRPROJointType, fn); }

// A finite, non-zero quaternion, normalised in place.
bool unitQuaternion(MeVector4 q, const char *fn) {
  const bool finite = realFinite(q[0]) && realFinite3(q[1], q[2], q[3]);
  const MeReal n = finite ? MeVector4Magnitude(q) : 0;
  if (!(n > (MeReal)1e-6) || !realFinite(n)) {
    MeWarning(0, "%s: the quaternion is zero or not finite; ignored", fn);
    return false;
  }
  for (int k = 0; k < 4; ++k) q[k] /= n;
  return true;
}

void setStrength(MeVector3 out, MeReal x, MeReal y, MeReal z, const char *fn) {
  if (!(x > 0 && y > 0 && z > 0)) {  // also rejects NaN
    MeWarning(0, "%s: strengths (%g, %g, %g) must be > 0; ignored", fn, (double)x, (double)y, (double)z);
    return;
  }
  MeVector3Set(out, x > MEINFINITY ? MEINFINITY : x, y > MEINFINITY ? MEINFINITY : y, z > MEINFINITY ? MEINFINITY : z);
}

}  // namespace

extern "C" {

void MEAPI MdtRPROJointGetPosition(const MdtRPROJointID j, const unsigned int i, MeVector3 p) {
  static const char *fn = "MdtRPROJointGetPosition";
  if (!ok(j, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(p != nullptr, fn, "position is NULL");
  attachmentPoint(j, (int)i, p);
}

void MEAPI MdtRPROJointSetRelativeQuaternion(const MdtRPROJointID j, const MeVector4 q) {
  static const char *fn = "MdtRPROJointSetRelativeQuaternion";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(q != nullptr, fn, "quaternion is NULL");
  MeVector4 u = {q[0], q[1], q[2], q[3]};
  if (unitQuaternion(u, fn)) MeVector4Copy(j->relativeQ, u);
}

void MEAPI MdtRPROJointGetRelativeQuaternion(const MdtRPROJointID j, MeVector4 q) {
  static const char *fn = "MdtRPROJointGetRelativeQuaternion";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(q != nullptr, fn, "quaternion is NULL");
  MeVector4Copy(q, j->relativeQ);
}

void MEAPI MdtRPROJointSetRelativeAngularVelocity(MdtRPROJointID j, MeVector3 w) {
  static const char *fn = "MdtRPROJointSetRelativeAngularVelocity";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(w != nullptr, fn, "velocity is NULL");
  ME_REQUIRE_ARG(MeVector3AllFinite(w), fn, "velocity is not finite; ignored");
  MeVector3Copy(j->relativeW, w);
}

void MEAPI MdtRPROJointGetRelativeAngularVelocity(const MdtRPROJointID j, MeVector3 w) {
  static const char *fn = "MdtRPROJointGetRelativeAngularVelocity";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(w != nullptr, fn, "velocity is NULL");
  MeVector3Copy(w, j->relativeW);
}

void MEAPI MdtRPROJointSetAttachmentPosition(const MdtRPROJointID j, const MeReal x, const MeReal y, const MeReal z,
                                             const unsigned int i) {
  static const char *fn = "MdtRPROJointSetAttachmentPosition";
  if (!ok(j, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "position is not finite; ignored");
  MeVector3Set(j->localPos[i], x, y, z);
  j->warmRows = 0;
}

void MEAPI MdtRPROJointGetAttachmentPosition(const MdtRPROJointID j, const unsigned int i, MeVector3 p) {
  static const char *fn = "MdtRPROJointGetAttachmentPosition";
  if (!ok(j, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(p != nullptr, fn, "position is NULL");
  MeVector3Copy(p, j->localPos[i]);
}

void MEAPI MdtRPROJointSetAttachmentQuaternion(const MdtRPROJointID j, const MeReal q0, const MeReal q1,
                                               const MeReal q2, const MeReal q3, const unsigned int i) {
  static const char *fn = "MdtRPROJointSetAttachmentQuaternion";
  if (!ok(j, fn) || !bodyIndexOk(i, fn)) return;
  MeVector4 q = {q0, q1, q2, q3};
  if (!unitQuaternion(q, fn)) return;
  MeMatrix3 R;
  MeQuaternionToR(R, q);  // rows: the frame's x and y in the body's axes
  MeVector3Copy(j->localAxis[i], R[0]);
  MeVector3Copy(j->localOrtho[i], R[1]);
  j->warmRows = 0;
}

void MEAPI MdtRPROJointGetAttachmentOrientation(const MdtRPROJointID j, const unsigned int i, MeVector4 q) {
  static const char *fn = "MdtRPROJointGetAttachmentOrientation";
  if (!ok(j, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(q != nullptr, fn, "quaternion is NULL");
  MeMatrix3 R;
  MeVector3Copy(R[0], j->localAxis[i]);
  MeVector3Copy(R[1], j->localOrtho[i]);
  MeVector3Cross(R[2], R[0], R[1]);
  MeQuaternionFromR(q, R);
}

void MEAPI MdtRPROJointSetAngularStrength(const MdtRPROJointID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtRPROJointSetAngularStrength";
  if (ok(j, fn)) setStrength(j->angularStrength, x, y, z, fn);
}

void MEAPI MdtRPROJointSetLinearStrength(const MdtRPROJointID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtRPROJointSetLinearStrength";
  if (ok(j, fn)) setStrength(j->linearStrength, x, y, z, fn);
}

void MEAPI MdtRPROJointGetAngularStrength(const MdtRPROJointID j, MeVector3 s) {
  static const char *fn = "MdtRPROJointGetAngularStrength";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(s != nullptr, fn, "NULL argument");
  MeVector3Copy(s, j->angularStrength);
}

void MEAPI MdtRPROJointGetLinearStrength(const MdtRPROJointID j, MeVector3 s) {
  static const char *fn = "MdtRPROJointGetLinearStrength";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(s != nullptr, fn, "NULL argument");
  MeVector3Copy(s, j->linearStrength);
}

}  // extern "C"
