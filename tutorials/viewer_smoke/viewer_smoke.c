/* viewer_smoke: the smallest MeViewer program worth running. A box, a
 * sphere, a cylinder, a cone and a torus stand on a checkerboard ground
 * plane; the box turns a little every frame; a caption sits in the corner.
 *
 *   viewer_smoke -frames 10 -out /tmp/x      writes /tmp/x/frame_00000.png ...
 *   viewer_smoke -help                       lists the viewer's options
 *
 * It is written the way Appendix B of the guide shows: options eaten by
 * RRenderContextCreate, cleanup registered with atexit, then RRun, which
 * never returns. */
#include "MeViewer.h"

#include <stdlib.h>

static RRender *rc;
static MeMatrix4 boxTM, sphereTM, cylinderTM, coneTM, torusTM;
static MeReal angle;

/* A TM turning by `a` about y, at (x, y, z). */
static void Place(MeMatrix4 tm, MeReal a, MeReal x, MeReal y, MeReal z) {
  MeMatrix4TMMakeIdentity(tm);
  tm[0][0] = MeCos(a), tm[0][2] = -MeSin(a);
  tm[2][0] = MeSin(a), tm[2][2] = MeCos(a);
  MeMatrix4TMSetPosition(tm, x, y, z);
}

static void MEAPI_CDECL cleanup(void) { RRenderContextDestroy(rc); }

static void MEAPI tick(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  angle += (MeReal)0.05;
  Place(boxTM, angle, -3, 1, 0);
}

int main(int argc, const char *argv[]) {
  const float red[4] = {0.9f, 0.2f, 0.2f, 1}, green[4] = {0.2f, 0.8f, 0.3f, 1}, blue[4] = {0.2f, 0.4f, 0.9f, 1};
  const float yellow[4] = {0.9f, 0.8f, 0.2f, 1}, white[4] = {1, 1, 1, 1}, purple[4] = {0.7f, 0.3f, 0.8f, 1};
  RGraphic *plane;
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(options, 0, 1);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;

  RCameraRotateElevation(rc, (MeReal)0.5);
  RCameraRotateAngle(rc, (MeReal)0.3);
  RCameraZoom(rc, 4);

  Place(boxTM, 0, -3, 1, 0);
  Place(sphereTM, 0, 0, 1, 0);
  Place(cylinderTM, 0, 3, 1, 0);
  Place(coneTM, 0, -1.5, 1, -3);
  Place(torusTM, 0, 1.5, 1, 3);
  RGraphicBoxCreate(rc, 1.5, 1.5, 1.5, red, boxTM);
  RGraphicSphereCreate(rc, 1, green, sphereTM);
  RGraphicCylinderCreate(rc, 0.7, 2, blue, cylinderTM);
  RGraphicConeCreate(rc, 0.8, 1, 1, yellow, coneTM);
  RGraphicTorusCreate(rc, 0.5, 1.2, purple, torusTM);
  plane = RGraphicGroundPlaneCreate(rc, 16, 4, white, 0);
  RGraphicSetTexture(rc, plane, "checkerboard");
  RGraphicTextCreate(rc, "viewer_smoke: five primitives on a checkerboard", 10, 10, white);

  atexit(cleanup);
  RRun(rc, tick, 0);
  return 0; /* never reached: RRun ends the program */
}
