/* window_drive: a small program driven by keys and the mouse, for the
 * window test (window_test.sh). A box stands on a ground plane and turns
 * by 0.02 rad a frame about the vertical; each press of an arrow key moves
 * it 0.5 along x (Left, Right) or z (Up, Down); Space (action 0) changes
 * its colour; moving the mouse with the left button held turns the camera
 * (theta = x / 100 rad). Everything it draws depends only on the frame
 * number and the input events, so a key script replays a live session. */
#include "MeViewer.h"

#include <math.h>
#include <string.h>

static RRender *rc;
static RGraphic *box;
static MeMatrix4 boxTM;
static float boxX, boxZ;
static int colourIndex;

static const float colours[3][4] = {{0.9f, 0.3f, 0.2f, 1}, {0.2f, 0.8f, 0.3f, 1}, {0.3f, 0.4f, 0.9f, 1}};

static void MEAPI Up(RRender *r, void *d) { (void)r, (void)d, boxZ -= 0.5f; }
static void MEAPI Down(RRender *r, void *d) { (void)r, (void)d, boxZ += 0.5f; }
static void MEAPI Left(RRender *r, void *d) { (void)r, (void)d, boxX -= 0.5f; }
static void MEAPI Right(RRender *r, void *d) { (void)r, (void)d, boxX += 0.5f; }

static void MEAPI Recolour(RRender *r, void *d) {
  (void)r, (void)d;
  colourIndex = (colourIndex + 1) % 3;
  RGraphicSetColor(box, colours[colourIndex]);
}

static void MEAPI Mouse(RRender *r, int x, int y, int buttons, void *d) {
  (void)y, (void)d;
  if (buttons & 1) RCameraSetView(r, 12, (AcmeReal)x / 100, 0.5f);
}

/* The box turns with the frame number: angle = 0.02 rad * frame. */
static void MEAPI Tick(RRender *r, void *d) {
  const float a = 0.02f * (float)r->m_nFrame;
  (void)d;
  boxTM[0][0] = cosf(a), boxTM[0][2] = -sinf(a);
  boxTM[2][0] = sinf(a), boxTM[2][2] = cosf(a);
  boxTM[3][0] = boxX, boxTM[3][1] = 0.75f, boxTM[3][2] = boxZ;
}

int main(int argc, const char **argv) {
  const float grey[4] = {0.7f, 0.7f, 0.7f, 1};
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(options, 0, 1);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;
  boxTM[0][0] = boxTM[1][1] = boxTM[2][2] = boxTM[3][3] = 1;
  box = RGraphicBoxCreate(rc, 1.5f, 1.5f, 1.5f, colours[0], boxTM);
  RGraphicGroundPlaneCreate(rc, 20, 10, grey, 0);
  RCameraSetView(rc, 12, 0, 0.5f);
  RRenderSetUpCallBack(rc, Up);
  RRenderSetDownCallBack(rc, Down);
  RRenderSetLeftCallBack(rc, Left);
  RRenderSetRightCallBack(rc, Right);
  RRenderSetActionNCallBack(rc, 0, Recolour, 0);
  RRenderSetMouseCallBack(rc, Mouse, 0);
  strcpy(rc->m_AppName, "window_drive"); /* the window title */
  RRun(rc, Tick, 0);
  return 0;
}
