// The universe: Appendix A's default sizes, what MstUniverseCreate builds,
// models with bodies and fixed models, McdModelSetBody, mass properties,
// bad input.
#include "mst_test_support.h"

#include "mdt_bridge.h"

using namespace mst_test;

TEST(MstUniverse, DefaultSizesAreAppendixA) {
  const MstUniverseSizes &s = MstUniverseDefaultSizes;
  EXPECT_EQ(s.dynamicBodiesMaxCount, 100);
  EXPECT_EQ(s.dynamicConstraintsMaxCount, 500);
  EXPECT_EQ(s.collisionUserGeometryTypesMaxCount, 0);
  EXPECT_EQ(s.collisionModelsMaxCount, 100);
  EXPECT_EQ(s.collisionPairsMaxCount, 500);
  EXPECT_EQ(s.collisionGeometryInstancesMaxCount, 100);
  EXPECT_EQ(s.materialsMaxCount, 10);
  EXPECT_EQ(s.lengthScale, 1);
  EXPECT_EQ(s.massScale, 1);
}

TEST(MstUniverse, CreateBuildsEverythingInsideAChangeBlock) {
  Scene s(false);
  ASSERT_NE(s.u, nullptr);
  EXPECT_EQ(MstUniverseGetWorld(s.u), s.u->world);
  EXPECT_EQ(MstUniverseGetSpace(s.u), s.u->space);
  EXPECT_EQ(MstUniverseGetBridge(s.u), s.u->bridge);
  EXPECT_EQ(MstUniverseGetFramework(s.u), s.u->frame);
  EXPECT_EQ(MdtWorldGetMaxBodies(s.u->world), 100u);
  EXPECT_EQ(MdtWorldGetMaxConstraints(s.u->world), 500u);
  EXPECT_EQ(McdSpaceIsChanging(s.u->space), 1);
  EXPECT_EQ(MstBridgeGetMaterialCount(s.u->bridge), 1);
  EXPECT_EQ(MstBridgeGetDefaultMaterial(), 0);
  EXPECT_NE(MdtWorldGetBodyEnableCallback(s.u->world, nullptr), nullptr);
}

TEST(MstUniverse, ModelAndBodyShareTransformAndVelocity) {
  Scene s(false);
  McdModelID m = s.ball(2, 1, 2, 3, 3);
  MdtBodyID b = McdModelGetBody(m);
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(MdtBodyIsEnabled(b));
  EXPECT_EQ(McdModelGetSpace(m), s.u->space);
  EXPECT_EQ(McdModelGetTransformPtr(m), MdtBodyGetTransformPtr(b));
  EXPECT_EQ(McdModelGetLinearVelocityPtr(m), MdtBodyGetLinearVelocityPtr(b));
  EXPECT_EQ(McdModelGetAngularVelocityPtr(m), MdtBodyGetAngularVelocityPtr(b));
  EXPECT_EQ(MdtBodyGetCollisionModel(b), m);
  MdtBodySetLinearVelocity(b, 4, 5, 6);
  EXPECT_EQ(McdModelGetLinearVelocityPtr(m)[1], 5);
  // Mass properties of a sphere of radius 2 at density 3.
  const double mass = 3 * 4.0 / 3.0 * M_PI * 8;
  EXPECT_NEAR(MdtBodyGetMass(b), mass, mass * 1e-5);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  EXPECT_NEAR(I[0][0], 0.4 * mass * 4, mass * 4e-5);
  McdModelDynamicsReset(m);
  MeVector3 p, v;
  MdtBodyGetPosition(b, p);
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_EQ(p[0] + p[1] + p[2], 0);
  EXPECT_EQ(v[0] + v[1] + v[2], 0);
  McdModelSetBody(m, nullptr);
  EXPECT_EQ(MdtBodyGetCollisionModel(b), nullptr);
  EXPECT_EQ(McdModelGetLinearVelocityPtr(m), nullptr);
  McdModelSetBody(m, b);
  MstModelAndBodyDestroy(m);
  EXPECT_EQ(MdtWorldGetBodyCount(s.u->world), 0u);
  EXPECT_EQ(McdSpaceGetModelCount(s.u->space), 0);
}

