/* gl_draw.h: drawing a context's lists with fixed-function OpenGL into the
 * current GL context (the OSMesa backend makes it current first). */
#ifndef KARMA_MEVIEWER_GL_DRAW_H
#define KARMA_MEVIEWER_GL_DRAW_H

#include "viewer_internal.h"

namespace karma::viewer {

/* Clears to the background, draws the 3D list with the camera and lights,
 * the native lines, then the 2D list over everything. Uploads textures
 * loaded since the last frame. */
void DrawSceneGL(RRender *rc);

}  // namespace karma::viewer

#endif
