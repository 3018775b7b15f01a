/* viewer.c: the QuadBike tutorial's application framework, there from
 * step 0: the window (MeViewer), the graphics of the terrain, the bike and
 * the rider, a camera that follows the bike, the keys, a two-line caption,
 * and the main loop, whose tick runs one simulation step (main.c's tick).
 *
 *   quadbike_stepNN [-flat | -terrain] [-noride] [viewer options]
 *
 * -flat / -terrain   the flat plane / the height field (default: the
 *                    height field, USE_TRI_LIST)
 * -noride            no scripted ride: you drive (keys below)
 * With -frames N (a headless run) and no -keys/-keyfile/-noride, the
 * scripted ride of main.c drives the bike (QuadBikeRideInputs).
 *
 * Keys (MeViewer calls back on a key press only, with no repeat and no
 * release, so the controls latch): Up accelerates (or releases the brake),
 * Down brakes (or releases the throttle), Left / Right steer one notch
 * (of 0.5) further that way, Space centres the steering. */
#include "MeViewer.h"
#include "heightfield_graphic.h"
#include "quadbike.h"
#include "tutorial_record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* "step05": the golden directory of this step (set by CMake) */
#ifndef QUADBIKE_STEP_NAME
#  define QUADBIKE_STEP_NAME "step19"
#endif

static RRender *rc;
static RGraphic *caption[2];
static HeightField drawnField; /* the terrain's shape before step 5 loads it */
static TutorialRecord *record;
static MeMatrix4 startTM, hBarStemTM;
static MeMatrix4 groundTileTM[5][5]; /* the flat ground's tiles */

/* What each step adds, for the caption. */
static const char *const stepText[20] = {
    "the application framework: no world yet",
    "PASTE_01: the universe (world, space, bridge)",
    "PASTE_02: materials for ground, wheels, chassis",
    "PASTE_03: collision update in the tick",
    "PASTE_04: the dynamics step in the tick",
    "PASTE_05: the terrain's collision model",
    "PASTE_06: the chassis falls onto the terrain",
    "PASTE_07: four loose wheels",
    "PASTE_08: wheels on suspension joints",
    "PASTE_09: handlebars on a hinge",
    "PASTE_10: throttle (back wheels)",
    "PASTE_11: brakes on all four wheels",
    "PASTE_12: the front wheels steer",
    "PASTE_13: the handlebars steer",
    "PASTE_14: a callback for wheel contacts",
    "PASTE_15: friction along the rolling wheel",
    "PASTE_16: the rider's limbs (no joints yet)",
    "PASTE_17: the rider's joints",
    "PASTE_18: hinge limits hold the posture",
    "PASTE_19: the rider crouches and leans",
};

/* ---- keys ------------------------------------------------------------ */

static void MEAPI Accelerate(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  if (quadBike.brakeInput > 0)
    quadBike.brakeInput = 0;
  else
    quadBike.throttleInput = 1;
}

static void MEAPI Brake(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  if (quadBike.throttleInput > 0)
    quadBike.throttleInput = 0;
  else
    quadBike.brakeInput = 1;
}

static void MEAPI SteerLeft(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  quadBike.steeringInput = min(1, quadBike.steeringInput + (MeReal)0.5);
}

static void MEAPI SteerRight(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  quadBike.steeringInput = max(-1, quadBike.steeringInput - (MeReal)0.5);
}

static void MEAPI CentreSteering(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  quadBike.steeringInput = 0;
}

/* ---- graphics ---------------------------------------------------------- */

static void CreateTerrainGraphics(void) {
  const float white[4] = {1, 1, 1, 1}, sand[4] = {0.85f, 0.78f, 0.55f, 1};
  RGraphic *g;
  if (landscape.useTriList) {
    const HeightField *hf = &landscape.heightField;
    if (!hf->heights) { /* before step 5: load it just to draw it */
      if (!HeightFieldFromBMP(&drawnField, "terrain2", 15)) return;
      hf = &drawnField;
    }
    g = HeightFieldCreateGraphic(rc, hf, sand, 16, NULL);
    if (g) RGraphicSetTexture(rc, g, "checkerboard");
  } else {
    /* A ground plane carries one copy of the texture, so the flat ground
     * is 5 x 5 tiles of 48 m, each with its own copy (6 m squares). */
    int i, k;
    for (i = 0; i < 5; ++i)
      for (k = 0; k < 5; ++k) {
        MeMatrix4TMMakeIdentity(groundTileTM[i][k]);
        MeMatrix4TMSetPosition(groundTileTM[i][k], (MeReal)(48 * (i - 2)), 0, (MeReal)(48 * (k - 2)));
        g = RGraphicGroundPlaneCreate(rc, 48, 8, white, 0);
        if (!g) continue;
        RGraphicSetTransformPtr(g, groundTileTM[i][k]);
        RGraphicSetTexture(rc, g, "checkerboard");
      }
  }
}

