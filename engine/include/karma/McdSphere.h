/* McdSphere.h: the sphere geometry, centred on its frame's origin.
 * Mass properties: V = 4/3 pi r^3, I = 2/5 m r^2 about every axis. */
#ifndef KARMA_MCDSPHERE_H
#define KARMA_MCDSPHERE_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdSphereID;

/* A sphere of the given radius (> 0 and finite), or NULL with a warning
 * (bad radius, NULL framework, type not registered). */
MEPUBLIC McdSphereID MEAPI McdSphereCreate(McdFrameworkID framework, MeReal radius);
MEPUBLIC MeReal MEAPI McdSphereGetRadius(McdSphereID sphere);
/* Ignored with a warning for a bad radius or a geometry of another type. */
MEPUBLIC void MEAPI McdSphereSetRadius(McdSphereID sphere, MeReal radius);

ME_EXTERN_C_END
#endif /* KARMA_MCDSPHERE_H */
