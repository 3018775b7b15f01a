/* MdtConeLimit.h: the cone limit. It keeps the angle between an axis fixed
 * in body 0 and an axis fixed in body 1 (each body's primary attachment
 * axis) at or below the cone half-angle. Like a contact it does nothing
 * while inside the cone and pushes back with one angular row once the cone
 * is reached; it leaves the twist about the axes free, so it is used
 * alongside a joint -- a ball and socket, a universal (whose 90-degree bend
 * it keeps away from), an Angular3 with rotation enabled. Half-angles below
 * about 5 degrees make the push direction ill-defined and should be avoided.
 *
 * Stiffness MEINFINITY (the default) is a hard, inelastic cone. A finite
 * stiffness makes it a spring acting only outside the cone: a torque T
 * pushing outwards settles T / stiffness beyond it. With finite stiffness,
 * MEINFINITY damping (the default) is read as no damping.
 *
 * Reset: both axes the world x axis (as placed when the bodies are set),
 * half-angle pi (no limit), stiffness and damping MEINFINITY. The position
 * functions exist for uniformity; the point plays no part. */
#ifndef KARMA_MDTCONELIMIT_H
#define KARMA_MDTCONELIMIT_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(ConeLimit, MdtConeLimitID)
MDT_CONSTRAINT_COMMON_API(ConeLimit, MdtConeLimitID)
MDT_CONSTRAINT_POSITION_API(ConeLimit, MdtConeLimitID)

/* Angle between the cone axis and its side, in (0, pi] (else rejected). */
MEPUBLIC void MEAPI MdtConeLimitSetConeHalfAngle(const MdtConeLimitID j, const MeReal theta);
MEPUBLIC MeReal MEAPI MdtConeLimitGetConeHalfAngle(const MdtConeLimitID j);
/* >= 0, MEINFINITY allowed; negative rejected. */
MEPUBLIC void MEAPI MdtConeLimitSetStiffness(const MdtConeLimitID j, const MeReal k);
MEPUBLIC MeReal MEAPI MdtConeLimitGetStiffness(const MdtConeLimitID j);
MEPUBLIC void MEAPI MdtConeLimitSetDamping(const MdtConeLimitID j, const MeReal d);
MEPUBLIC MeReal MEAPI MdtConeLimitGetDamping(const MdtConeLimitID j);
/* The cone axis in world coordinates for both bodies (normalised; zero or
 * non-finite rejected), or for one body only. */
MEPUBLIC void MEAPI MdtConeLimitSetAxis(const MdtConeLimitID j, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtConeLimitBodySetAxis(const MdtConeLimitID j, const unsigned int bodyindex, const MeReal x,
                                            const MeReal y, const MeReal z);
/* Body `bodyindex`'s cone axis, world coordinates. */
MEPUBLIC void MEAPI MdtConeLimitGetAxis(const MdtConeLimitID j, const unsigned int bodyindex, MeVector3 axis);
/* The present angle between the two axes (rad, in [0, pi]). */
MEPUBLIC MeReal MEAPI MdtConeLimitGetAngle(const MdtConeLimitID j);
ME_EXTERN_C_END

#endif
