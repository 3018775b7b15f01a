/* stacking_boxes: the guide's stack of 21 boxes. Each 1 x 0.3 x 1 box of
 * 5 kg starts 0.3 m above the one below it; they drop onto each other and
 * the stack stands. Epsilon is lowered to harden the contacts, gamma raised
 * to push overlapping boxes apart sooner, and auto-disable puts the boxes
 * to sleep once they are still (a sleeping box is drawn darker). */
#include "sample.h"

#include <stdio.h>

#define NO_BOXES 21

static MdtBodyID box_[NO_BOXES];
static RGraphic *graphic_[NO_BOXES];
static float colour_[NO_BOXES][4];
static int steps_, awake_ = NO_BOXES;

static void Shade(void) {
  int i, awake = 0;
  for (i = 0; i < NO_BOXES; ++i) {
    float c[4] = {colour_[i][0], colour_[i][1], colour_[i][2], 1};
    if (MdtBodyIsEnabled(box_[i]))
      ++awake;
    else
      c[0] *= 0.45f, c[1] *= 0.45f, c[2] *= 0.45f;
    RGraphicSetColor(graphic_[i], c);
  }
  ++steps_;
  if (awake != awake_) printf("t = %.2f s: %d boxes awake\n", steps_ / 60.0, awake);
  awake_ = awake;
}

int main(int argc, const char *argv[]) {
  const MeReal box_side[] = {(MeReal)1.0, (MeReal).3, (MeReal)1.0};
  const MeReal box_separation = (MeReal)2.0;
  const MeReal h = (MeReal)1 / 60, r = 2;
  static MeMatrix4 groundTM;
  RRender *rc = SampleOpen(argc, argv, "stacking boxes: 21 boxes drop, stand and fall asleep");
  MstUniverseID universe = SampleUniverse(0);
  MdtWorldID world = universe->world;
  MstBridgeID bridge = universe->bridge;
  MstMaterialID boxMaterial, groundMaterial;
  MdtContactParamsID box_ground, box_box;
  McdGeometryID boxGeometry;
  McdModelID ground;
  MeMatrix3 I = {{5, 0, 0}, {0, 5, 0}, {0, 0, 5}};
  int i;

  MdtWorldSetGravity(world, 0, -(MeReal)9.81, 0);
  /* Epsilon a little lower: harder contacts, less springy. */
  MdtWorldSetEpsilon(world, (MeReal)0.005);
  /* The guide's gamma = 5 is a rate (per second); ours is the fraction of
   * the error corrected per step, so the same correction is 5 * h. */
  MdtWorldSetGamma(world, 5 * h);
  MdtWorldSetAutoDisable(world, 1);
  /* Thresholds raised by r = 2 for 21 boxes, so they sleep sooner. */
  MdtWorldSetAutoDisableVelocityThreshold(world, r * (MeReal)0.02);
  MdtWorldSetAutoDisableAccelerationThreshold(world, r * (MeReal)0.5);
  MdtWorldSetAutoDisableAngularVelocityThreshold(world, r * (MeReal)0.001);
  MdtWorldSetAutoDisableAngularAccelerationThreshold(world, r * (MeReal)0.002);

  /* Box on ground: normal-force friction both ways, mu 0.4; box on box:
   * the default box friction, mu 0.1; hardly any bounce. */
  boxMaterial = MstBridgeGetNewMaterial(bridge);
  groundMaterial = MstBridgeGetNewMaterial(bridge);
  box_ground = MstBridgeGetContactParams(bridge, boxMaterial, groundMaterial);
  MdtContactParamsSetPrimaryFrictionModel(box_ground, MdtFrictionModelNormalForce);
  MdtContactParamsSetSecondaryFrictionModel(box_ground, MdtFrictionModelNormalForce);
  MdtContactParamsSetType(box_ground, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(box_ground, (MeReal)0.4);
  /* The normal-force model reads the coefficient, which SetFriction (the
   * box model's force limit, in newtons) leaves at 0: set it too. */
  MdtContactParamsSetFrictionCoefficient(box_ground, (MeReal)0.4);
  MdtContactParamsSetRestitution(box_ground, (MeReal)0.01);
  box_box = MstBridgeGetContactParams(bridge, boxMaterial, boxMaterial);
  MdtContactParamsSetType(box_box, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(box_box, (MeReal)0.1);
  MdtContactParamsSetRestitution(box_box, (MeReal)0.01);

  /* The ground: a plane through the origin facing +y (a plane's normal is
   * its z axis, so the TM's rows are x, -z, y). */
  MeMatrix4TMMakeIdentity(groundTM);
  groundTM[1][1] = 0, groundTM[1][2] = -1;
  groundTM[2][1] = 1, groundTM[2][2] = 0;
  ground = MstFixedModelCreate(universe, McdPlaneCreate(universe->frame), groundTM);
  McdModelSetMaterial(ground, groundMaterial);
  SampleGround(rc, 12, 0);

  /* One geometry for all 21 boxes. */
  boxGeometry = McdBoxCreate(universe->frame, box_side[0], box_side[1], box_side[2]);
  for (i = 0; i < NO_BOXES; ++i) {
    McdModelID model = MstModelAndBodyCreate(universe, boxGeometry, 1);
    box_[i] = McdModelGetBody(model);
    MdtBodySetMass(box_[i], 5);
    MdtBodySetInertiaTensor(box_[i], I);
    MdtBodySetPosition(box_[i], 0, (i + 1) * box_side[1] * box_separation, 0);
    McdModelSetMaterial(model, boxMaterial);
    colour_[i][0] = i % 2 ? 0.95f : 0.25f, colour_[i][1] = 0.3f + 0.03f * (float)i;
    colour_[i][2] = i % 2 ? 0.3f : 0.9f, colour_[i][3] = 1;
    graphic_[i] =
        RGraphicBoxCreate(rc, box_side[0], box_side[1], box_side[2], colour_[i], MdtBodyGetTransformPtr(box_[i]));
    SampleRecordBody(box_[i]);
  }

  SampleCamera(rc, 0, 4, 0, 12, (MeReal)0.5, (MeReal)0.15);
  SampleRun(argc, argv, "stacking_boxes", h, NULL, Shade);
  return 0;
}
