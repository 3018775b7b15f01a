/* render.h: the demo's software renderer, a 2D side view of the balls.
 *
 * World x (right) and y (up) map to pixels by one scale factor chosen so a
 * 10.4 m wide window fits the image; the ground line sits an eighth of the
 * height above the bottom edge. Every world coordinate is turned into an
 * integer pixel once (round half up, in MeReal); all drawing after that is
 * integer arithmetic, so frames are as deterministic as the simulation.
 *
 * The picture: a sky gradient, the ground, a dotted trail per ball, each ball
 * as a disc with a darker rim and a spoke showing its body x axis (so the spin
 * is visible), and a progress bar along the top edge. */
#ifndef KARMA_DEMO_RENDER_H
#define KARMA_DEMO_RENDER_H

#include "balls.h"

typedef struct DemoRenderer DemoRenderer;

/* NULL when out of memory. `frameCount` bounds the trail length. */
DemoRenderer *DemoRendererCreate(int width, int height, int frameCount);
void DemoRendererDestroy(DemoRenderer *r);
/* Call once per frame, in order: extends the trails. */
void DemoRendererRecord(DemoRenderer *r, const DemoWorld *world, int frame);
/* Draws frame `frame` of `frameCount` into the image and writes it as an RGB
 * PNG. Returns 1 on success. */
int DemoRendererWritePng(DemoRenderer *r, const DemoWorld *world, int frame, int frameCount, const char *path);

#endif
