/* MdtFixedPath.h: the fixed-path joint, a ball and socket whose attachment
 * point moves. A point of each body is held at the same place (three linear
 * degrees of freedom removed, rotations free), and each point may move
 * within its body with a given velocity. Driving body 1's point (often the
 * world's) along an animated path drags body 0 along with the right forces:
 * the velocity enters the constraint, so the motion is not left to error
 * correction.
 *
 * Animation: each step set the path point (SetPosition with body 1) and its
 * velocity (SetVelocity). With only a velocity set the point advances by
 * itself by velocity * step after every step in which the joint is
 * simulated.
 *
 * Reset: both points at body 0's origin, both velocities zero. */
#ifndef KARMA_MDTFIXEDPATH_H
#define KARMA_MDTFIXEDPATH_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(FixedPath, MdtFixedPathID)
MDT_CONSTRAINT_COMMON_API(FixedPath, MdtFixedPathID)

/* Body `bodyindex`'s attachment point, in world coordinates. */
MEPUBLIC void MEAPI MdtFixedPathSetPosition(const MdtFixedPathID j, const unsigned int bodyindex, const MeReal x,
                                            const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtFixedPathGetPosition(const MdtFixedPathID j, const unsigned int bodyindex, MeVector3 position);
/* Velocity of body `bodyindex`'s attachment point relative to that body, in
 * that body's frame (the world frame for the world). */
MEPUBLIC void MEAPI MdtFixedPathSetVelocity(const MdtFixedPathID j, const unsigned int bodyindex, const MeReal x,
                                            const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtFixedPathGetVelocity(const MdtFixedPathID j, const unsigned int bodyindex, MeVector3 velocity);
ME_EXTERN_C_END

#endif
