/* MdtPrismatic.h: the prismatic (slider) joint. The bodies keep their
 * relative orientation and may only move relative to each other along one
 * axis fixed in body 0: five degrees of freedom removed, one linear freedom
 * left. The slide -- how far body 0's attachment point has moved from body
 * 1's along the axis -- can be limited and motorised through
 * MdtPrismaticGetLimit (stops in length units, the motor in length/s with a
 * force limit).
 *
 * There is no Set/GetPosition: the joint point is body 0's origin, and
 * setting the axis takes the bodies' present placement as slide zero (the
 * two attachment points are made to coincide there).
 *
 * Reset: axis the world x axis as given when the bodies are set (the guide's
 * appendix D; its appendix A table says y, which this library does not
 * follow), slide zero at the bodies' placement at SetBodies, limit reset (no
 * stops, no motor). */
#ifndef KARMA_MDTPRISMATIC_H
#define KARMA_MDTPRISMATIC_H
#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Prismatic, MdtPrismaticID)
MDT_CONSTRAINT_COMMON_API(Prismatic, MdtPrismaticID)

/* The slide axis in world coordinates (normalised; zero or non-finite is
 * rejected). Also makes the present configuration slide position zero. */
MEPUBLIC void MEAPI MdtPrismaticSetAxis(const MdtPrismaticID j, const MeReal x, const MeReal y, const MeReal z);
/* The slide axis (body 0's, world coordinates). */
MEPUBLIC void MEAPI MdtPrismaticGetAxis(const MdtPrismaticID j, MeVector3 axis);
/* The joint's limit and motor; the pointer stays valid for the joint's life.
 * MdtLimitGetPosition reads the slide (offset included) after a step. */
MEPUBLIC MdtLimitID MEAPI MdtPrismaticGetLimit(const MdtPrismaticID j);
/* Copies a limit's parameters into the joint's limit. */
MEPUBLIC void MEAPI MdtPrismaticSetLimit(const MdtPrismaticID j, const MdtLimitID limit);
ME_EXTERN_C_END

#endif
