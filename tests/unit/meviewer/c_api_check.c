/* c_api_check.c: MeViewer.h from plain C11, compiled with the project's
 * warnings. The guide passes colours both as float arrays (RainbowChain)
 * and as MeReal arrays (the basic-steps program); both must compile
 * cleanly in either precision (MeViewerColor.h). */
#include "MeViewer.h"

int ViewerCApiCheck(RRender *rc);

int ViewerCApiCheck(RRender *rc) {
  MeReal red[] = {1, 0, 0, 0};   /* basic steps */
  float color[4] = {1, 1, 1, 1}; /* RainbowChain */
  const AcmeReal lineColour[4] = {1, 1, 0, 1};
  const AcmeReal a[3] = {0, 0, 0}, b[3] = {1, 1, 1};
  AcmeReal o[3] = {0, 0, 0}, e[3] = {0, 1, 0};
  int made = 0;
  made += RGraphicSphereCreate(rc, (MeReal)1.2, red, 0) != 0;
  made += RGraphicSphereCreate(rc, 1, color, 0) != 0;
  made += RGraphicGroundPlaneCreate(rc, 24, 2, color, 0) != 0;
  made += RGraphicGroundPlaneCreate(rc, 24, 2, red, 0) != 0;
  made += RGraphicBoxCreate(rc, 1, 1, 1, red, 0) != 0;
  made += RGraphicLineCreate(rc, o, e, red, 0) != 0;
  made += RNLineCreate(rc, a, b, lineColour, 0) != 0;
  made += RNLineCreate(rc, a, b, color, 0) != 0;
  RGraphicSetColor(rc->m_pRG_First, red);
  RGraphicSetColor(rc->m_pRG_First, color);
  return made;
}

/* The guide's tick forms, run through RRun's two- and three-argument
 * forms (each ends the process; see run_test.cpp). */
#include <stdio.h>

static int ticks;
static void MEAPI TickNoData(RRender *rc) {
  (void)rc;
  fprintf(stderr, "C tick without user data %d\n", ++ticks);
}
static void MEAPI TickWithData(RRender *rc, void *userdata) {
  (void)rc;
  fprintf(stderr, "C tick with user data %d\n", ++*(int *)userdata);
}

void ViewerCRunTwoArguments(RRender *rc);
void ViewerCRunNoDataThreeArguments(RRender *rc);
void ViewerCRunWithData(RRender *rc);
void ViewerCRunTwoArguments(RRender *rc) { RRun(rc, TickNoData); }
void ViewerCRunNoDataThreeArguments(RRender *rc) { RRun(rc, TickNoData, 0); }
void ViewerCRunWithData(RRender *rc) {
  static int n;
  RRun(rc, TickWithData, &n);
}
