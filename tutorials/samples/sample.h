/* sample.h: the boilerplate every chapter sample shares, so that each
 * sample file holds only the guide's scene.
 *
 * A sample is a main() that builds its world, then hands over:
 *
 *   RRender *rc = SampleOpen(argc, argv, "caption");    viewer + cleanup
 *   MstUniverseID u = SampleUniverse(); (or SampleWorld(bodies, constraints))
 *   ... bodies, joints, graphics (SampleGround, SampleConvexMeshGraphic) ...
 *   SampleCamera(rc, lookAt, distance, theta, phi);
 *   SampleRecordBody(body); ...                         recorded bodies, in order
 *   SampleRun(argc, argv, "door_hinge", h, beforeStep, afterStep);
 *
 * SampleRun records the run for the golden test (tutorial_record.h: program
 * "samples", step = the sample's name, every 10th step and the last) and
 * calls RRun, whose tick is { beforeStep; step the universe or the world;
 * record; afterStep }. RRun ends the program through exit(): the record's
 * atexit handler runs first (it was registered last), then the cleanup
 * SampleOpen registered, which destroys the universe or world and the
 * render context. */
#ifndef KARMA_TUTORIAL_SAMPLE_H
#define KARMA_TUTORIAL_SAMPLE_H

#include "MeViewer.h"
#include "Mst.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*SampleHook)(void);

/* The render context from the command line (the viewer's options are
 * eaten), a caption in the top-left corner, the cleanup registered with
 * atexit. Exits with status 1 if the viewer cannot start. */
RRender *SampleOpen(int argc, const char *argv[], const char *caption);

/* A universe of the default sizes, with `instances` geometry instances for
 * aggregates (0 for none); stepped by SampleRun and destroyed at exit. */
MstUniverseID SampleUniverse(int instances);
/* A dynamics world without collision, stepped and destroyed likewise. */
MdtWorldID SampleWorld(int bodies, int constraints);

/* A checkerboard ground of side `side` metres at height y (drawing only). */
RGraphic *SampleGround(RRender *rc, MeReal side, MeReal y);
/* The faces of a convex mesh as one graphic following tm. */
RGraphic *SampleConvexMeshGraphic(RRender *rc, McdConvexMeshID mesh, const float color[4], MeMatrix4Ptr tm);

/* Camera looking at (x, y, z) from `distance`, turned theta about y from
 * +z and raised phi above the horizon (radians). */
void SampleCamera(RRender *rc, MeReal x, MeReal y, MeReal z, MeReal distance, MeReal theta, MeReal phi);

/* The inertia tensor of a solid box of mass m and full side lengths
 * size[0..2] about its centre: diag(m/12 (y^2 + z^2), m/12 (x^2 + z^2),
 * m/12 (x^2 + y^2)). */
void SampleBoxInertia(MeReal m, const MeReal size[3], MeMatrix3 I);

/* Adds a body to the recorded set (before SampleRun). */
void SampleRecordBody(MdtBodyID body);

/* Records and runs (see the top of this file); never returns. */
void SampleRun(int argc, const char *argv[], const char *name, MeReal h, SampleHook beforeStep, SampleHook afterStep);

#ifdef __cplusplus
}
#endif

#endif