TEST(MstUniverse, AModelGivenAnotherBodyGetsContactsBetweenItsNewBodies) {
  // A box rests (and falls asleep) on a fixed box; then the fixed model is
  // given a heavy enabled body of its own. The model must collide from then
  // on, and the pair's contacts act between the box and that body with
  // normals that push them apart: the two fall together, the box on top,
  // one box height apart. (The model used to stay frozen, so the base fell
  // away from the sleeping box; and with both awake the old group acted on
  // the box alone with its normals reversed, and the box fell through.)
  Scene s(false);
  MeMatrix4TMMakeIdentity(s.groundTM);
  s.groundTM[3][2] = (MeReal)-0.5;
  McdModelID ground = MstFixedModelCreate(s.u, McdBoxCreate(s.u->frame, 10, 10, 1), s.groundTM);
  McdModelID box = MstModelAndBodyCreate(s.u, McdBoxCreate(s.u->frame, 1, 1, 1), 100);
  MdtBodySetPosition(McdModelGetBody(box), 0, 0, (MeReal)0.5);
  s.step(60);
  ASSERT_NEAR(Scene::z(box), 0.5, 0.02);

  MdtBodyID base = MdtBodyCreate(s.u->world);
  MstAutoSetMassProperties(base, McdModelGetGeometry(ground), (MeReal)1e4);  // 1e6 kg
  MdtBodySetPosition(base, 0, 0, (MeReal)-0.5);
  MdtBodyEnable(base);
  McdModelSetBody(ground, base);
  s.step();
  MdtBodyID top = McdModelGetBody(box);
  int contacts = 0;
  for (MdtContactID c = MdtBodyGetFirstContact(top); c; c = MdtBodyGetNextContact(top, c), ++contacts) {
    MdtBodyID b0 = MdtContactGetBody(c, 0), b1 = MdtContactGetBody(c, 1);
    ASSERT_TRUE((b0 == top && b1 == base) || (b0 == base && b1 == top));
    MeVector3 n, p0, p1;
    MdtContactGetNormal(c, n);
    MdtBodyGetPosition(b0, p0);
    MdtBodyGetPosition(b1, p1);
    EXPECT_GT(n[0] * (p0[0] - p1[0]) + n[1] * (p0[1] - p1[1]) + n[2] * (p0[2] - p1[2]), 0);  // toward body 0
  }
  EXPECT_GT(contacts, 0);
  for (int i = 0; i < 30; ++i) {
    s.step();
    MeVector3 under;
    MdtBodyGetPosition(base, under);
    ASSERT_NEAR(Scene::z(box) - under[2], 1.0, 0.02) << "step " << i;
  }
}

TEST(MstUniverse, AModelLeftWithoutABodyTakesItsContactsOffTheOldOne) {
  // A ball falls asleep on the ground plane (both models frozen), then its
  // model gives up the body: the pair now joins two bodiless models, and
  // the old body must not keep the plane's contacts. Woken, it falls.
  Scene s;
  McdModelID m = s.ball((MeReal)0.5, 0, 0, (MeReal)0.5);
  MdtBodyID b = McdModelGetBody(m);
  s.step(100);
  ASSERT_FALSE(MdtBodyIsEnabled(b));
  ASSERT_NE(MdtBodyGetFirstContact(b), nullptr);
  McdModelSetBody(m, nullptr);
  s.step();
  EXPECT_EQ(MdtBodyGetFirstContact(b), nullptr);
  MdtBodyEnable(b);
  s.step(50);
  MeVector3 p;
  MdtBodyGetPosition(b, p);
  EXPECT_LT(p[2], 0);  // about -0.7 after 0.5 s of free fall
}

