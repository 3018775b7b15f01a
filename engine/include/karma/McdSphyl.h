/* McdSphyl.h: the sphyl (capsule) geometry: a cylinder of radius r and
 * height h along z, centred on the origin, capped by two hemispheres of
 * radius r (total length h + 2r). It is the set of points within r of the
 * segment from (0,0,-h/2) to (0,0,h/2).
 * Mass properties, with mc = rho pi r^2 h (cylinder), ms = rho 4/3 pi r^3
 * (both caps):
 *   Izz = mc r^2 / 2 + ms 2 r^2 / 5
 *   Ixx = Iyy = mc (h^2/12 + r^2/4) + ms (2 r^2/5 + h^2/4 + 3 h r/8) */
#ifndef KARMA_MCDSPHYL_H
#define KARMA_MCDSPHYL_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdSphylID;

/* A sphyl (radius > 0, height >= 0, both finite; height 0 is a sphere), or
 * NULL with a warning. */
MEPUBLIC McdSphylID MEAPI McdSphylCreate(McdFrameworkID framework, MeReal radius, MeReal height);
MEPUBLIC MeReal MEAPI McdSphylGetRadius(McdSphylID sphyl);
MEPUBLIC MeReal MEAPI McdSphylGetHeight(McdSphylID sphyl);
/* Ignored with a warning for a bad value or a geometry of another type. */
MEPUBLIC void MEAPI McdSphylSetRadius(McdSphylID sphyl, MeReal radius);
MEPUBLIC void MEAPI McdSphylSetHeight(McdSphylID sphyl, MeReal height);

ME_EXTERN_C_END
#endif /* KARMA_MCDSPHYL_H */
