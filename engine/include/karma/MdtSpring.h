/* MdtSpring.h: the spring, a configurable distance constraint between a
 * point of each body (one degree of freedom removed, no angular
 * constraint). Its length d is the distance between the two attachment
 * points; it is governed by the joint's limit (MdtSpringGetLimit):
 *
 *   lower stop at the natural length L, upper stop at L;
 *   a SOFT stop is a damped spring acting past it, F = -k (d - L) - c dd/dt;
 *   a HARD stop (stiffness MEINFINITY, or above the limit's threshold) is a
 *   rigid end stop; stiffness and damping 0 switch that side off.
 *
 * So, with the limit's single limits:
 *   spring  both soft (the default): F = -k (d - L) - c dd/dt either way;
 *   rod     both hard (MdtSpringSetStiffness(j, MEINFINITY)): d = L;
 *   string  lower off, upper hard: d <= L, slack when shorter;
 *   elastic lower off, upper soft: stretches like a spring, slack when
 *           shorter.
 * When both stops are at the same length and of the same kind the spring is
 * one two-sided row (a linear damped spring, or a rigid rod); otherwise the
 * stops act one-sided as in MdtLimit. The limit's motor drives dd/dt.
 *
 * Defaults (Reset): each attachment point at its own body's origin (the
 * world origin for the world); natural length the distance between them
 * when the bodies (or the positions) are set, until MdtSpringSetNaturalLength
 * is called; both stops soft with stiffness 10 and damping 1 (our choice:
 * the guide gives none); no motor. */
#ifndef KARMA_MDTSPRING_H
#define KARMA_MDTSPRING_H
#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Spring, MdtSpringID)
MDT_CONSTRAINT_COMMON_API(Spring, MdtSpringID)

/* The attachment point on body `bodyindex` (0 or 1), world coordinates. */
MEPUBLIC void MEAPI MdtSpringSetPosition(const MdtSpringID joint, const unsigned int bodyindex, const MeReal x,
                                         const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtSpringGetPosition(const MdtSpringID joint, MeVector3 position, const unsigned int bodyindex);
/* The spring's limit; the pointer stays valid for the joint's life.
 * MdtLimitGetPosition reads the length (plus offset) after a step. */
MEPUBLIC MdtLimitID MEAPI MdtSpringGetLimit(const MdtSpringID joint);
/* Copies a limit's parameters into the spring's limit. */
MEPUBLIC void MEAPI MdtSpringSetLimit(const MdtSpringID joint, const MdtLimitID limit);
/* Both stops at L (>= 0, finite). */
MEPUBLIC void MEAPI MdtSpringSetNaturalLength(const MdtSpringID joint, const MeReal L);
/* Both stops' stiffness (>= 0; MEINFINITY makes a rod). */
MEPUBLIC void MEAPI MdtSpringSetStiffness(const MdtSpringID joint, const MeReal k);
/* Both stops' damping (>= 0, finite). */
MEPUBLIC void MEAPI MdtSpringSetDamping(const MdtSpringID joint, const MeReal c);
/* The upper stop's values; and the present length. */
MEPUBLIC MeReal MEAPI MdtSpringGetNaturalLength(const MdtSpringID joint);
MEPUBLIC MeReal MEAPI MdtSpringGetStiffness(const MdtSpringID joint);
MEPUBLIC MeReal MEAPI MdtSpringGetDamping(const MdtSpringID joint);
MEPUBLIC MeReal MEAPI MdtSpringGetLength(const MdtSpringID joint);
ME_EXTERN_C_END

#endif
