// body_mass.cpp: mass, inertia tensor and velocity damping.
#include "MeMessage.h"
#include "mdt_internal.h"

using namespace karma::mdt;

namespace {
constexpr const char *kNull = "body is NULL";
}

extern "C" {

void MEAPI MdtBodySetMass(const MdtBodyID body, const MeReal mass) {
  static const char *fn = "MdtBodySetMass";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite(mass) && mass > 0 && realFinite((MeReal)1 / mass), fn,
                 "mass must be positive and finite, got %g; ignored", (double)mass);
  body->mass = mass;
  body->invMass = (MeReal)1 / mass;
}

MeReal MEAPI MdtBodyGetMass(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetMass")) return (MeReal)0;
  return body->mass;
}

// Accepts a tensor when it is finite, symmetric to a relative 1e-4, and
// positive definite (Sylvester: the three leading minors are positive).
// The stored tensor is the symmetric part of the argument.
void MEAPI MdtBodySetInertiaTensor(const MdtBodyID body, MECONSTMATRIX MeMatrix3 I) {
  static const char *fn = "MdtBodySetInertiaTensor";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(I != nullptr, fn, "NULL argument");
  bool isFinite = true;
  MeReal largest = 0;
  for (int i = 0; i < 3; ++i) {
    isFinite = isFinite && MeVector3AllFinite(I[i]);
    for (int j = 0; j < 3; ++j) largest = std::fmax(largest, MeFabs(I[i][j]));
  }
  ME_REQUIRE_ARG(isFinite, fn, "tensor is not finite; ignored");
  const MeReal tol = (MeReal)1e-4 * largest;
  const bool symmetric =
      MeFabs(I[0][1] - I[1][0]) <= tol && MeFabs(I[0][2] - I[2][0]) <= tol && MeFabs(I[1][2] - I[2][1]) <= tol;
  ME_REQUIRE_ARG(symmetric, fn, "tensor is not symmetric; ignored");
  MeMatrix3 S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) S[i][j] = (MeReal)0.5 * (I[i][j] + I[j][i]);
  const MeReal minor2 = S[0][0] * S[1][1] - S[0][1] * S[1][0];
  const MeReal det = MeMatrix3Determinant(S);
  ME_REQUIRE_ARG(S[0][0] > 0 && minor2 > 0 && det > 0, fn,
                 "tensor is not positive definite (leading minors %g, %g, %g); ignored", (double)S[0][0],
                 (double)minor2, (double)det);
  MeMatrix3 inv;
  ME_REQUIRE_ARG(MeMatrix3Inverse(inv, S), fn, "tensor is singular; ignored");
  MeMatrix3Copy(body->inertiaCom, S);
  updateInertia(body);
}

void MEAPI MdtBodyGetInertiaTensor(const MdtBodyID body, MeMatrix3 I) {
  if (!liveBody(body, "MdtBodyGetInertiaTensor")) return;
  ME_REQUIRE_ARG(I != nullptr, "MdtBodyGetInertiaTensor", "NULL argument");
  MeMatrix3Copy(I, body->inertiaCom);
}

void MEAPI MdtBodySetLinearVelocityDamping(const MdtBodyID body, const MeReal d) {
  static const char *fn = "MdtBodySetLinearVelocityDamping";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite(d) && d >= 0, fn, "damping must be finite and >= 0, got %g; ignored", (double)d);
  body->linearDamping = d;
}

MeReal MEAPI MdtBodyGetLinearVelocityDamping(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetLinearVelocityDamping")) return (MeReal)0;
  return body->linearDamping;
}

void MEAPI MdtBodySetAngularVelocityDamping(const MdtBodyID body, const MeReal d) {
  static const char *fn = "MdtBodySetAngularVelocityDamping";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(realFinite(d) && d >= 0, fn, "damping must be finite and >= 0, got %g; ignored", (double)d);
  body->angularDamping = d;
}

MeReal MEAPI MdtBodyGetAngularVelocityDamping(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetAngularVelocityDamping")) return (MeReal)0;
  return body->angularDamping;
}

}  // extern "C"
