/* McdPlane.h: the plane geometry: the plane z = 0 of its frame, normal +z.
 * It is solid below (z < 0), so a penetration depth is measured from the
 * surface down. It has no finite volume (no mass properties) and its AABB is
 * unbounded except, when the normal lies along a world axis, on the solid
 * side's far face. To have a y-up ground, rotate its TM by pi/2 about x. */
#ifndef KARMA_MCDPLANE_H
#define KARMA_MCDPLANE_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdPlaneID;

/* A plane, or NULL with a warning (NULL framework, type not registered). */
MEPUBLIC McdPlaneID MEAPI McdPlaneCreate(McdFrameworkID framework);

ME_EXTERN_C_END
#endif /* KARMA_MCDPLANE_H */
