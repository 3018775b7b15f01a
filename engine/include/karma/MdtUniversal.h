/* MdtUniversal.h: the universal (Cardan, gimbal) joint. A point fixed in
 * each body is kept at the same place, and an axis fixed in body 0 is kept
 * perpendicular to an axis fixed in body 1: four degrees of freedom removed,
 * the bodies may turn about those two axes only (no twist about the third,
 * perpendicular to both). Like a real Cardan joint it becomes a poor torque
 * transmitter as the bend nears 90 degrees; a MdtConeLimit in parallel keeps
 * it away from there.
 *
 * Each body has an attachment frame (primary and secondary axis). The
 * joint's axis in body 0 is body 0's PRIMARY axis; its axis in body 1 is body
 * 1's SECONDARY axis. So with one world frame (p, o) given to both bodies, p
 * is body 0's axis and o body 1's.
 *
 * Reset: the joint point at body 0's origin; body 0's axis the world x axis
 * and body 1's the world y axis, as placed when the bodies are set. */
#ifndef KARMA_MDTUNIVERSAL_H
#define KARMA_MDTUNIVERSAL_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Universal, MdtUniversalID)
MDT_CONSTRAINT_COMMON_API(Universal, MdtUniversalID)
MDT_CONSTRAINT_POSITION_API(Universal, MdtUniversalID)

/* The joint axis fixed in body `bodyindex` (0 or 1), in world coordinates
 * (normalised; zero or non-finite is rejected). The other axis of that
 * body's frame is adjusted to stay orthogonal. This is the call of the
 * guide's cone-limited universal example. */
MEPUBLIC void MEAPI MdtUniversalSetAxis(const MdtUniversalID j, const unsigned int bodyindex, const MeReal x,
                                        const MeReal y, const MeReal z);
/* The joint axis fixed in body `bodyindex`, world coordinates. */
MEPUBLIC void MEAPI MdtUniversalGetAxis(const MdtUniversalID j, const unsigned int bodyindex, MeVector3 axis);
/* Body `bodyindex`'s whole attachment frame, world coordinates: primary and
 * secondary axes, which must be orthogonal. Body 0's joint axis is its
 * primary, body 1's its secondary. */
MEPUBLIC void MEAPI MdtUniversalSetAxes(const MdtUniversalID j, const unsigned int bodyindex, const MeReal px,
                                        const MeReal py, const MeReal pz, const MeReal ox, const MeReal oy,
                                        const MeReal oz);
MEPUBLIC void MEAPI MdtUniversalGetAxes(const MdtUniversalID j, const unsigned int bodyindex, MeVector3 primary,
                                        MeVector3 ortho);
ME_EXTERN_C_END

#endif
