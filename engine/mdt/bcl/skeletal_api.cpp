// skeletal_api.cpp: the skeletal joint's accessors and mutators.
#include <cmath>

#include "joint_input.h"
#include "skeletal.h"

using namespace karma::mdt;

namespace {

bool ok(const MdtSkeletal *j, const char *fn) { return checkType(j, kSkeletalType, fn); }

bool angleOk(MeReal a, bool zeroAllowed, const char *fn) {
  const bool good = (zeroAllowed ? a >= 0 : a > 0) && a <= (MeReal)ME_PI;
  if (!good) MeWarning(0, "%s: angle %g must be in %s0, pi]; ignored", fn, (double)a, zeroAllowed ? "[" : "(");
  return good;
}

void setStiffness(MdtSkeletal *j, MeReal MdtSkeletal::*field, MeReal k, const char *fn) {
  if (!ok(j, fn) || !nonNegative(k, fn, "stiffness")) return;
  j->*field = k > MEINFINITY ? MEINFINITY : k;
}

void setDamping(MdtSkeletal *j, MeReal MdtSkeletal::*field, MeReal d, const char *fn) {
  if (!ok(j, fn)) return;
  if (!(d >= 0) || !realFinite(d)) {
    MeWarning(0, "%s: damping %g must be finite and >= 0; ignored", fn, (double)d);
    return;
  }
  j->*field = d;
}

}  // namespace

extern "C" {

void MEAPI MdtSkeletalSetAxes(const MdtSkeletalID j, const MeReal px, const MeReal py, const MeReal pz, const MeReal ox,
                              const MeReal oy, const MeReal oz) {
  static const char *fn = "MdtSkeletalSetAxes";
  if (!ok(j, fn)) return;
  MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
  if (!orthogonalAxes(p, o, fn)) return;
  setWorldAxes(j, p, o);
  j->warmRows = 0;
}

void MEAPI MdtSkeletalGetAxes(const MdtSkeletalID j, MeVector3 primary, MeVector3 secondary) {
  static const char *fn = "MdtSkeletalGetAxes";
  if (!ok(j, fn)) return;
  ME_REQUIRE_ARG(primary != nullptr && secondary != nullptr, fn, "NULL argument");
  attachmentAxis(j, 0, primary);
  attachmentOrtho(j, 0, secondary);
}

void MEAPI MdtSkeletalSetConePrimaryLimitAngle(const MdtSkeletalID j, const MeReal theta) {
  static const char *fn = "MdtSkeletalSetConePrimaryLimitAngle";
  if (ok(j, fn) && angleOk(theta, false, fn)) j->primary = theta;
}
void MEAPI MdtSkeletalSetConeSecondaryLimitAngle(const MdtSkeletalID j, const MeReal theta) {
  static const char *fn = "MdtSkeletalSetConeSecondaryLimitAngle";
  if (ok(j, fn) && angleOk(theta, false, fn)) j->secondary = theta;
}
void MEAPI MdtSkeletalSetTwistLimitAngle(const MdtSkeletalID j, const MeReal theta) {
  static const char *fn = "MdtSkeletalSetTwistLimitAngle";
  if (ok(j, fn) && angleOk(theta, true, fn)) j->twist = theta;
}
MeReal MEAPI MdtSkeletalGetConePrimaryLimitAngle(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetConePrimaryLimitAngle") ? j->primary : 0;
}
MeReal MEAPI MdtSkeletalGetConeSecondaryLimitAngle(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetConeSecondaryLimitAngle") ? j->secondary : 0;
}
MeReal MEAPI MdtSkeletalGetTwistLimitAngle(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetTwistLimitAngle") ? j->twist : 0;
}

void MEAPI MdtSkeletalSetConeStiffness(const MdtSkeletalID j, const MeReal kp) {
  setStiffness(j, &MdtSkeletal::coneStiffness, kp, "MdtSkeletalSetConeStiffness");
}
void MEAPI MdtSkeletalSetConeDamping(const MdtSkeletalID j, const MeReal kd) {
  setDamping(j, &MdtSkeletal::coneDamping, kd, "MdtSkeletalSetConeDamping");
}
void MEAPI MdtSkeletalSetTwistStiffness(const MdtSkeletalID j, const MeReal kp) {
  setStiffness(j, &MdtSkeletal::twistStiffness, kp, "MdtSkeletalSetTwistStiffness");
}
void MEAPI MdtSkeletalSetTwistDamping(const MdtSkeletalID j, const MeReal kd) {
  setDamping(j, &MdtSkeletal::twistDamping, kd, "MdtSkeletalSetTwistDamping");
}
MeReal MEAPI MdtSkeletalGetConeStiffness(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetConeStiffness") ? j->coneStiffness : 0;
}
MeReal MEAPI MdtSkeletalGetConeDamping(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetConeDamping") ? j->coneDamping : 0;
}
MeReal MEAPI MdtSkeletalGetTwistStiffness(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetTwistStiffness") ? j->twistStiffness : 0;
}
MeReal MEAPI MdtSkeletalGetTwistDamping(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetTwistDamping") ? j->twistDamping : 0;
}

MeReal MEAPI MdtSkeletalGetSwingAngle(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetSwingAngle") ? skeletalAngles(j).theta : 0;
}
MeReal MEAPI MdtSkeletalGetTwistAngle(const MdtSkeletalID j) {
  return ok(j, "MdtSkeletalGetTwistAngle") ? skeletalAngles(j).twist : 0;
}

}  // extern "C"
