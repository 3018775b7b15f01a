/* heightfield_graphic.h: drawing a HeightField with MeViewer (separate from
 * heightfield.h so the simulation side of a tutorial needs no viewer). */
#ifndef KARMA_TUTORIAL_HEIGHTFIELD_GRAPHIC_H
#define KARMA_TUTORIAL_HEIGHTFIELD_GRAPHIC_H

#include "MeViewer.h"
#include "heightfield.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One RGraphic holding every triangle of the field (the same triangles as
 * collision, with smooth per-vertex normals and texture coordinates of one
 * repeat per `texelMetres`), in colour `color` (RGBA in [0, 1]), added to
 * rc's 3D render list. tm may be NULL (identity). */
RGraphic *HeightFieldCreateGraphic(RRender *rc, const HeightField *hf, const float color[4], MeReal texelMetres,
                                   MeMatrix4Ptr tm);

#ifdef __cplusplus
}
#endif

#endif
