/* stool: the guide's aggregate geometry. One model, one body, five
 * geometries: a 2.2 x 2.2 x 0.1 seat and four legs (cylinders of radius
 * 0.1, 2 long), each placed by its own relative transform. The stool is
 * dropped tilted; it lands on two legs and rocks onto all four. The guide
 * builds it with z up; here y is up (as in the viewer), so the seat's thin
 * side is along y and each leg is turned from z onto y. */
#include "sample.h"

#include <stdio.h>

#define PARTS 5

static McdModelID stool_;
static MeMatrix4 relTM_[PARTS];   /* kept by pointer by the aggregate */
static MeMatrix4 worldTM_[PARTS]; /* what the graphics follow */

/* Each part's world TM: its relative TM, then the model's. */
static void PlaceParts(void) {
  int i;
  for (i = 0; i < PARTS; ++i) MeMatrix4TMCompose(worldTM_[i], relTM_[i], McdModelGetTransformPtr(stool_));
}

int main(int argc, const char *argv[]) {
  const float wood[4] = {0.7f, 0.45f, 0.2f, 1}, dark[4] = {0.4f, 0.25f, 0.1f, 1};
  const MeReal legXZ[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  /* A leg's axis is z: rows x -> x, y -> -z, z -> y turn it upright. */
  MeMatrix3 upright = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
  static MeMatrix4 groundTM;
  RRender *rc = SampleOpen(argc, argv, "stool: an aggregate of a seat and four legs");
  /* Aggregate children take geometry instances from a pool. */
  MstUniverseID universe = SampleUniverse(100);
  McdFrameworkID framework = universe->frame;
  McdGeometryID seat, leg;
  McdAggregateID ag;
  MdtBodyID body;
  MeVector4 q;
  int i;

  MdtWorldSetGravity(universe->world, 0, (MeReal)-9.81, 0);
  MeMatrix4TMMakeIdentity(groundTM);
  groundTM[1][1] = 0, groundTM[1][2] = -1, groundTM[2][1] = 1, groundTM[2][2] = 0;
  MstFixedModelCreate(universe, McdPlaneCreate(framework), groundTM);
  SampleGround(rc, 12, 0);

  seat = McdBoxCreate(framework, (MeReal)2.2, (MeReal)0.1, (MeReal)2.2);
  leg = McdCylinderCreate(framework, (MeReal)0.1, 2);
  ag = McdAggregateCreate(framework, PARTS);
  MeMatrix4TMMakeIdentity(relTM_[0]);
  MeMatrix4TMSetPosition(relTM_[0], 0, 1, 0);
  McdAggregateAddElement(ag, seat, relTM_[0]);
  for (i = 0; i < 4; ++i) {
    MeMatrix4TMMakeFromRotationAndPosition(relTM_[i + 1], upright, legXZ[i][0], 0, legXZ[i][1]);
    McdAggregateAddElement(ag, leg, relTM_[i + 1]);
  }
  stool_ = MstModelAndBodyCreate(universe, ag, 1);
  body = McdModelGetBody(stool_);

  /* Tilted 0.3 rad about x, the lowest leg 0.3 m above the ground. */
  q[0] = MeCos((MeReal)0.15), q[1] = MeSin((MeReal)0.15), q[2] = 0, q[3] = 0;
  MdtBodySetQuaternion(body, q[0], q[1], q[2], q[3]);
  MdtBodySetPosition(body, 0, (MeReal)1.6, 0);
  McdModelUpdate(stool_);
  PlaceParts();

  RGraphicBoxCreate(rc, (MeReal)2.2, (MeReal)0.1, (MeReal)2.2, wood, worldTM_[0]);
  for (i = 1; i < PARTS; ++i) RGraphicCylinderCreate(rc, (MeReal)0.1, 2, dark, worldTM_[i]);

  SampleCamera(rc, 0, (MeReal)0.8, 0, 8, (MeReal)0.5, (MeReal)0.3);
  SampleRecordBody(body);
  SampleRun(argc, argv, "stool", (MeReal)1 / 60, NULL, PlaceParts);
  return 0;
}
