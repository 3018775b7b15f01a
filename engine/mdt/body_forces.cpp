// body_forces.cpp: the force, torque and impulse accumulators.
//
// Additions are checked before they land: a non-finite input, or a sum that
// would overflow, is rejected with a warning and leaves the accumulator as
// it was.
#include "MeMessage.h"
#include "active_sets.h"

using namespace karma::mdt;

namespace {

// acc += v, unless v or the sum is not finite. Returns false when rejected.
bool accumulate(MeVector3 acc, const MeVector3 v) {
  if (!MeVector3AllFinite(v)) return false;
  MeVector3 sum;
  MeVector3Add(sum, acc, v);
  if (!MeVector3AllFinite(sum)) return false;
  MeVector3Copy(acc, sum);
  return true;
}

// Linear and angular part of v applied at world point p: r = p - centre of mass.
bool accumulateAt(MdtBody *b, MeVector3 lin, MeVector3 ang, const MeVector3 v, const MeVector3 p) {
  if (!MeVector3AllFinite(v) || !MeVector3AllFinite(p)) return false;
  MeVector3 r, m, newLin, newAng;
  MeVector3 com;
  bodyCom(b, com);
  MeVector3Subtract(r, p, com);
  MeVector3Cross(m, r, v);
  MeVector3Add(newLin, lin, v);
  MeVector3Add(newAng, ang, m);
  if (!MeVector3AllFinite(newLin) || !MeVector3AllFinite(newAng)) return false;
  MeVector3Copy(lin, newLin);
  MeVector3Copy(ang, newAng);
  return true;
}

}  // namespace

extern "C" {

void MEAPI MdtBodyAddForce(const MdtBodyID body, const MeReal fx, const MeReal fy, const MeReal fz) {
  static const char *fn = "MdtBodyAddForce";
  if (!liveBody(body, fn)) return;
  noteDriven(body);
  const MeVector3 f = {fx, fy, fz};
  ME_REQUIRE_ARG(accumulate(body->force, f), fn, "force (%g, %g, %g) is not finite or overflows; ignored", (double)fx,
                 (double)fy, (double)fz);
}

void MEAPI MdtBodyAddTorque(const MdtBodyID body, const MeReal tx, const MeReal ty, const MeReal tz) {
  static const char *fn = "MdtBodyAddTorque";
  if (!liveBody(body, fn)) return;
  noteDriven(body);
  const MeVector3 t = {tx, ty, tz};
  ME_REQUIRE_ARG(accumulate(body->torque, t), fn, "torque (%g, %g, %g) is not finite or overflows; ignored", (double)tx,
                 (double)ty, (double)tz);
}

void MEAPI MdtBodyAddForceAtPosition(const MdtBodyID body, const MeReal fx, const MeReal fy, const MeReal fz,
                                     const MeReal px, const MeReal py, const MeReal pz) {
  static const char *fn = "MdtBodyAddForceAtPosition";
  if (!liveBody(body, fn)) return;
  noteDriven(body);
  const MeVector3 f = {fx, fy, fz};
  const MeVector3 p = {px, py, pz};
  ME_REQUIRE_ARG(accumulateAt(body, body->force, body->torque, f, p), fn,
                 "force (%g, %g, %g) at (%g, %g, %g) is not finite or overflows; ignored", (double)fx, (double)fy,
                 (double)fz, (double)px, (double)py, (double)pz);
}

void MEAPI MdtBodyAddImpulse(const MdtBodyID body, const MeReal jx, const MeReal jy, const MeReal jz) {
  static const char *fn = "MdtBodyAddImpulse";
  if (!liveBody(body, fn)) return;
  noteDriven(body);
  const MeVector3 j = {jx, jy, jz};
  ME_REQUIRE_ARG(accumulate(body->impulse, j), fn, "impulse (%g, %g, %g) is not finite or overflows; ignored",
                 (double)jx, (double)jy, (double)jz);
}

void MEAPI MdtBodyAddImpulseAtPosition(const MdtBodyID body, const MeReal jx, const MeReal jy, const MeReal jz,
                                       const MeReal px, const MeReal py, const MeReal pz) {
  static const char *fn = "MdtBodyAddImpulseAtPosition";
  if (!liveBody(body, fn)) return;
  noteDriven(body);
  const MeVector3 j = {jx, jy, jz};
  const MeVector3 p = {px, py, pz};
  ME_REQUIRE_ARG(accumulateAt(body, body->impulse, body->angularImpulse, j, p), fn,
                 "impulse (%g, %g, %g) at (%g, %g, %g) is not finite or overflows; ignored", (double)jx, (double)jy,
                 (double)jz, (double)px, (double)py, (double)pz);
}

void MEAPI MdtBodyGetForce(const MdtBodyID body, MeVector3 f) {
  if (!liveBody(body, "MdtBodyGetForce")) return;
  ME_REQUIRE_ARG(f != nullptr, "MdtBodyGetForce", "NULL argument");
  MeVector3Copy(f, body->force);
}

void MEAPI MdtBodyGetTorque(const MdtBodyID body, MeVector3 t) {
  if (!liveBody(body, "MdtBodyGetTorque")) return;
  ME_REQUIRE_ARG(t != nullptr, "MdtBodyGetTorque", "NULL argument");
  MeVector3Copy(t, body->torque);
}

void MEAPI MdtBodyGetImpulse(const MdtBodyID body, MeVector3 j) {
  if (!liveBody(body, "MdtBodyGetImpulse")) return;
  ME_REQUIRE_ARG(j != nullptr, "MdtBodyGetImpulse", "NULL argument");
  MeVector3Copy(j, body->impulse);
}

void MEAPI MdtBodyGetAngularImpulse(const MdtBodyID body, MeVector3 j) {
  if (!liveBody(body, "MdtBodyGetAngularImpulse")) return;
  ME_REQUIRE_ARG(j != nullptr, "MdtBodyGetAngularImpulse", "NULL argument");
  MeVector3Copy(j, body->angularImpulse);
}

void MEAPI MdtBodyResetForces(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyResetForces")) return;
  MeVector3Set(body->force, 0, 0, 0);
  MeVector3Set(body->torque, 0, 0, 0);
}

void MEAPI MdtBodyResetImpulses(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyResetImpulses")) return;
  MeVector3Set(body->impulse, 0, 0, 0);
  MeVector3Set(body->angularImpulse, 0, 0, 0);
}

}  // extern "C"
