/* MdtAngular3.h: the Angular3 joint. The relative orientation of the two
 * bodies is held at what it was when the bodies (or the axis) were set;
 * their positions stay free: three rotational degrees of freedom removed.
 * With rotation enabled, turning about the joint axis is allowed too, which
 * makes it an "Angular2" (two degrees removed).
 *
 * Stiffness and damping make the joint a rotational spring instead of rigid
 * rows: about each held axis a torque T settles at an angle T / stiffness.
 * MEINFINITY stiffness (the default) is rigid. A finite stiffness with
 * MEINFINITY damping (the default damping) is an undamped spring -- set the
 * damping too for a damped one. Stiffness and damping both zero switch the
 * joint off.
 *
 * There is no Set/GetPosition: the joint has no point.
 *
 * Reset: rotation not enabled, axis the world x axis (as placed when the
 * bodies are set), stiffness and damping MEINFINITY. */
#ifndef KARMA_MDTANGULAR3_H
#define KARMA_MDTANGULAR3_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Angular3, MdtAngular3ID)
MDT_CONSTRAINT_COMMON_API(Angular3, MdtAngular3ID)

/* TRUE frees rotation about the axis (Angular2); FALSE locks it again, at
 * the turn about the axis the bodies have then (no snapping back). */
MEPUBLIC void MEAPI MdtAngular3EnableRotation(const MdtAngular3ID j, const MeBool on);
MEPUBLIC MeBool MEAPI MdtAngular3RotationIsEnabled(const MdtAngular3ID j);
/* The axis of the free rotation, world coordinates (normalised; zero or
 * non-finite rejected). It matters only while rotation is enabled; the
 * present relative orientation is what the joint holds. */
MEPUBLIC void MEAPI MdtAngular3SetAxis(const MdtAngular3ID j, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtAngular3GetAxis(const MdtAngular3ID j, MeVector3 axis);
/* Spring stiffness (torque per radian) and damping (torque per rad/s) of the
 * held axes; >= 0, MEINFINITY allowed; negative rejected. */
MEPUBLIC void MEAPI MdtAngular3SetStiffness(const MdtAngular3ID j, const MeReal k);
MEPUBLIC MeReal MEAPI MdtAngular3GetStiffness(const MdtAngular3ID j);
MEPUBLIC void MEAPI MdtAngular3SetDamping(const MdtAngular3ID j, const MeReal d);
MEPUBLIC MeReal MEAPI MdtAngular3GetDamping(const MdtAngular3ID j);
ME_EXTERN_C_END

#endif
