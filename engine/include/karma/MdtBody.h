/* MdtBody.h: rigid bodies of a dynamics world.
 *
 * A body has a position (of its dynamics origin), an orientation kept as a
 * unit quaternion (w, x, y, z), linear and angular velocity in WORLD
 * coordinates, a mass and an inertia tensor given in the BODY frame, and
 * accumulators for force, torque and impulse.
 *
 * Defaults of a new body (l, m: the world's length and mass scales):
 * disabled; mass m; inertia 0.4 m l^2 I; at the origin with the identity
 * orientation; at rest; no damping; fast-spin axis (0, 1, 0), not in use;
 * gyroscopic mode MdtGyroscopicAuto; user data NULL; sort key 0; empty
 * accumulators.
 *
 * Accumulators: MdtBodyAdd* adds into them; a step uses them on every
 * enabled body and then clears them. A disabled body keeps what was added
 * until the first step in which it is enabled. An impulse J changes the
 * velocity by J/m in that step, independently of the step size.
 *
 * Bad input (NULL body, non-finite numbers, non-positive mass, a tensor that
 * is not symmetric positive definite, a zero quaternion or axis) is rejected
 * in every build: a warning names the function and the call has no effect. */
#ifndef KARMA_MDTBODY_H
#define KARMA_MDTBODY_H
#include "MeCall.h"
#include "MePrecision.h"
#include "MeMath.h"
#include "MdtWorld.h"

ME_EXTERN_C_BEGIN

/* Creates a disabled body in `world`; NULL (with one warning) when the
 * world's body pool is full. */
MEPUBLIC MdtBodyID MEAPI MdtBodyCreate(const MdtWorldID world);
/* Returns the body to its world's pool. NULL is ignored. The constraints
 * that used it are disabled and left without bodies, each attachment where
 * it was in the world and the last step's force and torque zero. */
MEPUBLIC void MEAPI MdtBodyDestroy(const MdtBodyID body);

MEPUBLIC void MEAPI MdtBodyEnable(const MdtBodyID body);
MEPUBLIC void MEAPI MdtBodyDisable(const MdtBodyID body);
MEPUBLIC MeBool MEAPI MdtBodyIsEnabled(const MdtBodyID body);
MEPUBLIC MdtWorldID MEAPI MdtBodyGetWorld(const MdtBodyID body);

/* ---- kinematic state ---------------------------------------------------- */

