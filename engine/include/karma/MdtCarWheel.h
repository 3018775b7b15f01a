/* MdtCarWheel.h: the car wheel joint. Body 0 is the chassis, body 1 the
 * wheel. The wheel's centre of mass stays on the STEERING axis, a line fixed
 * in the chassis through the joint position; the wheel turns about its HINGE
 * axis, fixed in the wheel, which is kept perpendicular to the steering axis.
 * Left free: the spin about the hinge axis, the travel along the steering
 * axis (the suspension) and, unless the steering is locked, the steering
 * turn about the steering axis.
 *
 * Angles and heights:
 *   steering angle  the chassis's turn about the steering axis s relative
 *                   to the wheel, from where they were when the axes were
 *                   set, in [-pi, pi); rate s . (w_chassis - w_wheel). That
 *                   is a hinge's convention (MdtHinge.h: body 0 relative to
 *                   body 1), so a wheel turned +a about s (to the left for
 *                   s up) reads -a. The steering MOTOR drives the wheel's
 *                   rate relative to the chassis, s . (w_wheel - w_chassis):
 *                   a positive desired velocity turns the wheel positively
 *                   about s and makes the reported angle fall. The guide's
 *                   QuadBike controller (PASTE_12: motor speed
 *                   k (target + angle)) relies on these opposite signs, and
 *                   its handlebar hinge (PASTE_13: hinge angle -target) on
 *                   the hinge's convention, so both turn the same way;
 *   hinge angle     the wheel's turn about the hinge axis relative to the
 *                   chassis, in [0, 2 pi); rate h . (w_wheel - w_chassis);
 *   height          s . (wheel centre - joint position): how far the wheel
 *                   centre is along the steering axis s from the joint
 *                   position fixed in the chassis (the chassis origin unless
 *                   MdtCarWheelSetPosition moved it). Usually negative.
 *
 * Suspension: a damped spring F = -Kp (height - reference) - Kd d(height)/dt
 * along s between the chassis and the wheel (none while Kp and Kd are 0),
 * plus hard stops at the low and high limits. limit_softness > 0 makes the
 * stops give way like a contact of that softness (the world's epsilon
 * units): a force F pushes roughly F h^2 softness / gamma past a stop.
 * A static load L on a wheel sags it by L / Kp from the reference.
 *
 * Motors: limited-force motors drive the hinge rate and, when unlocked, the
 * steering rate (rad/s) with at most the given torque either way.
 *
 * Defaults (Reset, Appendix A): position at the chassis origin; steering
 * axis the world z axis and hinge axis the world y axis as they are when the
 * bodies are set (the chassis's z and the wheel's y for unrotated bodies);
 * steering unlocked with its motor holding the steering rate at 0 with up to
 * 1e9; hinge motor off (0, 0); Kp = Kd = 0, limit softness 0, low limit -1e9,
 * high limit 1e9, reference 0.
 *
 * For fast-turning wheels set the wheel's fast-spin axis to the hinge axis
 * (MdtCarWheelGetHingeAxis) before every step (MdtBodySetFastSpinAxis). */
#ifndef KARMA_MDTCARWHEEL_H
#define KARMA_MDTCARWHEEL_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(CarWheel, MdtCarWheelID)
MDT_CONSTRAINT_COMMON_API(CarWheel, MdtCarWheelID)
MDT_CONSTRAINT_POSITION_API(CarWheel, MdtCarWheelID)

/* Both axes in world coordinates; they must be perpendicular (cosine below
 * 1e-3) and non-zero. The present steering turn becomes angle 0. */
MEPUBLIC void MEAPI MdtCarWheelSetSteeringAndHingeAxes(const MdtCarWheelID joint, const MeReal xSteer,
                                                       const MeReal ySteer, const MeReal zSteer, const MeReal xHinge,
                                                       const MeReal yHinge, const MeReal zHinge);
/* World coordinates, as they are now (steering: the chassis's; hinge: the
 * wheel's). */
MEPUBLIC void MEAPI MdtCarWheelGetSteeringAxis(const MdtCarWheelID joint, MeVector3 steeringAxis);
MEPUBLIC void MEAPI MdtCarWheelGetHingeAxis(const MdtCarWheelID joint, MeVector3 hingeAxis);

MEPUBLIC MeReal MEAPI MdtCarWheelGetHingeAngle(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetHingeAngleRate(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSteeringAngle(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSteeringAngleRate(const MdtCarWheelID joint);

/* forceLimit >= 0 and finite; 0 switches the motor off. */
MEPUBLIC void MEAPI MdtCarWheelSetHingeLimitedForceMotor(const MdtCarWheelID joint, const MeReal desiredVelocity,
                                                         const MeReal forceLimit);
MEPUBLIC MeReal MEAPI MdtCarWheelGetHingeMotorDesiredVelocity(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetHingeMotorMaxForce(const MdtCarWheelID joint);
MEPUBLIC void MEAPI MdtCarWheelSetSteeringLimitedForceMotor(const MdtCarWheelID joint, const MeReal desiredVelocity,
                                                            const MeReal forceLimit);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSteeringMotorDesiredVelocity(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSteeringMotorMaxForce(const MdtCarWheelID joint);

/* Locked: the steering angle is held at 0 (the steering motor is ignored). */
MEPUBLIC void MEAPI MdtCarWheelSetSteeringLock(const MdtCarWheelID joint, const MeBool lock);
MEPUBLIC MeBool MEAPI MdtCarWheelIsSteeringLocked(const MdtCarWheelID joint);

/* Kp, Kd, limit_softness >= 0 and finite; lolimit <= hilimit (they are
 * swapped otherwise); all finite. Rejected as a whole on bad input. */
MEPUBLIC void MEAPI MdtCarWheelSetSuspension(const MdtCarWheelID joint, const MeReal Kp, const MeReal Kd,
                                             const MeReal limit_softness, const MeReal lolimit, const MeReal hilimit,
                                             const MeReal reference);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionHeight(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionKp(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionKd(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionLimitSoftness(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionLowLimit(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionHighLimit(const MdtCarWheelID joint);
MEPUBLIC MeReal MEAPI MdtCarWheelGetSuspensionReference(const MdtCarWheelID joint);
ME_EXTERN_C_END

#endif
