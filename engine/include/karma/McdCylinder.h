/* McdCylinder.h: the cylinder geometry, axis along z, centred on its frame's
 * origin: radius r, full height h (z from -h/2 to h/2).
 * Mass properties: V = pi r^2 h, Izz = m r^2 / 2, Ixx = Iyy = m (3 r^2 + h^2) / 12. */
#ifndef KARMA_MCDCYLINDER_H
#define KARMA_MCDCYLINDER_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdCylinderID;

/* A cylinder (radius, height > 0 and finite), or NULL with a warning. */
MEPUBLIC McdCylinderID MEAPI McdCylinderCreate(McdFrameworkID framework, MeReal radius, MeReal height);
MEPUBLIC MeReal MEAPI McdCylinderGetRadius(McdCylinderID cylinder);
MEPUBLIC MeReal MEAPI McdCylinderGetHeight(McdCylinderID cylinder);
/* Ignored with a warning for a bad value or a geometry of another type. */
MEPUBLIC void MEAPI McdCylinderSetRadius(McdCylinderID cylinder, MeReal radius);
MEPUBLIC void MEAPI McdCylinderSetHeight(McdCylinderID cylinder, MeReal height);

ME_EXTERN_C_END
#endif /* KARMA_MCDCYLINDER_H */
