// mdt_internal.h: the private layout of worlds and bodies, shared by the Mdt
// sources. Not installed.
#pragma once

#include "MdtBody.h"
#include "MdtWorld.h"
#include "MePool.h"
#include "bridge/mdt_bridge.h"

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
  MeMatrix3 inertia;     // about the centre of mass, body axes, symmetric positive definite
  MeMatrix3 invInertia;  // body axes
  MeMatrix3 inertiaCom;  // as the user gave it: about the centre of mass, COM frame axes
  MeMatrix4 comTM;       // centre-of-mass frame relative to the body frame
  MeReal linearDamping;
  MeReal angularDamping;
  MeVector3 fastSpinAxis;
  MeBool fastSpinEnabled;
  MdtGyroscopicMode gyroscopicMode;
  // Classification of `inertia` for the gyroscopic rules (gyroscopic.cpp),
  // kept by updateInertia: spherical within a relative 1e-6, exactly
  // spherical, and the infinity norm of invInertia.
  MeBool inertiaSpherical;
  MeBool inertiaExactlySpherical;
  MeReal invInertiaNorm;
  MeBool enabled;
  MeBool alive;          // TRUE from MdtBodyCreate to MdtBodyDestroy (stale handles are refused)
  MdtBody *nextRetired;  // destroyed bodies waiting for reuse, oldest first
  void *userData;
  void *collisionModel;  // the bridge's slot (bridge/mdt_bridge.h); never read here
  MeI32 sortKey;
  std::uint64_t serial;  // creation order within the world, for tie-breaks
  MeReal idleTime;       // seconds spent below every auto-disable threshold
  MeReal awakeTime;      // seconds stepped since the body was last enabled
  int awakeSteps;        // steps since the body was last enabled
  // Scratch of the step: velocities after forces but before constraints,
  // the world-frame inverse inertia, and the body's index in its partition.
  MeVector3 vPred;
  MeVector3 wPred;
  MeMatrix3 invInertiaWorld;
  MeMatrix3 geomStiffness;  // world frame, from last step's constraint forces
  int index;
  int mark;
  // Active sets (active_sets.h): the index in the awake list, whether the
  // body is in the driven list, and the head of its list of constraints.
  int awakeSlot;
  MeBool drivenListed;
  struct MdtConstraint *firstConstraint;
};

namespace karma::platform {
struct Kernels;
}  // namespace karma::platform

namespace karma::mdt {
struct StepScratch;
// Constraint pools a world may have: the first and up to this many grown
// ones, each doubling the slots (constraint_slots.cpp).
inline constexpr int kMaxConstraintPools = 24;
// Constraint slots start on a cache line, so that the fields a type keeps
// together in one line (contact_internal.h) take one line.
inline constexpr int kConstraintSlotAlignment = 64;
// Released constraint slots a world holds back from reuse (constraint.h, "Slots").
inline constexpr int kHeldConstraintSlots = 64;
struct ActiveSets;
}  // namespace karma::mdt

struct MdtWorldPrivate {
  MePool bodies;
  MePool constraints;  // every constraint type, slots of the largest size
  // Pools added when `constraints` is full (constraint_slots.cpp).
  MePool overflow[karma::mdt::kMaxConstraintPools];
  int overflowCount;
  MeBool grewConstraints;  // the growth has been reported
  // The last released constraint slots, still in use in their pools, oldest
  // at heldSlots[heldFirst], heldCount of them in ring order.
  void *heldSlots[karma::mdt::kHeldConstraintSlots];
  int heldFirst;
  int heldCount;
  unsigned constraintSlotSize;
  std::uint64_t nextConstraintSerial;
  karma::mdt::StepScratch *scratch;  // step work arrays, reused across steps
  karma::mdt::ActiveSets *active;    // what the step touches (active_sets.h)
  MdtContactImportanceCBPtr importance;
  MdtBodyEnableCallbackPtr bodyEnableCB;  // called by MdtBodyEnable / MdtBodyDisable
  void *bodyEnableData;
  // Called by MdtBodyDestroy for a body that still has a collision model
  // (bridge/mdt_bridge.h), before the body goes.
  MdtBodyDestroyCallbackPtr bodyDestroyCB;
  // Destroyed bodies keep their pool slot, oldest first, until the pool has
  // no never-used or long-free slot left (body_lifecycle.cpp).
  MdtBody *retiredHead;
  MdtBody *retiredTail;
  unsigned int retiredCount;
  unsigned int maxBodies;
  unsigned int maxConstraints;
  unsigned int enabledCount;
  MeReal lengthScale;
  MeReal massScale;
  MeReal lastStepSize;  // of the last MdtWorldStep, 0 before the first
  std::uint64_t nextSerial;
  MdtWorldParams checked;              // params as last validated (world_params.cpp)
  int debugDrawOptions;                // MdtWorldSetDebugDrawOptions, stored only
  MdtAliveWindowMode aliveWindowMode;  // how the alive window counts (sleep.cpp)
  MeBool forcesDoNotWake;              // MdtWorldSetWakeByForce(world, 0): the FAQ's reading
  // The platform backend the step runs on (MdtWorldSetPlatform): never
  // NULL, always one the CPU supports; the process default at creation.
  const karma::platform::Kernels *kernels;
};

