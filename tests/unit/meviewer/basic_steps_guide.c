/* basic_steps_guide.c: the guide's "Basic Steps Involved in Creating a
 * Karma Dynamics Program" (a sphere moving under gravity), kept as the
 * guide prints it apart from layout and the (void) casts that keep -Wextra
 * quiet about the tick's unused parameters, to prove that its MeViewer calls
 * compile and run in both precisions (its colour is an MeReal array, its
 * tick exits after 600 steps, its cleanup runs through atexit). */
/* Will need the dynamics and the viewer library for this example */
#include "Mdt.h"
#include "MeViewer.h"

#include <stdlib.h>

/* The following 3 functions are used. */
/* The standard Karma calling convention, MEAPI, is __stdcall */
int MEAPI_CDECL main(int, const char **);
void MEAPI_CDECL cleanup(void);
void MEAPI tick(RRender *, void *);
/* Karma dynamics variable world_ is a pointer to an MdtWorld struct */
MdtWorldID world_;
/* sphereD_ is a pointer to an MdtBody struct */
MdtBodyID sphereD_;
/* Karma renderer structures */
RRender *rc;
RGraphic *sphereG_;
/* The following struct contains command line parameters passed to the program */
MeCommandLineOptions *opts;

void MEAPI_CDECL cleanup(void) {
  /* Deallocate memory assigned to the body */
  MdtBodyDestroy(sphereD_);
  /* Destroying the world deallocates memory assigned to all bodies and
       constraints contained in it. The body destroy above is not critical */
  MdtWorldDestroy(world_);
  /* Clean the graphics memory */
  RRenderContextDestroy(rc);
}

void MEAPI tick(RRender *rc, void *userdata) {
  static int count = 0;
  (void)rc, (void)userdata;
  /* exit the simulation after 600 time-steps */
  if (++count == 600) exit(0);
  /* Evolve the dynamics world by 0.01 seconds */
  MdtWorldStep(world_, 0.01f);
}

int MEAPI_CDECL main(int argc, const char *argv[]) {
  /* Define the color red for the body. */
  /* The parameters passed to red correspond to
       Red Green Blue and Alpha (how opaque the object is) */
  MeReal red[] = {1, 0, 0, 0};
  opts = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(opts, 0, 1);
  /* Create a dynamics world with unit sizes. */
  /* The corresponding structure allocates
       enough memory for one body and no constraints */
  world_ = MdtWorldCreate(1, 0, 1, 1);
  /* Set the world property gravity to act with
       equal strength along the -x and -y directions */
  MdtWorldSetGravity(world_, (MeReal)-0.3, (MeReal)-0.3, 0);
  /* Make a body and add it to the dynamics world world_. */
  sphereD_ = MdtBodyCreate(world_);
  /* Turn the body sphereD_ on so that it is included
       when the world world_ is evolved. */
  MdtBodyEnable(sphereD_);
  /* Render a sphere. Assign it the color red, give it a radius
       of 1.2 and update the graphical spheres position and
       orientation with that contained in the sphereD_ struct */
  sphereG_ = RGraphicSphereCreate(rc, (MeReal)1.2, red, MdtBodyGetTransformPtr(sphereD_));
  /* Register the function to clean up the memory when the program exits */
  atexit(cleanup);
  /* Begin the update loop by calling the renderer, that
       in turn repeatedly calls the callback tick. */
  RRun(rc, tick, 0);
  return 0;
}
