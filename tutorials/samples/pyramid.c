/* pyramid: the guide's convex mesh. Five points (an apex and a 6 x 6 base)
 * become a hull, the hull a model with a body; the pyramid is dropped on
 * one corner of its base, tips over and settles on its base. The body's
 * centre of mass is the hull's, 0.75 m above the base, not the mesh origin
 * (MstModelAndBodyCreate sets the offset). */
#include "sample.h"

int main(int argc, const char *argv[]) {
  const float sand[4] = {0.9f, 0.75f, 0.35f, 1};
  /* These are the five points of the pyramid. */
  MeVector3 pyramidPoints[] = {{0, 2, 0}, {-3, -1, -3}, {3, -1, -3}, {-3, -1, 3}, {3, -1, 3}};
  static MeMatrix4 groundTM;
  RRender *rc = SampleOpen(argc, argv, "pyramid: a convex mesh of five points");
  MstUniverseID universe = SampleUniverse(0);
  McdFrameworkID framework = MstUniverseGetFramework(universe);
  McdGeometryID pyramidGeom;
  McdModelID pyramidModel;
  MdtBodyID body;
  MeVector3 axis = {1, 0, 1};
  MeMatrix3 R;
  MeVector4 q;

  MdtWorldSetGravity(universe->world, 0, (MeReal)-9.81, 0);
  MeMatrix4TMMakeIdentity(groundTM);
  groundTM[1][1] = 0, groundTM[1][2] = -1, groundTM[2][1] = 1, groundTM[2][2] = 0;
  MstFixedModelCreate(universe, McdPlaneCreate(framework), groundTM);
  SampleGround(rc, 24, 0);

  pyramidGeom = McdConvexMeshCreateHull(framework, pyramidPoints, 5, 0);
  pyramidModel = MstModelAndBodyCreate(universe, pyramidGeom, 1);
  body = McdModelGetBody(pyramidModel);
  /* Tilted 0.35 rad about the (1, 0, 1) diagonal, a base corner first. */
  MeMatrix3FromAxisAngle(R, axis, (MeReal)0.35);
  MeQuaternionFromR(q, R);
  MdtBodySetQuaternion(body, q[0], q[1], q[2], q[3]);
  MdtBodySetPosition(body, 0, (MeReal)3.5, 0);

  SampleConvexMeshGraphic(rc, pyramidGeom, sand, McdModelGetTransformPtr(pyramidModel));
  SampleCamera(rc, 0, 1, 0, 16, (MeReal)0.4, (MeReal)0.35);
  SampleRecordBody(body);
  SampleRun(argc, argv, "pyramid", (MeReal)1 / 60, NULL, NULL);
  return 0;
}