static void CreateVehicleGraphics(void) {
  const float red[4] = {0.8f, 0.12f, 0.1f, 1}, black[4] = {0.12f, 0.12f, 0.12f, 1};
  const float grey[4] = {0.6f, 0.6f, 0.62f, 1};
  const VehicleData *d = &quadBikeData;
  RGraphic *g;
  int i;
  if (quadBike.chassisBody)
    RGraphicBoxCreate(rc, d->chassisDims[0], d->chassisDims[1], d->chassisDims[2], red,
                      MdtBodyGetTransformPtr(quadBike.chassisBody));
  for (i = 0; i < 4; ++i) {
    if (!quadBike.wheelBody[i]) continue;
    /* A cylinder about the wheel's z axis, its hinge axis */
    g = RGraphicCylinderCreate(rc, d->wheelRadius, d->wheelWidth, black, MdtBodyGetTransformPtr(quadBike.wheelBody[i]));
    if (g) RGraphicSetTexture(rc, g, "checkerboard");
  }
  if (quadBike.hBarBody) {
    RGraphicCylinderCreate(rc, (MeReal)0.025, d->hBarWidth, grey, MdtBodyGetTransformPtr(quadBike.hBarBody));
    /* the stem down to the chassis, fixed to the handlebars */
    MeMatrix4TMMakeIdentity(hBarStemTM);
    RGraphicBoxCreate(rc, (MeReal)0.05, (MeReal)0.35, (MeReal)0.05, grey, hBarStemTM);
  }
}

static void CreateRiderGraphics(void) {
  const float shirt[4] = {0.15f, 0.35f, 0.8f, 1}, trousers[4] = {0.2f, 0.2f, 0.25f, 1};
  const float skin[4] = {0.95f, 0.75f, 0.6f, 1}, helmet[4] = {0.95f, 0.85f, 0.1f, 1};
  int i;
  for (i = 0; i < NUM_LIMBS; ++i) {
    const float *colour = i == HEAD                              ? helmet
                          : i == LOWER_LEGS || i == UPPER_LEGS   ? trousers
                          : i == R_LOWER_ARM || i == L_LOWER_ARM ? skin
                                                                 : shirt;
    if (!rider.limbBody[i]) continue;
    RGraphicBoxCreate(rc, riderData.limbDim[i][0], riderData.limbDim[i][1], riderData.limbDim[i][2], colour,
                      MdtBodyGetTransformPtr(rider.limbBody[i]));
  }
}

/* The handlebar stem hangs 0.175 m below the bar's centre, turning with it. */
static void UpdateStem(void) {
  const MeReal *tm;
  int i;
  if (!quadBike.hBarBody) return;
  tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.hBarBody);
  for (i = 0; i < 16; ++i) hBarStemTM[i / 4][i % 4] = tm[i];
  for (i = 0; i < 3; ++i) hBarStemTM[3][i] -= (MeReal)0.175 * tm[4 + i];
}

static void UpdateCaption(void) {
  const float white[4] = {1, 1, 1, 1};
  char line[160];
  MeReal speed = 0;
  int i;
  if (quadBike.chassisBody) {
    MeVector3 v;
    MdtBodyGetLinearVelocity(quadBike.chassisBody, v);
    speed = MeVector3Magnitude(v);
  }
  for (i = 0; i < 2; ++i)
    if (caption[i]) RGraphicDelete(rc, caption[i], 1);
  snprintf(line, sizeof line, "QuadBike step %02d  %s", QUADBIKE_STEP, stepText[QUADBIKE_STEP]);
  caption[0] = RGraphicTextCreate(rc, line, 8, 8, white);
  snprintf(line, sizeof line, "t %4.1f s  speed %4.1f m/s  throttle %.1f  brake %.1f  steer %+.1f",
           (double)QuadBikeTime(), (double)speed, (double)quadBike.throttleInput, (double)quadBike.brakeInput,
           (double)quadBike.steeringInput);
  caption[1] = RGraphicTextCreate(rc, line, 8, 26, white);
}

/* The camera looks at the chassis from behind and to its right, 7 m away,
 * and swings round after the bike as it turns (closing a tenth of the
 * angle each frame). */
static void UpdateCamera(void) {
  const MeReal behindRight = (MeReal)-2.32; /* from the bike's heading */
  static MeReal theta = 0;
  static int started = 0;
  MeReal target, d;
  MeVector3 at;
  if (quadBike.chassisBody) {
    const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
    MdtBodyGetPosition(quadBike.chassisBody, at);
    target = MeAtan2(tm[0], tm[2]) + behindRight; /* tm[0..2]: the bike's x axis */
  } else {
    MeVector3Copy(at, startTM[3]);
    target = (MeReal)(ME_PI / 2) + behindRight;
  }
  if (!started) theta = target, started = 1;
  d = target - theta;
  while (d > (MeReal)ME_PI) d -= (MeReal)(2 * ME_PI);
  while (d < (MeReal)-ME_PI) d += (MeReal)(2 * ME_PI);
  theta += (MeReal)0.1 * d;
  at[1] += (MeReal)0.4;
  RCameraSetLookAt(rc, at);
  RCameraSetView(rc, 7, theta, (MeReal)0.35);
}

