/* ballman.c: the guide's Ballman, drawn by MeViewer: a rag doll falls down
 * a staircase; a key propels it into a stack of boxes; the options menu
 * switches between the cheap and the high-quality friction model, and the
 * performance bar shows what each costs (its "dynamics" segment is the
 * time of MdtWorldStep, Kea's solve included). The simulation is in
 * ballman_sim.c.
 *
 * Controls: $ACTION1 (Tab) opens the options menu (Up/Down choose, Return
 * toggles 'High Quality Friction model', Tab closes it); $ACTION2 (Return)
 * resets; $ACTION3 (x) propels the rag doll towards the boxes for half a
 * second; F1 shows the help; Escape quits.
 *
 * Options (besides MeViewer's): -steadyclock times the performance bar with
 * a clock that steps 1 ms per reading, so that its frames are the same on
 * every run (the golden tests use it); -trajectory FILE (the golden record). */
#include "MeViewer.h"
#include "ballman_sim.h"
#include "tutorial_record.h"

#include <stdlib.h>
#include <string.h>

/* Render context */
RRender *rc;

static Ballman *ballman;
static TutorialRecord *record;
static RGraphic *modelText;

/* Capsules are drawn as a cylinder on the body's transform and a sphere at
 * each end, whose transforms follow the body (CapEnds). */
static MeMatrix4 capTM[BALLMAN_PARTS][2];

static double MEAPI SteadyClock(void *user) {
  static double now;
  (void)user;
  return now += 1;
}

static void CapEnds(void) {
  int i, k, e;
  for (i = 0; i < BALLMAN_PARTS; ++i) {
    const BallmanPartShape *s = &ballman->partShape[i];
    MeMatrix4Ptr tm;
    if (s->shape != BallmanCapsule) continue;
    tm = McdModelGetTransformPtr(ballman->part[i]);
    for (e = 0; e < 2; ++e) {
      const MeReal along = (e == 0 ? (MeReal)0.5 : -(MeReal)0.5) * s->b;
      MeMatrix4Copy(capTM[i][e], tm);
      for (k = 0; k < 3; ++k) capTM[i][e][3][k] = tm[3][k] + along * tm[2][k];
    }
  }
}

static void ShowModel(void) {
  static const float white[4] = {1, 1, 1, 1};
  if (modelText) RGraphicDelete(rc, modelText, 1);
  modelText = RGraphicTextCreate(rc,
                                 ballman->highQuality ? "friction: high quality (Coulomb, normal force)"
                                                      : "friction: cheap (viscous slip, adhesive)",
                                 10, 10, white);
}

static void MEAPI ToggleFriction(MeBool on) {
  BallmanSetHighQualityFriction(ballman, on);
  ShowModel();
}

static void MEAPI Reset(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  BallmanReset(ballman);
  CapEnds();
}

static void MEAPI Propel(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  BallmanPropel(ballman);
}

static void MEAPI tick(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  /* One frame, one step, timed in the two sections the performance bar
     * reads. */
  MeProfileStartSection("collision");
  BallmanCollide(ballman);
  MeProfileEndSection("collision");
  MeProfileStartSection("dynamics");
  BallmanDynamics(ballman);
  MeProfileEndSection("dynamics");
  CapEnds();
  TutorialRecordStep(record);
}

/* Registered before the record is created: atexit handlers run in reverse
 * order, so the record's own handler (which reads the bodies to write the
 * last frame) runs first and the universe is destroyed after it. */
static void MEAPI_CDECL cleanup(void) {
  RRenderContextDestroy(rc);
  BallmanDestroy(ballman);
}

