// mdt_internal.h: the private layout of worlds and bodies, shared by the Mdt
// sources. Not installed.
#pragma once

#include "MdtBody.h"
#include "MdtWorld.h"
#include "MePool.h"

#include <cmath>
#include <cstdint>

// The body. Velocities, forces and impulses are in world coordinates; the
// inertia tensor and its inverse are in the body frame. `tm` is the live TM
// handed out by MdtBodyGetTransformPtr: it is rebuilt from `q` and
// `position` whenever either changes.
struct MdtBody {
  MdtWorldID world;
  MeMatrix4 tm;
  MeVector3 position;
  MeVector4 q;
  MeVector3 velocity;
  MeVector3 angularVelocity;
  MeVector3 acceleration;
  MeVector3 angularAcceleration;
  MeVector3 force;
  MeVector3 torque;
  MeVector3 impulse;
  MeVector3 angularImpulse;
  MeReal mass;
  MeReal invMass;
  MeMatrix3 inertia;     // body frame, symmetric positive definite
  MeMatrix3 invInertia;  // body frame
  MeReal linearDamping;
  MeReal angularDamping;
  MeVector3 fastSpinAxis;
  MeBool fastSpinEnabled;
  MeBool enabled;
  void *userData;
  MeI32 sortKey;
  std::uint64_t serial;  // creation order within the world, for tie-breaks
};

struct MdtWorldPrivate {
  MePool bodies;
  MdtBody **order;  // scratch for the step order, maxBodies entries
  unsigned int maxBodies;
  unsigned int maxConstraints;
  unsigned int enabledCount;
  MeReal lengthScale;
  MeReal massScale;
  std::uint64_t nextSerial;
};

namespace karma::mdt {

inline bool realFinite(MeReal x) { return std::isfinite(x); }
inline bool realFinite3(MeReal a, MeReal b, MeReal c) {
  return realFinite(a) && realFinite(b) && realFinite(c);
}

// Rebuilds b->tm from b->q and b->position.
void updateTransform(MdtBody *b);
// Sets the default state of a freshly handed-out body.
void initBody(MdtBody *b, MdtWorldID world);
// Integrates one enabled body over h seconds and clears its accumulators.
void integrateBody(MdtBody *b, const MeVector3 gravity, MeReal h);
// w = R^T (Ib (R v)): a world vector through a body-frame tensor.
void applyBodyTensor(MeVector3 out, const MdtBody *b, MECONSTMATRIX MeMatrix3 tensor,
                     const MeVector3 v);

}  // namespace karma::mdt
