/* McdBox.h: the box geometry, centred on its frame's origin, edges along
 * the frame's axes. Its size is given as full edge lengths (dx, dy, dz).
 * Mass properties: V = dx dy dz, Ixx = m (dy^2 + dz^2) / 12 (and cyclic). */
#ifndef KARMA_MCDBOX_H
#define KARMA_MCDBOX_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdBoxID;

/* A dx x dy x dz box (each > 0 and finite), or NULL with a warning. */
MEPUBLIC McdBoxID MEAPI McdBoxCreate(McdFrameworkID framework, MeReal dx, MeReal dy, MeReal dz);
/* Full edge lengths. Any output pointer may be NULL. */
MEPUBLIC void MEAPI McdBoxGetDimensions(McdBoxID box, MeReal *dx, MeReal *dy, MeReal *dz);
/* Half edge lengths. */
MEPUBLIC void MEAPI McdBoxGetRadii(McdBoxID box, MeVector3 radii);
/* Ignored with a warning for bad sizes or a geometry of another type. */
MEPUBLIC void MEAPI McdBoxSetDimensions(McdBoxID box, MeReal dx, MeReal dy, MeReal dz);

ME_EXTERN_C_END
#endif /* KARMA_MCDBOX_H */