/* ---- the loop ------------------------------------------------------------ */

static void MEAPI Tick(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  tick();
  if (record) TutorialRecordStep(record);
  UpdateStem();
  UpdateCamera();
  UpdateCaption();
}

static void MEAPI_CDECL Cleanup(void) {
  RRenderContextDestroy(rc);
  QuadBikeDestroy();
  HeightFieldDestroy(&drawnField);
}

int main(int argc, const char *argv[]) {
  QuadBikeOptions options;
  MeCommandLineOptions *opts;
  MdtBodyID bodies[14];
  MeVector3 startPos;
  int i, n, headless = 0, scripted = 0, noride;

  for (i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "-help"))
      printf(
          "QuadBike step %d (tutorials/quadbike/README.md). Options of the program:\n"
          "  -flat          the flat plane%s\n"
          "  -terrain       the height field from terrain2.bmp%s\n"
          "  -noride        no scripted ride: drive with the keys\n"
          "  -trajectory F  write the golden trajectory to F\n"
          "With -frames N and no -keys/-keyfile/-noride the scripted ride drives.\n"
          "Keys: Up throttle, Down brake, Left/Right steer a notch, Space centre.\n\n",
          QUADBIKE_STEP, USE_TRI_LIST ? "" : " (the default)", USE_TRI_LIST ? " (the default)" : "");
    if (!strcmp(argv[i], "-frames")) headless = 1;
    if (!strcmp(argv[i], "-keys") || !strcmp(argv[i], "-keyfile")) scripted = 1;
  }
  opts = MeCommandLineOptionsCreate(argc, argv);
  options.useTriList = USE_TRI_LIST;
  if (MeCommandLineOptionsCheckFor(opts, "-flat", 1)) options.useTriList = 0;
  if (MeCommandLineOptionsCheckFor(opts, "-terrain", 1)) options.useTriList = 1;
  noride = MeCommandLineOptionsCheckFor(opts, "-noride", 1);
  options.ride = headless && !scripted && !noride;

  rc = RRenderContextCreate(opts, 0, 1);
  MeCommandLineOptionsDestroy(opts);
  if (!rc) return 1;
  strcpy(rc->m_AppName, "QuadBike");
  /* Registered before the record's own exit handler, so that it runs after
   * it: the record writes the last frame from the bodies. */
  atexit(Cleanup);
  record = TutorialRecordCreate(argc, (char **)argv, "quadbike", QUADBIKE_STEP_NAME, timeStep, 10);

  printf("QuadBike step %d: %s\n  terrain: %s; %s\n", QUADBIKE_STEP, stepText[QUADBIKE_STEP],
         options.useTriList ? "height field (terrain2.bmp)" : "flat plane",
         options.ride ? "the scripted ride drives (throttle 1-4.5 s, steer left 2.5-4.5 s, brake from 4.5 s)"
                      : "keys: Up throttle, Down brake, Left/Right steer, Space centre");
  if (!QuadBikeCreate(&options)) {
    fprintf(stderr, "quadbike: could not create the Karma universe\n");
    return 1;
  }
  landscape.useTriList = options.useTriList;
  QuadBikeStartPosition(startPos);
  MeMatrix4TMMakeIdentity(startTM);
  MeMatrix4TMSetPosition(startTM, startPos[0], startPos[1], startPos[2]);

  CreateTerrainGraphics();
  if (drawnField.heights) /* before step 5: the camera looks at the drawn terrain */
    startTM[3][1] = HeightFieldHeightAt(&drawnField, startPos[0], startPos[2]) + (MeReal)0.6;
  CreateVehicleGraphics();
  CreateRiderGraphics();
  UpdateStem();

  UpdateCamera();
  UpdateCaption();

  RRenderSetUpCallBack(rc, Accelerate);
  RRenderSetDownCallBack(rc, Brake);
  RRenderSetLeftCallBack(rc, SteerLeft);
  RRenderSetRightCallBack(rc, SteerRight);
  RRenderSetActionNCallBack(rc, 0, CentreSteering, 0);

  if (record) {
    n = QuadBikeBodies(bodies);
    for (i = 0; i < n; ++i) TutorialRecordAddBody(record, bodies[i]);
    TutorialRecordStart(record);
  }
  RRun(rc, Tick, 0);
  return 0;
}
