/* rainbowchain_viewer: the viewer side of the guide's RainbowChain, written
 * as Appendix B shows it: HSV-coloured spheres, a checkerboard ground
 * plane, the camera moves, the performance bar, the help (shown at the
 * start, which pauses the simulation until F1), an action callback on
 * Return that resets, cleanup through atexit. MeViewer knows nothing of
 * dynamics, so instead of Karma bodies a swinging chain is computed here:
 * link k hangs at angle theta_k(t) = 0.5 sin(1.7 t + 0.35 k) from the one
 * above it, the top link from (0, 7, 0), each link `kLink` long.
 *
 * For its golden test it also writes the balls' positions as a trajectory
 * (-trajectory FILE), finished by the same atexit cleanup, and with
 * -steadyclock times the performance bar with a clock that steps 1 ms per
 * reading, so the bar's frames are the same on every run. */
#include "MeViewer.h"

#include <karma/golden/KarmaTrajectory.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NBALLS 10

/* Render context */
RRender *rc;
/* graphics */
RGraphic *sphereG[NBALLS];
RGraphic *planeG;

static MeMatrix4 ballTM[NBALLS];
static const MeReal ballRadius = (MeReal)0.5, kLink = (MeReal)1.1;
static MeReal simTime;
static KarmaTrajectoryWriter *trajectory;

static void PlaceChain(void) {
  MeReal x = 0, y = 7, angle;
  int i;
  for (i = 0; i < NBALLS; ++i) {
    angle = (MeReal)0.5 * MeSin((MeReal)1.7 * simTime + (MeReal)0.35 * (MeReal)i);
    x += kLink * MeSin(angle);
    y -= kLink * MeCos(angle);
    MeMatrix4TMMakeIdentity(ballTM[i]);
    MeMatrix4TMSetPosition(ballTM[i], x, y, 0);
  }
}

static void RecordFrame(RRender *r) {
  static const MeReal q[4] = {1, 0, 0, 0}, zero[3] = {0, 0, 0};
  int i;
  KarmaTrajectoryWriterBeginFrame(trajectory, r->m_nFrame, simTime);
  for (i = 0; i < NBALLS; ++i) KarmaTrajectoryWriterAddBody(trajectory, ballTM[i][3], q, zero, zero);
  KarmaTrajectoryWriterEndFrame(trajectory);
}

static double MEAPI SteadyClock(void *user) {
  (void)user;
  static double now;
  return now += 1;
}

static void MEAPI Reset(RRender *r, void *userdata) {
  (void)userdata;
  simTime = 0;
  PlaceChain();
  fprintf(stderr, "rainbowchain: reset at frame %d\n", r->m_nFrame);
}

static void MEAPI tick(RRender *r, void *userdata) {
  (void)userdata;
  simTime += (MeReal)1 / 60;
  PlaceChain();
  if (r->m_nFrame % 20 == 0) RecordFrame(r);
}

static void MEAPI_CDECL cleanup(void) {
  char hash[KARMA_GOLDEN_HASH_TEXT_SIZE];
  KarmaGoldenFormatHash(KarmaTrajectoryWriterHash(trajectory), hash);
  printf("state hash: %s\n", hash);
  KarmaTrajectoryWriterDestroy(trajectory);
  RRenderContextDestroy(rc);
}

int main(int argc, const char *argv[]) {
  float color[4];
  int i;
  KarmaTrajectoryInfo info = {"rainbowchain_viewer", "main", "reference", "every 20th frame", (MeReal)1 / 60, NBALLS};
  /* Create your help array. */
  char *help[3] = {"$ACTION1 - toggle options menu", "$ACTION2 - reset", "$MOUSE - apply mouse force"};

  /* Initialise rendering attributes. */
  MeCommandLineOptions *options;
  options = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(options, 0, 1);
  trajectory = KarmaTrajectoryWriterCreate(MeCommandLineOptionsGetString(options, "-trajectory", 1), &info);
  if (MeCommandLineOptionsCheckFor(options, "-steadyclock", 1)) MeProfileSetClock(SteadyClock, 0);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;
  strcpy(rc->m_AppName, "RainbowChain");

  RCameraRotateElevation(rc, (MeReal)1.1);
  RCameraRotateAngle(rc, (MeReal)0.2);
  RCameraZoom(rc, 10);
  RPerformanceBarCreate(rc);
  RRenderCreateUserHelp(rc, help, 3);
  RRenderToggleUserHelp(rc);
  RRenderSetActionNCallBack(rc, 2, Reset, 0);

  PlaceChain();
  for (i = 0; i < NBALLS; i++) {
    /* Convert Hue Saturation Value to Red Green Blue. */
    MeHSVtoRGB(((MeReal)i / (MeReal)NBALLS) * 360, 1, 1, color);
    color[3] = 1;
    sphereG[i] = RGraphicSphereCreate(rc, ballRadius, color, ballTM[i]);
  }
  color[0] = color[1] = color[2] = color[3] = 1;
  planeG = RGraphicGroundPlaneCreate(rc, 24, 2, color, 0);
  RGraphicSetTexture(rc, planeG, "checkerboard");

  RecordFrame(rc);
  atexit(cleanup);
  RRun(rc, tick, 0);
  return 0; /* not reached */
}