MEPUBLIC void MEAPI MdtBodySetPosition(const MdtBodyID body, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtBodyGetPosition(const MdtBodyID body, MeVector3 position);
/* Normalised on the way in; a zero or non-finite quaternion is rejected. */
MEPUBLIC void MEAPI MdtBodySetQuaternion(const MdtBodyID body, const MeReal qw, const MeReal qx, const MeReal qy,
                                         const MeReal qz);
MEPUBLIC void MEAPI MdtBodyGetQuaternion(const MdtBodyID body, MeVector4 q);
/* R: rows are the body axes in world coordinates. It is converted to a
 * quaternion (so a slightly non-orthonormal R is cleaned up); a matrix that
 * is far from a rotation is rejected. */
MEPUBLIC void MEAPI MdtBodySetOrientation(const MdtBodyID body, MECONSTMATRIX MeMatrix3 R);
MEPUBLIC void MEAPI MdtBodyGetOrientation(const MdtBodyID body, MeMatrix3 R);
/* Copies the body's TM (rotation rows 0-2, position row 3). */
MEPUBLIC void MEAPI MdtBodyGetTransform(const MdtBodyID body, MeMatrix4 tm);
/* The body's own TM: the same pointer for the body's whole life, kept up to
 * date by every step and every change of position or orientation. Read only. */
MEPUBLIC MeMatrix4Ptr MEAPI MdtBodyGetTransformPtr(const MdtBodyID body);

MEPUBLIC void MEAPI MdtBodySetLinearVelocity(const MdtBodyID body, const MeReal dx, const MeReal dy, const MeReal dz);
MEPUBLIC void MEAPI MdtBodyGetLinearVelocity(const MdtBodyID body, MeVector3 v);
/* World coordinates (rad/s). */
MEPUBLIC void MEAPI MdtBodySetAngularVelocity(const MdtBodyID body, const MeReal wx, const MeReal wy, const MeReal wz);
MEPUBLIC void MEAPI MdtBodyGetAngularVelocity(const MdtBodyID body, MeVector3 w);
/* Change of velocity over the last step divided by its length (zero before
 * the first step the body takes part in). */
MEPUBLIC void MEAPI MdtBodyGetLinearAcceleration(const MdtBodyID body, MeVector3 a);
MEPUBLIC void MEAPI MdtBodyGetAngularAcceleration(const MdtBodyID body, MeVector3 a);

/* ---- mass properties ------------------------------------------------------ */

/* mass > 0 and finite. Does not change the inertia tensor. */
MEPUBLIC void MEAPI MdtBodySetMass(const MdtBodyID body, const MeReal mass);
MEPUBLIC MeReal MEAPI MdtBodyGetMass(const MdtBodyID body);
/* Full 3x3 tensor about the centre of mass, in the centre-of-mass frame
 * (the body frame unless a relative transform with a rotation is set); must
 * be symmetric and positive definite. */
MEPUBLIC void MEAPI MdtBodySetInertiaTensor(const MdtBodyID body, MECONSTMATRIX MeMatrix3 I);
MEPUBLIC void MEAPI MdtBodyGetInertiaTensor(const MdtBodyID body, MeMatrix3 I);

/* Centre of mass relative to the body frame (default: at the origin, same
 * axes). The body's position and TM stay those of its body frame (what
 * models and graphics follow); the dynamics turns the body about its centre
 * of mass. The inertia tensor is about the centre of mass, in the axes of
 * this transform. Linear velocity is the centre of mass's; MdtBodyAddForce
 * acts through the centre of mass, and lever arms (AtPosition, joints,
 * contacts) are measured from it. */
MEPUBLIC void MEAPI MdtBodySetCenterOfMassRelativeTransform(const MdtBodyID body, MECONSTMATRIX MeMatrix4 tm);
MEPUBLIC void MEAPI MdtBodyGetCenterOfMassRelativeTransform(const MdtBodyID body, MeMatrix4 tm);
MEPUBLIC void MEAPI MdtBodySetCenterOfMassRelativePosition(const MdtBodyID body, const MeVector3 pos);
MEPUBLIC void MEAPI MdtBodyGetCenterOfMassRelativePosition(const MdtBodyID body, MeVector3 pos);
/* World position of the centre of mass. */
MEPUBLIC void MEAPI MdtBodyGetCenterOfMassPosition(const MdtBodyID body, MeVector3 pos);

/* Velocity damping: a drag force -d v (linear) and torque -d w (angular)
 * added in every step; d >= 0 and finite. */
MEPUBLIC void MEAPI MdtBodySetLinearVelocityDamping(const MdtBodyID body, const MeReal d);
MEPUBLIC MeReal MEAPI MdtBodyGetLinearVelocityDamping(const MdtBodyID body);
MEPUBLIC void MEAPI MdtBodySetAngularVelocityDamping(const MdtBodyID body, const MeReal d);
MEPUBLIC MeReal MEAPI MdtBodyGetAngularVelocityDamping(const MdtBodyID body);

/* Fast-spin axis (world coordinates, normalised): when in use, the step
 * turns the body separately about this axis and about the rest of its
 * angular velocity, which keeps small off-axis turns of fast spinners (car
 * wheels) accurate. Setting an axis puts it in use; a zero axis is rejected. */
MEPUBLIC void MEAPI MdtBodySetFastSpinAxis(const MdtBodyID body, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtBodyGetFastSpinAxis(const MdtBodyID body, MeVector3 axis);
MEPUBLIC void MEAPI MdtBodyDisableFastSpinAxis(const MdtBodyID body);
MEPUBLIC MeBool MEAPI MdtBodyIsFastSpinAxisEnabled(const MdtBodyID body);

/* Gyroscopic effect (an extension of this engine; not in Karma 1.2): the
 * term w x Iw w of Euler's equation, by which a spinning body whose principal
 * moments differ tumbles and precesses while its world angular momentum
 * stays fixed. Without it a body keeps its world angular velocity and turns
 * about it. The modes:
 *   MdtGyroscopicAuto    (the default) computed, except when the body's
 *                        three principal moments are equal within a relative
 *                        1e-6 (the term is then zero, or within a few 1e-6 of
 *                        zero) or when this step's spin makes it smaller than
 *                        the rounding of the angular velocity:
 *                        h |w x Iw w| |Ib^-1| <= epsilon |w|;
 *   MdtGyroscopicAlways  computed at any spin; left out only when the three
 *                        principal moments are exactly equal (the term is
 *                        then exactly zero);
 *   MdtGyroscopicNever   never computed.
 * Any other value is rejected with a warning. */
typedef enum MdtGyroscopicMode {
  MdtGyroscopicAuto = 0,
  MdtGyroscopicAlways = 1,
  MdtGyroscopicNever = 2
} MdtGyroscopicMode;
MEPUBLIC void MEAPI MdtBodySetGyroscopicMode(const MdtBodyID body, const MdtGyroscopicMode mode);
MEPUBLIC MdtGyroscopicMode MEAPI MdtBodyGetGyroscopicMode(const MdtBodyID body);

/* ---- user data and ordering ----------------------------------------------- */

MEPUBLIC void MEAPI MdtBodySetUserData(const MdtBodyID body, void *data);
MEPUBLIC void *MEAPI MdtBodyGetUserData(const MdtBodyID body);
/* Bodies are processed in increasing sort key, ties in creation order. */
MEPUBLIC void MEAPI MdtBodySetSortKey(const MdtBodyID body, const MeI32 key);
MEPUBLIC MeI32 MEAPI MdtBodyGetSortKey(const MdtBodyID body);

/* ---- forces, torques, impulses (world coordinates) ----------------------- */

MEPUBLIC void MEAPI MdtBodyAddForce(const MdtBodyID body, const MeReal fx, const MeReal fy, const MeReal fz);
MEPUBLIC void MEAPI MdtBodyAddTorque(const MdtBodyID body, const MeReal tx, const MeReal ty, const MeReal tz);
/* Force applied at world point p: adds F and the torque (p - position) x F. */
MEPUBLIC void MEAPI MdtBodyAddForceAtPosition(const MdtBodyID body, const MeReal fx, const MeReal fy, const MeReal fz,
                                              const MeReal px, const MeReal py, const MeReal pz);
MEPUBLIC void MEAPI MdtBodyAddImpulse(const MdtBodyID body, const MeReal jx, const MeReal jy, const MeReal jz);
/* Impulse at world point p: adds J and the angular impulse (p - position) x J. */
MEPUBLIC void MEAPI MdtBodyAddImpulseAtPosition(const MdtBodyID body, const MeReal jx, const MeReal jy, const MeReal jz,
                                                const MeReal px, const MeReal py, const MeReal pz);
/* The accumulated force / torque / linear impulse / angular impulse. */
MEPUBLIC void MEAPI MdtBodyGetForce(const MdtBodyID body, MeVector3 f);
MEPUBLIC void MEAPI MdtBodyGetTorque(const MdtBodyID body, MeVector3 t);
MEPUBLIC void MEAPI MdtBodyGetImpulse(const MdtBodyID body, MeVector3 j);
MEPUBLIC void MEAPI MdtBodyGetAngularImpulse(const MdtBodyID body, MeVector3 j);
/* Empty the force and torque / the linear and angular impulse accumulators. */
MEPUBLIC void MEAPI MdtBodyResetForces(const MdtBodyID body);
MEPUBLIC void MEAPI MdtBodyResetImpulses(const MdtBodyID body);

ME_EXTERN_C_END

#endif /* KARMA_MDTBODY_H */