TEST(MstUniverse, TwoModelsOfOneBodyMakeNoContactGroup) {
  // Two overlapping models of one body: nothing to push apart, so no group
  // is made and nothing is warned (a group between a body and itself is
  // refused with a warning).
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  McdModelID a = s.ball((MeReal)0.5, 0, 0, 0);
  McdModelID c = s.ball((MeReal)0.5, (MeReal)0.5, 0, 0);
  MdtBodyID other = McdModelGetBody(c);
  McdModelSetBody(c, McdModelGetBody(a));
  MdtBodyDestroy(other);
  WarningCapture warnings;
  s.step(5);
  EXPECT_EQ(warnings.count(), 0u);
  EXPECT_EQ(MdtBodyGetFirstContact(McdModelGetBody(a)), nullptr);
}

TEST(MstUniverse, FixedModelKeepsItsTransformAndIsFrozen) {
  Scene s;
  EXPECT_EQ(McdModelGetTransformPtr(s.ground), (MeMatrix4Ptr)s.groundTM);
  EXPECT_EQ(McdSpaceModelIsFrozen(s.ground), 1);
  EXPECT_EQ(McdModelGetBody(s.ground), nullptr);
  MstFixedModelDestroy(s.ground);
  EXPECT_EQ(McdSpaceGetModelCount(s.u->space), 0);
}

TEST(MstUniverse, AutoMassOfABoxWithAnOffsetHull) {
  Scene s(false);
  MdtBodyID b = MdtBodyCreate(s.u->world);
  MeVector3 pts[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(pts[i], (MeReal)(i & 1), (MeReal)((i >> 1) & 1) * 2, (MeReal)((i >> 2) & 1) * 3);
  MstAutoSetMassProperties(b, McdConvexMeshCreateHull(s.u->frame, pts, 8, 0), 2);
  EXPECT_NEAR(MdtBodyGetMass(b), 12, 1e-4);
  MeVector3 com;
  MdtBodyGetCenterOfMassRelativePosition(b, com);
  EXPECT_NEAR(com[0], 0.5, 1e-5);
  EXPECT_NEAR(com[1], 1.0, 1e-5);
  EXPECT_NEAR(com[2], 1.5, 1e-5);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  EXPECT_NEAR(I[2][2], 12.0 / 12 * (1 + 4), 1e-3);
}

TEST(MstUniverse, BadInput) {
  WarningCapture w;
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  sizes.materialsMaxCount = 0;
  EXPECT_EQ(MstUniverseCreate(&sizes), nullptr);
  sizes = MstUniverseDefaultSizes;
  sizes.lengthScale = -1;
  EXPECT_EQ(MstUniverseCreate(&sizes), nullptr);
  EXPECT_EQ(MstUniverseCreate(nullptr), nullptr);
  EXPECT_EQ(w.count(), 3u);
  Scene s;
  MdtBodyID body = MdtBodyCreate(s.u->world);
  MstAutoSetMassProperties(body, McdPlaneCreate(s.u->frame), 1);  // no volume
  EXPECT_TRUE(w.lastMentions("MstAutoSetMassProperties"));
  EXPECT_EQ(MdtBodyGetMass(body), 1);
  EXPECT_EQ(MstModelAndBodyCreate(nullptr, nullptr, 1), nullptr);
  McdModelDynamicsReset(s.ground);  // no body
  EXPECT_TRUE(w.lastMentions("no body"));
  // Destroying a model outside a change block is refused.
  McdSpaceEndChanges(s.u->space);
  MstFixedModelDestroy(s.ground);
  EXPECT_TRUE(w.lastMentions("change block"));
  EXPECT_EQ(McdSpaceGetModelCount(s.u->space), 1);
  McdSpaceBeginChanges(s.u->space);
  MstUniverseStep(nullptr, kH);
  MstBridgeUpdateContacts(nullptr, nullptr, nullptr);
  EXPECT_EQ(MstBridgeCreate(s.u->frame, 0), nullptr);
  MstUniverseDestroy(nullptr);
}

extern "C" int mst_c_api_check(void);

TEST(MstUniverse, CProgramLandsABallOnThePlane) { EXPECT_EQ(mst_c_api_check(), 1); }
