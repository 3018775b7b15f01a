/* CarTerrain: a car on a height-field terrain (the viewer side; the
 * simulation is carterrain.c).
 *
 *   carterrain [viewer options]   e.g. -frames 601 -every 200 -out DIR -size 320x240
 *
 * Controls (keys do not repeat: each press is one notch):
 *   Up / Down      throttle up / down by a quarter (below zero: reverse)
 *   Left / Right   steer left / right by a quarter of full lock
 *   Space          brake on / off
 * Until a control is pressed the car follows the scripted drive
 * (CarTerrainScript), so a headless run shows it driving. */
#include "MeViewer.h"
#include "carterrain.h"
#include "heightfield_graphic.h"
#include "tutorial_record.h"

#include <stdio.h>
#include <stdlib.h>

static CarTerrain car;
static RRender *rc;
static TutorialRecord *record;
static int scripted = 1;
static MeMatrix4 cabinRelTM, cabinTM;

static void MEAPI_CDECL cleanup(void) {
  CarTerrainDestroy(&car);
  RRenderContextDestroy(rc);
}

static void TakeOver(void) {
  if (scripted) printf("t = %.2f s: manual control\n", (double)car.steps * (double)CAR_STEP);
  scripted = 0;
}
static void MEAPI ThrottleUp(RRender *r, void *d) { (void)r, (void)d, TakeOver(), car.throttle += (MeReal)0.25; }
static void MEAPI ThrottleDown(RRender *r, void *d) { (void)r, (void)d, TakeOver(), car.throttle -= (MeReal)0.25; }
static void MEAPI SteerLeft(RRender *r, void *d) { (void)r, (void)d, TakeOver(), car.steering += (MeReal)0.25; }
static void MEAPI SteerRight(RRender *r, void *d) { (void)r, (void)d, TakeOver(), car.steering -= (MeReal)0.25; }
static void MEAPI Brake(RRender *r, void *d) { (void)r, (void)d, TakeOver(), car.brake = !car.brake; }

/* The camera behind the car and a little to its left, looking at it. */
static void Follow(void) {
  MeMatrix4Ptr tm = MdtBodyGetTransformPtr(car.chassisBody);
  AcmeVector3 at;
  at[0] = tm[3][0], at[1] = tm[3][1], at[2] = tm[3][2];
  RCameraSetLookAt(rc, at);
  /* theta is measured about y from +z; behind the car is -forward. */
  RCameraSetView(rc, 16, MeAtan2(-tm[0][0], -tm[0][2]) + (MeReal)0.6, (MeReal)0.45);
}

static void MEAPI tick(RRender *r, void *userdata) {
  (void)r, (void)userdata;
  if (scripted) CarTerrainScript(&car);
  CarTerrainStep(&car);
  TutorialRecordStep(record);
  MeMatrix4TMCompose(cabinTM, cabinRelTM, MdtBodyGetTransformPtr(car.chassisBody));
  Follow();
  if (car.steps % 120 == 0) {
    MeVector3 p;
    MdtBodyGetPosition(car.chassisBody, p);
    printf("t = %4.1f s: chassis at (%6.2f, %5.2f, %6.2f), speed %5.2f m/s, driven %6.1f m\n",
           (double)car.steps * (double)CAR_STEP, (double)p[0], (double)p[1], (double)p[2],
           (double)CarTerrainForwardSpeed(&car), (double)car.distance);
  }
}

int main(int argc, const char *argv[]) {
  const float grass[4] = {0.55f, 0.8f, 0.45f, 1}, paint[4] = {0.85f, 0.15f, 0.1f, 1};
  const float glass[4] = {0.55f, 0.7f, 0.85f, 1}, tyre[4] = {0.15f, 0.15f, 0.15f, 1};
  const float white[4] = {1, 1, 1, 1};
  RGraphic *ground;
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(argc, argv);
  int i;
  rc = RRenderContextCreate(options, 0, 1);
  MeCommandLineOptionsDestroy(options);
  if (!rc) return 1;
  /* Registered before the record's own handler, so it runs after it. */
  atexit(cleanup);
  if (!CarTerrainCreate(&car, "terrain2")) return 1;

  ground = HeightFieldCreateGraphic(rc, &car.terrain, grass, 8, NULL);
  RGraphicSetTexture(rc, ground, "checkerboard");
  RGraphicBoxCreate(rc, CAR_CHASSIS_LENGTH, CAR_CHASSIS_HEIGHT, CAR_CHASSIS_WIDTH, paint,
                    MdtBodyGetTransformPtr(car.chassisBody));
  MeMatrix4TMMakeIdentity(cabinRelTM);
  MeMatrix4TMSetPosition(cabinRelTM, (MeReal)-0.3, CAR_CHASSIS_HEIGHT, 0);
  MeMatrix4TMCompose(cabinTM, cabinRelTM, MdtBodyGetTransformPtr(car.chassisBody));
  RGraphicBoxCreate(rc, (MeReal)1.6, (MeReal)0.5, (MeReal)1.4, glass, cabinTM);
  /* A wheel is a sphere to collision (the guide's advice) and a tyre to
   * the eye: a cylinder about the wheel's z, its hinge axis. */
  for (i = 0; i < CAR_WHEELS; ++i)
    RGraphicCylinderCreate(rc, CAR_WHEEL_RADIUS, (MeReal)0.3, tyre, MdtBodyGetTransformPtr(car.wheelBody[i]));
  RGraphicTextCreate(rc, "CarTerrain: $UP/$DOWN throttle, $LEFT/$RIGHT steer, $ACTION0 brake", 10, 10, white);

  RRenderSetUpCallBack(rc, ThrottleUp);
  RRenderSetDownCallBack(rc, ThrottleDown);
  RRenderSetLeftCallBack(rc, SteerLeft);
  RRenderSetRightCallBack(rc, SteerRight);
  RRenderSetActionNCallBack(rc, 0, Brake, NULL);
  Follow();

  record = TutorialRecordCreate(argc, (char **)argv, "carterrain", "main", CAR_STEP, 10);
  if (!record) return 1;
  TutorialRecordAddBody(record, car.chassisBody);
  for (i = 0; i < CAR_WHEELS; ++i) TutorialRecordAddBody(record, car.wheelBody[i]);
  TutorialRecordStart(record);
  RRun(rc, tick, 0);
  return 0;
}
