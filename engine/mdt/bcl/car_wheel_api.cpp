// car_wheel_api.cpp: the car wheel joint's accessors and mutators.
#include <cmath>

#include "car_wheel.h"
#include "joint_input.h"

using namespace karma::mdt;

namespace {

bool ok(const MdtCarWheel *j, const char *fn) { return checkType(j, kCarWheelType, fn); }

void setMotor(MdtLimit *m, MeReal v, MeReal f, const char *fn) {
  if (!realFinite(v)) {
    MeWarning(0, "%s: desired velocity is not finite; ignored", fn);
    return;
  }
  if (!(f >= 0) || !realFinite(f)) {
    MeWarning(0, "%s: force limit %g must be finite and >= 0; ignored", fn, (double)f);
    return;
  }
  m->motorDesiredVelocity = v;
  m->motorMaxForce = f;
  m->motorized = f > 0 ? TRUE : FALSE;
}

}  // namespace

extern "C" {

void MEAPI MdtCarWheelSetSteeringAndHingeAxes(const MdtCarWheelID j, const MeReal xs, const MeReal ys, const MeReal zs,
                                              const MeReal xh, const MeReal yh, const MeReal zh) {
  static const char *fn = "MdtCarWheelSetSteeringAndHingeAxes";
  if (!ok(j, fn)) return;
  MeVector3 s = {xs, ys, zs}, h = {xh, yh, zh}, a;
  if (!unitDirection(s, fn, "the steering axis") || !unitDirection(h, fn, "the hinge axis")) return;
  const MeReal cosine = MeVector3Dot(s, h);
  if (std::fabs(cosine) > (MeReal)1e-3) {
    MeWarning(0, "%s: the axes are not perpendicular (cosine %g); ignored", fn, (double)cosine);
    return;
  }
  MeVector3MultiplyAdd(h, -cosine, s);
  MeVector3Normalize(h);
  // Both frames (a, o, n) = (h x s, h, s): n0 = s, o1 = h (car_wheel.h).
  MeVector3Cross(a, h, s);
  setWorldAxes(j, a, h);
  j->steer.rawValid = FALSE;
  j->hinge.rawValid = FALSE;
  j->warmRows = 0;
}

void MEAPI MdtCarWheelGetSteeringAxis(const MdtCarWheelID j, MeVector3 axis) {
  static const char *fn = "MdtCarWheelGetSteeringAxis";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  MeVector3Copy(axis, wheelGeometry(j).s);
}

void MEAPI MdtCarWheelGetHingeAxis(const MdtCarWheelID j, MeVector3 axis) {
  static const char *fn = "MdtCarWheelGetHingeAxis";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  attachmentOrtho(j, 1, axis);
}

MeReal MEAPI MdtCarWheelGetHingeAngle(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetHingeAngle") ? wheelHingeAngle(j) : 0;
}

MeReal MEAPI MdtCarWheelGetHingeAngleRate(const MdtCarWheelID j) {
  if (!ok(j, "MdtCarWheelGetHingeAngleRate")) return 0;
  MeVector3 h;
  attachmentOrtho(j, 1, h);
  return wheelRelativeRate(j, h);
}

// The reported steering angle and rate are the chassis's turn relative to
// the wheel, -phi and s . (w0 - w1), as a hinge reports body 0 relative to
// body 1 (hinge.cpp); the steering motor drives phi's rate s . (w1 - w0).
MeReal MEAPI MdtCarWheelGetSteeringAngle(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSteeringAngle") ? -wheelSteeringAngle(j) : 0;
}

MeReal MEAPI MdtCarWheelGetSteeringAngleRate(const MdtCarWheelID j) {
  if (!ok(j, "MdtCarWheelGetSteeringAngleRate")) return 0;
  return -wheelRelativeRate(j, wheelGeometry(j).s);
}

void MEAPI MdtCarWheelSetHingeLimitedForceMotor(const MdtCarWheelID j, const MeReal v, const MeReal f) {
  static const char *fn = "MdtCarWheelSetHingeLimitedForceMotor";
  if (ok(j, fn)) setMotor(&j->hinge, v, f, fn);
}
MeReal MEAPI MdtCarWheelGetHingeMotorDesiredVelocity(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetHingeMotorDesiredVelocity") ? j->hinge.motorDesiredVelocity : 0;
}
MeReal MEAPI MdtCarWheelGetHingeMotorMaxForce(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetHingeMotorMaxForce") ? j->hinge.motorMaxForce : 0;
}

void MEAPI MdtCarWheelSetSteeringLimitedForceMotor(const MdtCarWheelID j, const MeReal v, const MeReal f) {
  static const char *fn = "MdtCarWheelSetSteeringLimitedForceMotor";
  if (ok(j, fn)) setMotor(&j->steer, v, f, fn);
}
MeReal MEAPI MdtCarWheelGetSteeringMotorDesiredVelocity(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSteeringMotorDesiredVelocity") ? j->steer.motorDesiredVelocity : 0;
}
MeReal MEAPI MdtCarWheelGetSteeringMotorMaxForce(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSteeringMotorMaxForce") ? j->steer.motorMaxForce : 0;
}

void MEAPI MdtCarWheelSetSteeringLock(const MdtCarWheelID j, const MeBool lock) {
  if (!ok(j, "MdtCarWheelSetSteeringLock")) return;
  j->steeringLocked = lock ? TRUE : FALSE;
  j->warmRows = 0;
}
MeBool MEAPI MdtCarWheelIsSteeringLocked(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelIsSteeringLocked") ? j->steeringLocked : FALSE;
}

void MEAPI MdtCarWheelSetSuspension(const MdtCarWheelID j, const MeReal kp, const MeReal kd, const MeReal softness,
                                    const MeReal lo, const MeReal hi, const MeReal ref) {
  static const char *fn = "MdtCarWheelSetSuspension";
  if (!ok(j, fn)) return;
  if (!realFinite3(kp, kd, softness) || !realFinite3(lo, hi, ref)) {
    MeWarning(0, "%s: an argument is not finite; ignored", fn);
    return;
  }
  if (!nonNegative(kp, fn, "Kp") || !nonNegative(kd, fn, "Kd") || !nonNegative(softness, fn, "limit softness")) return;
  j->kp = kp;
  j->kd = kd;
  j->limitSoftness = softness;
  j->suspension.limit[0].stop = lo < hi ? lo : hi;
  j->suspension.limit[1].stop = lo < hi ? hi : lo;
  j->reference = ref;
  j->warmRows = 0;
}

MeReal MEAPI MdtCarWheelGetSuspensionHeight(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionHeight") ? wheelGeometry(j).height : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionKp(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionKp") ? j->kp : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionKd(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionKd") ? j->kd : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionLimitSoftness(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionLimitSoftness") ? j->limitSoftness : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionLowLimit(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionLowLimit") ? j->suspension.limit[0].stop : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionHighLimit(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionHighLimit") ? j->suspension.limit[1].stop : 0;
}
MeReal MEAPI MdtCarWheelGetSuspensionReference(const MdtCarWheelID j) {
  return ok(j, "MdtCarWheelGetSuspensionReference") ? j->reference : 0;
}

}  // extern "C"
