// body_state.cpp: position, orientation, transform and velocities.
#include "MeMessage.h"
#include "mdt_internal.h"

using namespace karma::mdt;

namespace {
constexpr const char *kNull = "body is NULL";
}

extern "C" {

void MEAPI MdtBodySetPosition(const MdtBodyID body, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtBodySetPosition";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "position (%g, %g, %g) is not finite; ignored", (double)x, (double)y,
                 (double)z);
  MeVector3Set(body->position, x, y, z);
  updateTransform(body);
}

void MEAPI MdtBodyGetPosition(const MdtBodyID body, MeVector3 position) {
  if (!liveBody(body, "MdtBodyGetPosition")) return;
  ME_REQUIRE_ARG(position != nullptr, "MdtBodyGetPosition", "NULL argument");
  MeVector3Copy(position, body->position);
}

void MEAPI MdtBodySetQuaternion(const MdtBodyID body, const MeReal qw, const MeReal qx, const MeReal qy,
                                const MeReal qz) {
  static const char *fn = "MdtBodySetQuaternion";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite(qw) && realFinite3(qx, qy, qz), fn, "quaternion (%g, %g, %g, %g) is not finite; ignored",
                 (double)qw, (double)qx, (double)qy, (double)qz);
  MeVector4 q = {qw, qx, qy, qz};
  const MeReal n = MeVector4Magnitude(q);
  ME_REQUIRE_ARG(n > 0 && realFinite(n), fn, "quaternion has zero (or overflowing) length; ignored");
  MeQuaternionNormalize(q);
  MeVector4Copy(body->q, q);
  updateTransform(body);
}

void MEAPI MdtBodyGetQuaternion(const MdtBodyID body, MeVector4 q) {
  if (!liveBody(body, "MdtBodyGetQuaternion")) return;
  ME_REQUIRE_ARG(q != nullptr, "MdtBodyGetQuaternion", "NULL argument");
  MeVector4Copy(q, body->q);
}

void MEAPI MdtBodySetOrientation(const MdtBodyID body, MECONSTMATRIX MeMatrix3 R) {
  static const char *fn = "MdtBodySetOrientation";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(R != nullptr, fn, "NULL argument");
  bool ok = true;
  for (int i = 0; i < 3; ++i) ok = ok && MeVector3AllFinite(R[i]);
  ME_REQUIRE_ARG(ok, fn, "matrix is not finite; ignored");
  ME_REQUIRE_ARG(MeMatrix3IsRotation(R, (MeReal)1e-2), fn,
                 "matrix is not a rotation (rows must be orthonormal, det +1); ignored");
  MeQuaternionFromR(body->q, R);
  MeQuaternionNormalize(body->q);
  updateTransform(body);
}

void MEAPI MdtBodyGetOrientation(const MdtBodyID body, MeMatrix3 R) {
  if (!liveBody(body, "MdtBodyGetOrientation")) return;
  ME_REQUIRE_ARG(R != nullptr, "MdtBodyGetOrientation", "NULL argument");
  MeMatrix4TMGetRotation(R, body->tm);
}

void MEAPI MdtBodyGetTransform(const MdtBodyID body, MeMatrix4 tm) {
  if (!liveBody(body, "MdtBodyGetTransform")) return;
  ME_REQUIRE_ARG(tm != nullptr, "MdtBodyGetTransform", "NULL argument");
  MeMatrix4Copy(tm, body->tm);
}

MeMatrix4Ptr MEAPI MdtBodyGetTransformPtr(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetTransformPtr")) return nullptr;
  return body->tm;
}

void MEAPI MdtBodySetLinearVelocity(const MdtBodyID body, const MeReal dx, const MeReal dy, const MeReal dz) {
  static const char *fn = "MdtBodySetLinearVelocity";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite3(dx, dy, dz), fn, "velocity (%g, %g, %g) is not finite; ignored", (double)dx, (double)dy,
                 (double)dz);
  MeVector3Set(body->velocity, dx, dy, dz);
}

void MEAPI MdtBodyGetLinearVelocity(const MdtBodyID body, MeVector3 v) {
  if (!liveBody(body, "MdtBodyGetLinearVelocity")) return;
  ME_REQUIRE_ARG(v != nullptr, "MdtBodyGetLinearVelocity", "NULL argument");
  MeVector3Copy(v, body->velocity);
}

void MEAPI MdtBodySetAngularVelocity(const MdtBodyID body, const MeReal wx, const MeReal wy, const MeReal wz) {
  static const char *fn = "MdtBodySetAngularVelocity";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite3(wx, wy, wz), fn, "angular velocity (%g, %g, %g) is not finite; ignored", (double)wx,
                 (double)wy, (double)wz);
  MeVector3Set(body->angularVelocity, wx, wy, wz);
}

void MEAPI MdtBodyGetAngularVelocity(const MdtBodyID body, MeVector3 w) {
  if (!liveBody(body, "MdtBodyGetAngularVelocity")) return;
  ME_REQUIRE_ARG(w != nullptr, "MdtBodyGetAngularVelocity", "NULL argument");
  MeVector3Copy(w, body->angularVelocity);
}

void MEAPI MdtBodyGetLinearAcceleration(const MdtBodyID body, MeVector3 a) {
  if (!liveBody(body, "MdtBodyGetLinearAcceleration")) return;
  ME_REQUIRE_ARG(a != nullptr, "MdtBodyGetLinearAcceleration", "NULL argument");
  MeVector3Copy(a, body->acceleration);
}

void MEAPI MdtBodyGetAngularAcceleration(const MdtBodyID body, MeVector3 a) {
  if (!liveBody(body, "MdtBodyGetAngularAcceleration")) return;
  ME_REQUIRE_ARG(a != nullptr, "MdtBodyGetAngularAcceleration", "NULL argument");
  MeVector3Copy(a, body->angularAcceleration);
}

void MEAPI MdtBodySetFastSpinAxis(const MdtBodyID body, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtBodySetFastSpinAxis";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "axis (%g, %g, %g) is not finite; ignored", (double)x, (double)y, (double)z);
  MeVector3 a = {x, y, z};
  const MeReal n = MeVector3Magnitude(a);
  ME_REQUIRE_ARG(n > 0 && realFinite(n), fn, "axis has zero (or overflowing) length; ignored");
  MeVector3Normalize(a);
  MeVector3Copy(body->fastSpinAxis, a);
  body->fastSpinEnabled = TRUE;
}

void MEAPI MdtBodyGetFastSpinAxis(const MdtBodyID body, MeVector3 axis) {
  if (!liveBody(body, "MdtBodyGetFastSpinAxis")) return;
  ME_REQUIRE_ARG(axis != nullptr, "MdtBodyGetFastSpinAxis", "NULL argument");
  MeVector3Copy(axis, body->fastSpinAxis);
}

void MEAPI MdtBodyDisableFastSpinAxis(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyDisableFastSpinAxis")) return;
  body->fastSpinEnabled = FALSE;
}

MeBool MEAPI MdtBodyIsFastSpinAxisEnabled(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyIsFastSpinAxisEnabled")) return FALSE;
  return body->fastSpinEnabled ? TRUE : FALSE;
}

}  // extern "C"
