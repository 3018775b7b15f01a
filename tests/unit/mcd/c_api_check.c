/* c_api_check.c: the Mcd headers compile as C11 (also together with the Mdt
 * headers, in either order) and the API links from C. */
#include "Mcd.h"
#include "MdtWorld.h"
#include "McdModel.h"

int mcd_c_api_check(void);

static int MEAPI NoTriangles(McdModelPair *pair, McdUserTriangle *list, MeVector3 pos, MeReal radius, int max) {
  (void)pair;
  (void)list;
  (void)pos;
  (void)radius;
  (void)max;
  return 0;
}

int mcd_c_api_check(void) {
  static MeMatrix4 planeTM, ballTM, legTM;
  McdFrameworkID fw = McdInit(0, 8, 4, 1);
  McdGeometryID plane, ball, tri, agg;
  McdModelID ground, m;
  McdModelPair *pair;
  McdContact contacts[4];
  McdIntersectResult result;
  MeVector3 mn = {-1, -1, -1}, mx = {1, 1, 1};
  MdtBodyID none = 0;
  int ok;
  if (!fw) return 0;
  McdPrimitivesRegisterTypes(fw);
  McdPrimitivesRegisterInteractions(fw);
  MeMatrix4TMMakeIdentity(planeTM);
  MeMatrix4TMMakeIdentity(ballTM);
  MeMatrix4TMMakeIdentity(legTM);
  MeMatrix4TMSetPosition(ballTM, 0, 0, (MeReal)0.5);
  plane = McdPlaneCreate(fw);
  ball = McdSphereCreate(fw, 1);
  tri = McdTriangleListCreate(fw, mn, mx, 4, NoTriangles);
  ((McdTriangleList *)tri)->triangleMaxCount = 8;
  agg = McdAggregateCreate(fw, 1);
  McdAggregateAddElement(agg, ball, legTM);
  ground = McdModelCreate(plane);
  m = McdModelCreate(ball);
  McdModelSetTransformPtr(ground, planeTM);
  McdModelSetTransformPtr(m, ballTM);
  McdModelStoreBody(m, none);
  McdModelUpdate(ground);
  McdModelUpdate(m);
  pair = McdModelPairCreate(m, ground);
  McdHello(pair);
  result.contacts = contacts;
  result.contactMaxCount = 4;
  ok = McdNearby(pair) && McdIntersect(pair, &result) && result.contactCount == 1 &&
       result.contacts[0].separation < 0 && result.pair->model1 == m && McdTriangleListGetMaxTriangles(tri) == 8 &&
       McdModelGetBody(m) == none;
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  McdTerm(fw);
  return ok;
}
