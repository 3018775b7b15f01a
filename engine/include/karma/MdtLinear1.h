/* MdtLinear1.h: the Linear1 joint. A point fixed in body 0 is kept on a
 * plane fixed in body 1: one linear degree of freedom (along the plane's
 * normal) removed; sliding in the plane and every rotation stay free.
 *
 * The plane passes through body 1's attachment point (SetPosition sets both
 * bodies' points at once: body 0's point and a point of the plane). Its
 * normal is body 1's primary axis, set with MdtLinear1SetAxis -- the guide
 * names no function for it; this one follows MdtHingeSetAxis.
 *
 * Reset: both points at body 0's origin, normal the world x axis (as placed
 * when the bodies are set). */
#ifndef KARMA_MDTLINEAR1_H
#define KARMA_MDTLINEAR1_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Linear1, MdtLinear1ID)
MDT_CONSTRAINT_COMMON_API(Linear1, MdtLinear1ID)
MDT_CONSTRAINT_POSITION_API(Linear1, MdtLinear1ID)

/* The plane normal in world coordinates (normalised; zero or non-finite
 * rejected). */
MEPUBLIC void MEAPI MdtLinear1SetAxis(const MdtLinear1ID j, const MeReal x, const MeReal y, const MeReal z);
/* The plane normal (fixed in body 1), world coordinates. */
MEPUBLIC void MEAPI MdtLinear1GetAxis(const MdtLinear1ID j, MeVector3 axis);
ME_EXTERN_C_END

#endif
