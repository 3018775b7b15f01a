/* two_spheres: the guide's walk through the pipeline with two spheres
 * that approach, collide and part. Each sphere's axis-aligned bounding box
 * is drawn as a wire frame, green while the boxes are apart, yellow while
 * they overlap but the spheres do not touch, red while the spheres touch;
 * every change of stage is printed with what the bridge and the world do
 * in it. The spheres are offset sideways so that their boxes meet before
 * they do, and they rebound at an angle. */
#include "sample.h"

#include <stdio.h>

static McdModelID model_[2];
static MdtBodyID body_[2];
static RGraphic *boxG_[2];
static MeMatrix4 boxTM_[2];
static int steps_, stage_ = 1, touched_;

static int BoxesOverlap(void) {
  MeVector3 lo[2], hi[2];
  int k;
  McdModelGetAABB(model_[0], lo[0], hi[0]);
  McdModelGetAABB(model_[1], lo[1], hi[1]);
  for (k = 0; k < 3; ++k)
    if (hi[0][k] < lo[1][k] || hi[1][k] < lo[0][k]) return 0;
  return 1;
}

static void Stage(void) {
  static const char *what[6] = {
      "",
      "1: boxes apart: no pair, no contacts; each sphere its own partition",
      "2: boxes overlap: a hello pair; the test finds no contact",
      "3: the spheres touch: a contact group, one partition, Kea pushes them apart",
      "4: moving apart: a staying pair; the test finds no contact, the contact goes",
      "5: boxes apart again: a goodbye pair; the contact group is destroyed",
  };
  static const float colour[6][4] = {{0, 0, 0, 1},        {0.2f, 0.9f, 0.2f, 1}, {1, 0.85f, 0.1f, 1},
                                     {1, 0.15f, 0.1f, 1}, {1, 0.85f, 0.1f, 1},   {0.2f, 0.9f, 0.2f, 1}};
  const int overlap = BoxesOverlap();
  const int touching = MdtBodyGetFirstContact(body_[0]) != NULL;
  int stage, i;
  if (touching) touched_ = 1;
  stage = !overlap ? (touched_ ? 5 : 1) : touching ? 3 : touched_ ? 4 : 2;
  ++steps_;
  if (stage != stage_) printf("step %3d: stage %s\n", steps_, what[stage]);
  stage_ = stage;
  for (i = 0; i < 2; ++i) {
    MeVector3 p;
    MdtBodyGetPosition(body_[i], p);
    MeMatrix4TMSetPosition(boxTM_[i], p[0], p[1], p[2]);
    RGraphicSetColor(boxG_[i], colour[stage]);
  }
}

int main(int argc, const char *argv[]) {
  const float colour[2][4] = {{0.9f, 0.4f, 0.1f, 1}, {0.2f, 0.5f, 0.95f, 1}};
  const MeReal r = (MeReal)0.5;
  RRender *rc = SampleOpen(argc, argv, "two spheres colliding: box colour = pipeline stage");
  MstUniverseID universe = SampleUniverse(0);
  MstMaterialID ball = MstBridgeGetNewMaterial(universe->bridge);
  McdGeometryID sphere = McdSphereCreate(universe->frame, r);
  int i;

  /* No gravity; perfectly elastic contacts between the spheres. */
  MdtContactParamsSetRestitution(MstBridgeGetContactParams(universe->bridge, ball, ball), 1);
  for (i = 0; i < 2; ++i) {
    const MeReal side = i ? 1 : -1;
    model_[i] = MstModelAndBodyCreate(universe, sphere, 1);
    body_[i] = McdModelGetBody(model_[i]);
    McdModelSetMaterial(model_[i], ball);
    MdtBodySetPosition(body_[i], 2 * side, 0, (MeReal)0.2 * side);
    MdtBodySetLinearVelocity(body_[i], -side, 0, 0);
    RGraphicSphereCreate(rc, r, colour[i], MdtBodyGetTransformPtr(body_[i]));
    MeMatrix4TMMakeIdentity(boxTM_[i]);
    MeMatrix4TMSetPosition(boxTM_[i], 2 * side, 0, (MeReal)0.2 * side);
    boxG_[i] = RGraphicBoxCreate(rc, 2 * r, 2 * r, 2 * r, colour[1], boxTM_[i]);
    RGraphicSetWireframe(boxG_[i], 1);
    SampleRecordBody(body_[i]);
  }
  SampleGround(rc, 12, (MeReal)-0.5);

  printf("step   0: stage %s\n", "1: boxes apart: no pair, no contacts; each sphere its own partition");
  SampleCamera(rc, 0, 0, 0, 6, 0, (MeReal)0.6);
  SampleRun(argc, argv, "two_spheres", (MeReal)1 / 60, NULL, Stage);
  return 0;
}
