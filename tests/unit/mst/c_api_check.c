/* c_api_check.c: Mst.h (with Mdt.h and Mcd.h) compiles as C11 and the
 * guide's universe program links from C: two balls on a plane. */
#include "Mst.h"

int mst_c_api_check(void);

static MeBool MEAPI KeepPair(McdIntersectResult *r, MdtContactGroupID g) {
  (void)r;
  return g != 0;
}

int mst_c_api_check(void) {
  static MeMatrix4 planeTM;
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  MstUniverseID universe;
  McdModelID ball;
  MstMaterialID ballMat;
  MdtContactParamsID p;
  MeVector3 pos;
  int i, ok;
  sizes.collisionModelsMaxCount = 3;
  universe = MstUniverseCreate(&sizes);
  if (!universe) return 0;
  MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, 0, -10);
  MeMatrix4TMMakeIdentity(planeTM);
  MstFixedModelCreate(universe, McdPlaneCreate(MstUniverseGetFramework(universe)), planeTM);
  ball = MstModelAndBodyCreate(universe, McdSphereCreate(universe->frame, 1), 1);
  MdtBodySetPosition(McdModelGetBody(ball), 0, 0, 3);
  ballMat = MstBridgeGetNewMaterial(universe->bridge);
  McdModelSetMaterial(ball, ballMat);
  p = MstBridgeGetContactParams(universe->bridge, MstBridgeGetDefaultMaterial(), ballMat);
  MdtContactParamsSetRestitution(p, (MeReal)0.2);
  MstBridgeSetPerPairCB(universe->bridge, ballMat, 0, KeepPair);
  for (i = 0; i < 200; ++i) MstUniverseStep(universe, (MeReal)0.01);
  MdtBodyGetPosition(McdModelGetBody(ball), pos);
  ok = pos[2] > (MeReal)0.99 && pos[2] < (MeReal)1.01;
  MstUniverseDestroy(universe);
  return ok;
}
