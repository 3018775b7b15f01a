/* MdtHinge.h: the hinge (revolute) joint. The bodies may only turn about a
 * common axis through a common point: five degrees of freedom removed. The
 * hinge angle, measured about the axis from body 1's secondary axis to body
 * 0's, can be limited and motorised through MdtHingeGetLimit; it is tracked
 * through full turns, so stops beyond +-pi work.
 * Reset: position at body 0's origin, axis the world x axis (as given when
 * the bodies are set), limit reset (no stops, no motor). */
#ifndef KARMA_MDTHINGE_H
#define KARMA_MDTHINGE_H
#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Hinge, MdtHingeID)
MDT_CONSTRAINT_COMMON_API(Hinge, MdtHingeID)
MDT_CONSTRAINT_POSITION_API(Hinge, MdtHingeID)

/* The axis in world coordinates (normalised; zero is rejected). */
MEPUBLIC void MEAPI MdtHingeSetAxis(const MdtHingeID j, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtHingeGetAxis(const MdtHingeID j, MeVector3 axis);
/* The hinge's limit and motor; the pointer stays valid for the joint's life. */
MEPUBLIC MdtLimitID MEAPI MdtHingeGetLimit(const MdtHingeID j);
/* Copies a limit's parameters into the hinge's limit. */
MEPUBLIC void MEAPI MdtHingeSetLimit(const MdtHingeID j, const MdtLimitID limit);
/* Current hinge angle (limit offset included) and its rate (rad, rad/s). */
MEPUBLIC MeReal MEAPI MdtHingeGetAngle(const MdtHingeID j);
MEPUBLIC MeReal MEAPI MdtHingeGetAngleRate(const MdtHingeID j);
ME_EXTERN_C_END

#endif