int main(int argc, const char *argv[]) {
  static const float skin[4] = {1.0f, 0.75f, 0.55f, 1}, shirt[4] = {0.2f, 0.45f, 0.9f, 1},
                     trousers[4] = {0.25f, 0.25f, 0.35f, 1}, stone[4] = {0.7f, 0.68f, 0.62f, 1},
                     crate[4] = {0.85f, 0.55f, 0.2f, 1}, white[4] = {1, 1, 1, 1};
  char *help[4] = {"$ACTION1 - options menu: High Quality Friction model", "$ACTION2 - reset",
                   "$ACTION3 - propel the rag doll towards the boxes", "F1 - this help"};
  const MeReal lookAt[3] = {(MeReal)3.4, (MeReal)0.5, 0};
  MeCommandLineOptions *options;
  RMenu *menu;
  int i, e;

  options = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(options, 0, 1);
  if (MeCommandLineOptionsCheckFor(options, "-steadyclock", 1)) MeProfileSetClock(SteadyClock, 0);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;
  strcpy(rc->m_AppName, "Ballman");

  ballman = BallmanCreate();
  if (!ballman) return 1;
  atexit(cleanup);
  record = TutorialRecordCreate(argc, (char **)argv, "ballman", "main", kBallmanStep, 10);
  if (!record) return 1;
  for (i = 0; i < BALLMAN_PARTS; ++i) TutorialRecordAddBody(record, McdModelGetBody(ballman->part[i]));
  for (i = 0; i < BALLMAN_BOXES; ++i) TutorialRecordAddBody(record, McdModelGetBody(ballman->box[i]));

  /* The camera: in front of the stairs and to the side, looking at the
     * middle of the flight. */
  RCameraSetLookAt(rc, lookAt);
  RCameraSetView(rc, (MeReal)10.5, (MeReal)0.55, (MeReal)0.42);

  RPerformanceBarCreate(rc);
  RRenderCreateUserHelp(rc, help, 4);

  menu = RMenuCreate(rc, "Ballman options");
  RMenuAddToggleEntry(menu, "High Quality Friction model", ToggleFriction, FALSE);
  RRenderSetDefaultMenu(rc, menu);
  RRenderSetActionNCallBack(rc, 2, Reset, 0);
  RRenderSetActionNCallBack(rc, 3, Propel, 0);

  /* The scene. */
  {
    RGraphic *floor = RGraphicGroundPlaneCreate(rc, 30, 2, white, 0);
    RGraphicSetTexture(rc, floor, "checkerboard");
  }
  for (i = 0; i < BALLMAN_STEPS; ++i)
    RGraphicBoxCreate(rc, ballman->stairSize[i][0], ballman->stairSize[i][1], ballman->stairSize[i][2], stone,
                      ballman->stairTM[i]);
  for (i = 0; i < BALLMAN_BOXES; ++i)
    RGraphicBoxCreate(rc, ballman->boxSide, ballman->boxSide, ballman->boxSide, crate,
                      McdModelGetTransformPtr(ballman->box[i]));

  /* The rag doll. */
  CapEnds();
  for (i = 0; i < BALLMAN_PARTS; ++i) {
    const BallmanPartShape *s = &ballman->partShape[i];
    MeMatrix4Ptr tm = McdModelGetTransformPtr(ballman->part[i]);
    const float *colour = i == BallmanHead                                 ? skin
                          : i == BallmanTorso                              ? shirt
                          : i == BallmanForearmL || i == BallmanForearmR   ? skin
                          : i == BallmanUpperArmL || i == BallmanUpperArmR ? shirt
                                                                           : trousers;
    if (s->shape == BallmanBox)
      RGraphicBoxCreate(rc, s->a, s->b, s->c, colour, tm);
    else if (s->shape == BallmanSphere)
      RGraphicSphereCreate(rc, s->a, colour, tm);
    else {
      RGraphicCylinderCreate(rc, s->a, s->b, colour, tm);
      for (e = 0; e < 2; ++e) RGraphicSphereCreate(rc, s->a, colour, capTM[i][e]);
    }
  }
  ShowModel();

  TutorialRecordStart(record);
  RRun(rc, tick, 0);
  return 0; /* not reached */
}
