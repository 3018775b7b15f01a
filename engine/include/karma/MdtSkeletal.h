/* MdtSkeletal.h: the skeletal joint, a ball and socket whose relative
 * rotation is limited in swing (an elliptical cone) and twist, for limbs.
 *
 * Frames: body 0's attachment axes a0 (the cone axis), o0, n0 = a0 x o0 and
 * body 1's a1 (the limb axis), o1, as set with MdtSkeletalSetAxes.
 * Swing: a1 leaves a0 by the angle theta towards the direction psi measured
 * from o0 towards n0 (a1 = cos(theta) a0 + sin(theta) (cos(psi) o0 +
 * sin(psi) n0)). The cone lets theta reach
 *     limit(psi) = 1 / sqrt(cos^2(psi) / P^2 + sin^2(psi) / S^2),
 * P the PRIMARY half-angle (swing towards o0), S the SECONDARY (towards n0):
 * an elliptical cone of half-angles P and S, circular when they are equal.
 * Twist: the turn of body 1 about a1 beyond the great-circle (swing-only)
 * rotation from the reference alignment, in [-pi, pi]; limited to
 * [-T, T], T the twist limit angle.
 * Each limit is hard (stiffness MEINFINITY) or, with a finite stiffness, a
 * damped spring acting past it (torque stiffness * excess + damping * rate).
 * A half-angle or twist limit of pi is no limit.
 *
 * Defaults (Reset): position at body 0's origin, axes the world x (primary)
 * and y as the bodies are when they are set; P = S = T = pi/4 (the guide's
 * reference pages; its introduction says pi, which we do not follow);
 * stiffness MEINFINITY (hard), damping 0.
 * (The guide declares the getters and some setters with an MdtConeLimitID;
 * they take the skeletal joint here.) */
#ifndef KARMA_MDTSKELETAL_H
#define KARMA_MDTSKELETAL_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Skeletal, MdtSkeletalID)
MDT_CONSTRAINT_COMMON_API(Skeletal, MdtSkeletalID)
MDT_CONSTRAINT_POSITION_API(Skeletal, MdtSkeletalID)

/* The cone axis (primary) and the secondary axis, world coordinates, for both
 * bodies: the present relative orientation becomes the reference. They must
 * be non-zero and orthogonal. GetAxes reports body 0's. */
MEPUBLIC void MEAPI MdtSkeletalSetAxes(const MdtSkeletalID j, const MeReal px, const MeReal py, const MeReal pz,
                                       const MeReal ox, const MeReal oy, const MeReal oz);
MEPUBLIC void MEAPI MdtSkeletalGetAxes(const MdtSkeletalID j, MeVector3 primary, MeVector3 secondary);

/* Angles in (0, pi] (the twist limit in [0, pi]). */
MEPUBLIC void MEAPI MdtSkeletalSetConePrimaryLimitAngle(const MdtSkeletalID j, const MeReal theta);
MEPUBLIC void MEAPI MdtSkeletalSetConeSecondaryLimitAngle(const MdtSkeletalID j, const MeReal theta);
MEPUBLIC void MEAPI MdtSkeletalSetTwistLimitAngle(const MdtSkeletalID j, const MeReal theta);
MEPUBLIC MeReal MEAPI MdtSkeletalGetConePrimaryLimitAngle(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetConeSecondaryLimitAngle(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetTwistLimitAngle(const MdtSkeletalID j);
/* Stiffness >= 0 (MEINFINITY: hard); damping >= 0 and finite. */
MEPUBLIC void MEAPI MdtSkeletalSetConeStiffness(const MdtSkeletalID j, const MeReal kp);
MEPUBLIC void MEAPI MdtSkeletalSetConeDamping(const MdtSkeletalID j, const MeReal kd);
MEPUBLIC void MEAPI MdtSkeletalSetTwistStiffness(const MdtSkeletalID j, const MeReal kp);
MEPUBLIC void MEAPI MdtSkeletalSetTwistDamping(const MdtSkeletalID j, const MeReal kd);
MEPUBLIC MeReal MEAPI MdtSkeletalGetConeStiffness(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetConeDamping(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetTwistStiffness(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetTwistDamping(const MdtSkeletalID j);
/* The present swing angle theta and twist (rad). */
MEPUBLIC MeReal MEAPI MdtSkeletalGetSwingAngle(const MdtSkeletalID j);
MEPUBLIC MeReal MEAPI MdtSkeletalGetTwistAngle(const MdtSkeletalID j);
ME_EXTERN_C_END

#endif
