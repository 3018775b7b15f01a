/* MdtLimit.h: limits and motors on a joint's free degree of freedom (the
 * hinge angle, the prismatic slide, a car wheel's suspension, a spring's
 * length ...).
 *
 * A limit has a lower and an upper single limit (limit[0], limit[1]) and a
 * limited-force motor. Positions are in the user's coordinates:
 * position = measured coordinate + offset (MdtLimitSetPosition sets the
 * offset so that the current configuration reads as the given value).
 *
 * A single limit whose stiffness is ABOVE the stiffness threshold is HARD: it
 * stops the joint at `stop` and makes it rebound with `restitution` times the
 * impact speed (damping is ignored). At or below the threshold it is SOFT: a
 * damped spring (stiffness, damping) acting only beyond the stop, so a motor
 * pushing with torque T settles T/stiffness past it (restitution is ignored).
 * Stiffness and damping both zero switch that side off.
 *
 * The motor drives the joint's rate towards `motorDesiredVelocity` with a
 * force (torque) of at most `motorMaxForce` either way.
 *
 * Hinge angles are tracked through full turns, so stops beyond +-pi work.
 *
 * Members are public because programs written against the guide write, for
 * example, `limit->limit[0].restitution`; the functions below validate and
 * are preferred. Defaults (MdtLimitReset): stops 0, stiffness MEINFINITY,
 * damping 0, restitution 1, threshold MEINFINITY, not limited, no motor,
 * position not calculated, offset 0. */
#ifndef KARMA_MDTLIMIT_H
#define KARMA_MDTLIMIT_H
#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MdtSingleLimit {
  MeReal stop;        /* lower (limit[0]) or upper (limit[1]) bound of position */
  MeReal stiffness;   /* >= 0; spring constant of a soft stop */
  MeReal damping;     /* >= 0; damping of a soft stop */
  MeReal restitution; /* in [0, 1]; rebound ratio of a hard stop */
} MdtSingleLimit;
typedef MdtSingleLimit *MdtSingleLimitID;

typedef struct MdtLimit {
  MdtSingleLimit limit[2];   /* [0] lower, [1] upper */
  MeReal stiffnessThreshold; /* stiffness above this: hard stop */
  MeReal motorDesiredVelocity;
  MeReal motorMaxForce;     /* >= 0 */
  MeBool limited;           /* stops active */
  MeBool motorized;         /* motor active */
  MeBool calculatePosition; /* keep `position` and `velocity` up to date */
  MeReal offset;            /* user position = measured + offset */
  MeReal position;          /* last computed position (user coordinates) */
  MeReal velocity;          /* last computed rate */
  /* Bookkeeping for multi-turn angles; not for users. */
  MeReal rawPrevious;
  MeReal turns;
  MeBool rawValid;
} MdtLimit;
typedef MdtLimit *MdtLimitID;

/* ---- single limits ------------------------------------------------------ */
MEPUBLIC void MEAPI MdtSingleLimitReset(const MdtSingleLimitID sl);
MEPUBLIC MeReal MEAPI MdtSingleLimitGetStop(const MdtSingleLimitID sl);
MEPUBLIC MeReal MEAPI MdtSingleLimitGetStiffness(const MdtSingleLimitID sl);
MEPUBLIC MeReal MEAPI MdtSingleLimitGetDamping(const MdtSingleLimitID sl);
MEPUBLIC MeReal MEAPI MdtSingleLimitGetRestitution(const MdtSingleLimitID sl);
MEPUBLIC void MEAPI MdtSingleLimitSetStop(const MdtSingleLimitID sl, const MeReal stop);
/* Negative values are rejected (warning, no change). */
MEPUBLIC void MEAPI MdtSingleLimitSetStiffness(const MdtSingleLimitID sl, const MeReal k);
MEPUBLIC void MEAPI MdtSingleLimitSetDamping(const MdtSingleLimitID sl, const MeReal d);
/* Outside [0, 1] is rejected. */
MEPUBLIC void MEAPI MdtSingleLimitSetRestitution(const MdtSingleLimitID sl, const MeReal e);

/* ---- limits --------------------------------------------------------------- */
MEPUBLIC void MEAPI MdtLimitReset(const MdtLimitID limit);
MEPUBLIC MdtSingleLimitID MEAPI MdtLimitGetLowerLimit(const MdtLimitID limit);
MEPUBLIC MdtSingleLimitID MEAPI MdtLimitGetUpperLimit(const MdtLimitID limit);
/* Copy a single limit in. A lower stop above the upper stop moves the upper
 * stop up to it, and vice versa. */
MEPUBLIC void MEAPI MdtLimitSetLowerLimit(const MdtLimitID limit, const MdtSingleLimitID sl);
MEPUBLIC void MEAPI MdtLimitSetUpperLimit(const MdtLimitID limit, const MdtSingleLimitID sl);

MEPUBLIC MeReal MEAPI MdtLimitGetPosition(const MdtLimitID limit);
MEPUBLIC MeReal MEAPI MdtLimitGetVelocity(const MdtLimitID limit);
/* Offsets the measured coordinate so that it reads `position` now. */
MEPUBLIC void MEAPI MdtLimitSetPosition(const MdtLimitID limit, const MeReal position);

MEPUBLIC MeReal MEAPI MdtLimitGetStiffnessThreshold(const MdtLimitID limit);
MEPUBLIC void MEAPI MdtLimitSetStiffnessThreshold(const MdtLimitID limit, const MeReal t);

/* forceLimit >= 0; zero switches the motor off, positive switches it on. */
MEPUBLIC void MEAPI MdtLimitSetLimitedForceMotor(const MdtLimitID limit, const MeReal desiredVelocity,
                                                 const MeReal forceLimit);
MEPUBLIC MeReal MEAPI MdtLimitGetMotorDesiredVelocity(const MdtLimitID limit);
MEPUBLIC MeReal MEAPI MdtLimitGetMotorMaxForce(const MdtLimitID limit);

/* Actuators and indicators. Activating limits or the motor also turns
 * position calculation on, which cannot be turned off while either is on. */
MEPUBLIC void MEAPI MdtLimitActivateLimits(const MdtLimitID limit, const MeBool on);
MEPUBLIC void MEAPI MdtLimitActivateMotor(const MdtLimitID limit, const MeBool on);
MEPUBLIC void MEAPI MdtLimitCalculatePosition(const MdtLimitID limit, const MeBool on);
MEPUBLIC MeBool MEAPI MdtLimitIsActive(const MdtLimitID limit);
MEPUBLIC MeBool MEAPI MdtLimitIsMotorized(const MdtLimitID limit);
MEPUBLIC MeBool MEAPI MdtLimitPositionIsCalculated(const MdtLimitID limit);

/* A position controller on the limited-force motor (QuadBike steers its
 * handlebars with it): with e = desiredPosition - position, it sets the
 * motor's desired velocity to maxSpeed * e / gap, clamped to +-maxSpeed
 * (full speed further than `gap` away, slowing down linearly inside it),
 * and its force limit to maxForce. gap > 0. Call it every step. */
MEPUBLIC void MEAPI MdtLimitController(const MdtLimitID limit, const MeReal desiredPosition, const MeReal gap,
                                       const MeReal maxSpeed, const MeReal maxForce);

ME_EXTERN_C_END

#endif /* KARMA_MDTLIMIT_H */
