/* MdtLinear2.h: the Linear2 joint. A point fixed in body 0 is kept on a line
 * fixed in body 1 (a bead on a rail): two linear degrees of freedom removed;
 * sliding along the line and every rotation stay free.
 *
 * The line passes through body 1's attachment point (SetPosition sets both
 * bodies' points at once) along body 1's primary axis, the direction.
 *
 * Reset: both points at body 0's origin, direction the world x axis (as
 * placed when the bodies are set; the guide's table gives (0,0,0), which is
 * no direction). */
#ifndef KARMA_MDTLINEAR2_H
#define KARMA_MDTLINEAR2_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(Linear2, MdtLinear2ID)
MDT_CONSTRAINT_COMMON_API(Linear2, MdtLinear2ID)
MDT_CONSTRAINT_POSITION_API(Linear2, MdtLinear2ID)

/* The line's direction in world coordinates (normalised; zero or non-finite
 * rejected). */
MEPUBLIC void MEAPI MdtLinear2SetDirection(const MdtLinear2ID j, const MeReal x, const MeReal y, const MeReal z);
/* The line's direction (fixed in body 1), world coordinates. */
MEPUBLIC void MEAPI MdtLinear2GetDirection(const MdtLinear2ID j, MeVector3 direction);
ME_EXTERN_C_END

#endif