namespace karma::mdt {

inline bool realFinite(MeReal x) { return std::isfinite(x); }
inline bool realFinite3(MeReal a, MeReal b, MeReal c) { return realFinite(a) && realFinite(b) && realFinite(c); }

// True for a body between MdtBodyCreate and MdtBodyDestroy; for NULL or a
// destroyed body (a stale handle) it warns, naming `fn`, and is false. A
// slot is reused only after every other free one (body_lifecycle.cpp), so
// a stale handle is caught until the pool cycles back to its slot.
bool liveBody(const MdtBody *b, const char *fn);

// Rebuilds b->tm from b->q and b->position.
void updateTransform(MdtBody *b);
// World position of the centre of mass (the body origin when not offset).
void bodyCom(const MdtBody *b, MeVector3 out);
// Recomputes inertia / invInertia (body axes) from inertiaCom and comTM.
void updateInertia(MdtBody *b);
// Sets the default state of a freshly handed-out body.
void initBody(MdtBody *b, MdtWorldID world);
// The step of one body, in three stages:
//   predictVelocities: vPred, wPred from the forces and impulses (and the
//                      world-frame inverse inertia for the solver);
//   (the solver adds constraint impulses with applyImpulse)
//   advanceBody:       position and orientation from vPred, wPred; clears
//                      the accumulators.
void predictVelocities(MdtBody *b, const MeVector3 gravity, MeReal h);
void applyImpulse(MdtBody *b, const MeVector3 linear, const MeVector3 angular);
void advanceBody(MdtBody *b, MeReal h);
// The torque-free turn over h of a body whose angular velocity is w1 at the
// start (rotation_drift.cpp): `turn` is the world angular velocity to hold
// over h, `wEndBody` the body-frame angular velocity at the end; the world
// angular momentum and the kinetic energy are kept.
void freeRotationDrift(const MdtBody *b, const MeVector3 w1, MeReal h, MeVector3 turn, MeVector3 wEndBody);
// The torque-free turn of a body whose gyroscopic term is left out: the
// world angular velocity w1 is held over h (rotation_drift.cpp), `turn` is
// w1 with the same angle limit as freeRotationDrift.
void plainRotationTurn(const MeVector3 w1, MeReal h, MeVector3 turn);
// Sets b's inertia classification from b->inertia and b->invInertia
// (gyroscopic.cpp); called by updateInertia.
void classifyInertia(MdtBody *b);
// Whether this step computes b's gyroscopic term at angular velocity w
// (world frame), by its mode and the rules of gyroscopic.cpp.
bool gyroscopicActs(const MdtBody *b, const MeVector3 w, MeReal h);
// w = R^T (Ib (R v)): a world vector through a body-frame tensor.
void applyBodyTensor(MeVector3 out, const MdtBody *b, MECONSTMATRIX MeMatrix3 tensor, const MeVector3 v);
// out = R^T Ib R: a body-frame tensor in the world frame, column k being
// applyBodyTensor of the k-th unit vector.
void bodyTensorInWorld(MeMatrix3 out, const MdtBody *b, MECONSTMATRIX MeMatrix3 tensor);

// The direct-write check of the world parameters (world_params.cpp):
// rememberCheckedParams when the world is made, checkDirectParamWrites at
// the start of each step.
void rememberCheckedParams(MdtWorldID world);
void checkDirectParamWrites(MdtWorldID world);
// Wakes each disabled body whose accumulated force, torque or impulse is
// above the auto-disable thresholds (sleep.cpp); called before partitions
// are built. The accumulators of the bodies that stay disabled are cleared.
void wakeDrivenBodies(MdtWorldID world);
// The world as a diagnostic source (MeDiagnostics.h; world_diagnostics.cpp),
// from MdtWorldCreate to MdtWorldDestroy.
void registerWorldDiagnostics(MdtWorldID world);
void unregisterWorldDiagnostics(MdtWorldID world);

}  // namespace karma::mdt
