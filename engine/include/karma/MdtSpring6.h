/* MdtSpring6.h: the six-degree-of-freedom spring, a configurable compliance
 * between two body frames. (The guide only names it; this is our design.)
 *
 * Each body has an attachment frame: a point and axes (x = primary, y =
 * secondary, z = x cross y), set together for both bodies from world
 * coordinates by MdtSpring6SetPosition / MdtSpring6SetAxes, so the frames
 * coincide in the configuration the bodies are in at that moment: that is
 * the spring's rest configuration. Along and about each axis of body 0's
 * frame there is a spring:
 *   linear axis k:  force  = -K_k (x1 - x0) . e_k - C_k (relative speed)
 *   angular axis k: torque = -K_k phi_k - C_k (relative rate about e_k)
 * where phi is the rotation vector (axis times angle, exact, not a small
 * angle) turning body 0's frame onto body 1's, in body 0's frame axes. So a
 * static load F along (torque T about) a soft axis settles at F / K (T / K).
 *
 * Per axis, with stiffness K >= 0 and damping C >= 0:
 *   K = MEINFINITY            the axis is locked (rigid), the default;
 *   K finite, C = MEINFINITY  a pure spring (damping read as 0);
 *   K = 0, C = 0 or MEINFINITY  the axis is free;
 *   otherwise                 a damped spring.
 * All axes locked makes a weld; all free makes nothing.
 *
 * Defaults (Reset): the frames at body 0's origin with the world's x and y
 * axes as the bodies are when they are set; every stiffness and damping
 * MEINFINITY (six locked axes). */
#ifndef KARMA_MDTSPRING6_H
#define KARMA_MDTSPRING6_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Spring6, MdtSpring6ID)
MDT_CONSTRAINT_COMMON_API(Spring6, MdtSpring6ID)
MDT_CONSTRAINT_POSITION_API(Spring6, MdtSpring6ID)

/* Both frames' axes in world coordinates (non-zero, orthogonal). */
MEPUBLIC void MEAPI MdtSpring6SetAxes(const MdtSpring6ID j, const MeReal px, const MeReal py, const MeReal pz,
                                      const MeReal ox, const MeReal oy, const MeReal oz);
/* Body 0's axes, world coordinates. */
MEPUBLIC void MEAPI MdtSpring6GetAxes(const MdtSpring6ID j, MeVector3 primary, MeVector3 secondary);
/* axis: 0 (primary), 1 (secondary), 2 (their cross product). Stiffness and
 * damping >= 0, MEINFINITY allowed; NaN or negative is rejected. */
MEPUBLIC void MEAPI MdtSpring6SetLinearStiffness(const MdtSpring6ID j, const unsigned int axis, const MeReal k);
MEPUBLIC void MEAPI MdtSpring6SetLinearDamping(const MdtSpring6ID j, const unsigned int axis, const MeReal c);
MEPUBLIC void MEAPI MdtSpring6SetAngularStiffness(const MdtSpring6ID j, const unsigned int axis, const MeReal k);
MEPUBLIC void MEAPI MdtSpring6SetAngularDamping(const MdtSpring6ID j, const unsigned int axis, const MeReal c);
MEPUBLIC MeReal MEAPI MdtSpring6GetLinearStiffness(const MdtSpring6ID j, const unsigned int axis);
MEPUBLIC MeReal MEAPI MdtSpring6GetLinearDamping(const MdtSpring6ID j, const unsigned int axis);
MEPUBLIC MeReal MEAPI MdtSpring6GetAngularStiffness(const MdtSpring6ID j, const unsigned int axis);
MEPUBLIC MeReal MEAPI MdtSpring6GetAngularDamping(const MdtSpring6ID j, const unsigned int axis);
ME_EXTERN_C_END

#endif
