/* rainbowchain.c: the guide's RainbowChain (Appendix B) with real Karma
 * bodies. The viewer calls are the ones Appendix B walks through; the
 * simulation is in chain.c.
 *
 * Controls: $ACTION2 (Return) resets the chain; dragging with the left
 * mouse button pulls the last ball along the drag, in the plane of the
 * screen, with a force that grows with the drag's length; F1 shows the
 * help; Escape quits.
 *
 * Options (besides MeViewer's): -steadyclock times the performance bar with
 * a clock that steps 1 ms per reading, so that its frames are the same on
 * every run (the golden test uses it); -trajectory FILE (the golden record). */
#include "MeViewer.h"
#include "chain.h"
#include "tutorial_record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NBALLS RC_NBALLS

/* Render context */
RRender *rc;
/* graphics */
RGraphic *sphereG[NBALLS];
RGraphic *planeG;

static RainbowChain *chain;
static TutorialRecord *record;

/* The mouse drag: where the left button went down, and whether it is held. */
static int dragging, dragX, dragY;
/* Newtons per pixel of drag, for a 640-pixel-wide view, and the most the
 * mouse may pull (about three times a ball's weight). */
static const MeReal kMouseForcePerPixel = (MeReal)0.1, kMouseForceMax = 25;

static double MEAPI SteadyClock(void *user) {
  static double now;
  (void)user;
  return now += 1;
}

static void MEAPI Reset(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  RainbowChainReset(chain);
  dragging = 0;
}

/* The drag (dx right, dy down in pixels) becomes a force in the plane of
 * the screen: along the camera's right and up directions. */
static void MEAPI MouseForce(RRender *r, int x, int y, int buttons, void *userdata) {
  MeReal right[3], up[3], dx, dy, scale;
  MeReal st = MeSin(r->m_CameraTheta), ct = MeCos(r->m_CameraTheta);
  MeReal sp = MeSin(r->m_CameraPhi), cp = MeCos(r->m_CameraPhi);
  (void)userdata;
  if (!(buttons & 1)) {
    dragging = 0;
    RainbowChainSetEndForce(chain, 0, 0, 0);
    return;
  }
  if (!dragging) {
    dragging = 1, dragX = x, dragY = y;
    return;
  }
  right[0] = ct, right[1] = 0, right[2] = -st;
  up[0] = -sp * st, up[1] = cp, up[2] = -sp * ct;
  scale = kMouseForcePerPixel * (MeReal)640 / (MeReal)(r->m_nWidth > 0 ? r->m_nWidth : 640);
  dx = scale * (MeReal)(x - dragX);
  dy = -scale * (MeReal)(y - dragY);
  if (dx * dx + dy * dy > kMouseForceMax * kMouseForceMax) {
    MeReal shrink = kMouseForceMax / MeSqrt(dx * dx + dy * dy);
    dx *= shrink, dy *= shrink;
  }
  RainbowChainSetEndForce(chain, dx * right[0] + dy * up[0], dx * right[1] + dy * up[1], dx * right[2] + dy * up[2]);
}

static void MEAPI tick(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  /* One frame, one step, timed in the two sections the performance bar
     * reads. */
  MeProfileStartSection("collision");
  RainbowChainCollide(chain);
  MeProfileEndSection("collision");
  MeProfileStartSection("dynamics");
  RainbowChainDynamics(chain);
  MeProfileEndSection("dynamics");
  TutorialRecordStep(record);
}

/* Registered before the record is created: atexit handlers run in reverse
 * order, so the record's own handler (which reads the bodies to write the
 * last frame) runs first and the universe is destroyed after it. */
static void MEAPI_CDECL cleanup(void) {
  RRenderContextDestroy(rc);
  RainbowChainDestroy(chain);
}

int main(int argc, const char *argv[]) {
  float color[4];
  int i;
  /* Create your help array. */
  char *help[3] = {"$ACTION1 - toggle options menu", "$ACTION2 - reset", "$MOUSE - apply mouse force"};

  /* Initialise rendering attributes. */
  MeCommandLineOptions *options;
  options = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(options, 0, 1);
  if (MeCommandLineOptionsCheckFor(options, "-steadyclock", 1)) MeProfileSetClock(SteadyClock, 0);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;
  strcpy(rc->m_AppName, "RainbowChain");

  chain = RainbowChainCreate();
  if (!chain) return 1;
  atexit(cleanup);
  record = TutorialRecordCreate(argc, (char **)argv, "rainbowchain", "main", kChainStep, 10);
  if (!record) return 1;
  for (i = 0; i < NBALLS; i++) TutorialRecordAddBody(record, McdModelGetBody(chain->ball[i]));

  /* The camera, in polar coordinates about the origin. */
  RCameraRotateElevation(rc, (MeReal)1.1);
  RCameraRotateAngle(rc, (MeReal)0.2);
  RCameraZoom(rc, 10);

  /* The bar shows the time of collision, dynamics and rendering. */
  RPerformanceBarCreate(rc);

  /* The help. The guide also shows it at once (which pauses the
     * simulation until F1); here F1 shows it, so a run without a key
     * script moves from the first frame. */
  RRenderCreateUserHelp(rc, help, 3);

  RRenderSetActionNCallBack(rc, 2, Reset, 0);
  RRenderSetMouseCallBack(rc, MouseForce, 0);

  for (i = 0; i < NBALLS; i++) {
    /* Convert Hue Saturation Value to Red Green Blue. */
    MeHSVtoRGB(((MeReal)i / (MeReal)NBALLS) * 360, 1, 1, color);
    color[3] = 1;
    sphereG[i] = RGraphicSphereCreate(rc, kChainBallRadius, color, McdModelGetTransformPtr(chain->ball[i]));
  }
  color[0] = color[1] = color[2] = color[3] = 1;
  planeG = RGraphicGroundPlaneCreate(rc, 24, 2, color, 0);
  RGraphicSetTexture(rc, planeG, "checkerboard");

  TutorialRecordStart(record);
  RRun(rc, tick, 0);
  return 0; /* not reached */
}
