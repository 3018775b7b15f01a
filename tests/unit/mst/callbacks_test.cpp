// The bridge's callbacks and their return values, contact groups (first
// touch, body order with a fixed model, gone with the goodbye), materials.
#include "mst_test_support.h"

using namespace mst_test;

namespace {
int gCalls = 0;
MeBool gReturn = 1;
MeBool MEAPI IntersectCB(McdIntersectResult *r) {
  ++gCalls;
  EXPECT_GT(r->contactCount, 0);
  return gReturn;
}
MeBool MEAPI PerContactCB(McdIntersectResult *, McdContact *colC, MdtContactID dynC) {
  ++gCalls;
  EXPECT_NEAR(MdtContactGetPenetration(dynC), -colC->separation, 1e-6);
  return gReturn;
}
MeBool MEAPI PerPairCB(McdIntersectResult *, MdtContactGroupID g) {
  ++gCalls;
  EXPECT_GT(MdtContactGroupGetCount(g), 0);
  return gReturn;
}

// Drops a ball from z = 1 onto the ground for 100 steps with one callback
// returning `keep`; returns the ball's final height and the call count.
double Drop(int which, MeBool keep, int *calls) {
  Scene s;
  McdModelID ball = s.ball((MeReal)0.5, 0, 0, 1);
  const MstMaterialID m = MstBridgeGetNewMaterial(s.u->bridge);
  McdModelSetMaterial(ball, m);
  MstBridgeID b = s.u->bridge;
  if (which == 0) MstBridgeSetIntersectCB(b, 0, m, IntersectCB);
  if (which == 1) MstBridgeSetPerContactCB(b, m, 0, PerContactCB);
  if (which == 2) MstBridgeSetPerPairCB(b, 0, m, PerPairCB);
  gCalls = 0;
  gReturn = keep;
  s.step(100);
  *calls = gCalls;
  return Scene::z(ball);
}
}  // namespace

TEST(MstCallbacks, ReturningOneKeepsTheContacts) {
  for (int which = 0; which < 3; ++which) {
    int calls = 0;
    EXPECT_NEAR(Drop(which, 1, &calls), 0.5, 2e-3) << "callback " << which;
    EXPECT_GT(calls, 10) << "callback " << which;
  }
}

TEST(MstCallbacks, ReturningZeroDropsTheContacts) {
  for (int which = 0; which < 3; ++which) {
    int calls = 0;
    EXPECT_LT(Drop(which, 0, &calls), -1) << "callback " << which << ": fell through";
    EXPECT_GT(calls, 0) << "callback " << which;
  }
}

TEST(MstCallbacks, GettersAndEitherOrder) {
  Scene s;
  MstBridgeID b = s.u->bridge;
  const MstMaterialID m = MstBridgeGetNewMaterial(b);
  MstBridgeSetPerPairCB(b, m, 0, PerPairCB);
  EXPECT_EQ(MstBridgeGetPerPairCB(b, 0, m), PerPairCB);
  EXPECT_EQ(MstBridgeGetIntersectCB(b, m, 0), nullptr);
  MstBridgeSetIntersectCB(b, 0, m, IntersectCB);
  EXPECT_EQ(MstBridgeGetIntersectCB(b, m, 0), IntersectCB);
  MstBridgeSetPerContactCB(b, m, m, PerContactCB);
  EXPECT_EQ(MstBridgeGetPerContactCB(b, m, m), PerContactCB);
  WarningCapture w;
  EXPECT_EQ(MstBridgeGetContactParams(b, 0, 5), nullptr);  // material 5 not in use
  EXPECT_TRUE(w.lastMentions("MstBridgeGetContactParams"));
  for (int i = 2; i < 10; ++i) EXPECT_EQ(MstBridgeGetNewMaterial(b), i);
  EXPECT_EQ(MstBridgeGetNewMaterial(b), -1);
  EXPECT_TRUE(w.lastMentions("materialsMaxCount"));
}

// The guide's example: a fast ball passes through a wall (PerPair returns
// 0 and slows it down); a slow one bounces off. Only sphere-sphere,
// sphere-plane and box-plane exist yet, so the "wall" is a fixed sphere of
// radius 0.3 at the origin, hit head-on by a ball of radius 0.1; the ball
// loses 10% per step inside (the guide halves it, which would stop it
// inside this thick wall).
namespace {
MstMaterialID gBallMat;
const MeReal kThresh = 5;
MeBool MEAPI WallCollisionCB(McdIntersectResult *c, MdtContactGroupID) {
  MdtBodyID ball = McdModelGetMaterial(c->pair->model1) == gBallMat ? McdModelGetBody(c->pair->model1)
                                                                    : McdModelGetBody(c->pair->model2);
  MeVector3 vel;
  MdtBodyGetLinearVelocity(ball, vel);
  if (MeVector3Magnitude(vel) > kThresh) {
    MeVector3Scale(vel, (MeReal)0.9);
    MdtBodySetLinearVelocity(ball, vel[0], vel[1], vel[2]);
    return 0;  // delete the contacts: through the wall
  }
  return 1;  // keep them: bounce off
}
double ThrowAtWall(MeReal speed) {
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  MeMatrix4 wallTM;
  MeMatrix4TMMakeIdentity(wallTM);
  McdModelID wall = MstFixedModelCreate(s.u, McdSphereCreate(s.u->frame, (MeReal)0.3), wallTM);
  McdModelID ball = s.ball((MeReal)0.1, -2, 0, 0);
  gBallMat = MstBridgeGetNewMaterial(s.u->bridge);
  const MstMaterialID wallMat = MstBridgeGetNewMaterial(s.u->bridge);
  McdModelSetMaterial(ball, gBallMat);
  McdModelSetMaterial(wall, wallMat);
  MstBridgeSetPerPairCB(s.u->bridge, wallMat, gBallMat, WallCollisionCB);
  MdtContactParamsSetRestitution(MstBridgeGetContactParams(s.u->bridge, gBallMat, wallMat), 1);
  MdtBodySetLinearVelocity(McdModelGetBody(ball), speed, 0, 0);
  s.step(150);
  MeVector3 p;
  MdtBodyGetPosition(McdModelGetBody(ball), p);
  return p[0];
}
}  // namespace

TEST(MstCallbacks, PerPairZeroLetsTheBallThroughTheWall) {
  const double fast = ThrowAtWall(20), slow = ThrowAtWall(2);
  std::printf("[ figures  ] after 1.5 s: fast ball at x = %.3f, slow ball at x = %.3f\n", fast, slow);
  EXPECT_GT(fast, 2.0);   // went through and on
  EXPECT_LT(slow, -1.5);  // bounced back (restitution 1): about -0.4 - 2 * 0.7
}

TEST(MstContactGroups, GroupOnFirstTouchDynamicBodyFirstGoneWithGoodbye) {
  Scene s;
  McdModelID ball = s.ball((MeReal)0.5, 0, 0, (MeReal)0.8);
  MdtBodyID body = McdModelGetBody(ball);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  MdtBodySetLinearVelocity(body, 0, 0, -1);
  s.step();
  EXPECT_EQ(MdtWorldGetConstraintCount(s.u->world), 0u);  // apart: no group yet
  s.step(35);                                             // touching after 0.3 s
  EXPECT_GT(MdtWorldGetConstraintCount(s.u->world), 0u);
  // Find the group through the ball's contacts: body 0 is the ball.
  MdtContactID c = MdtBodyGetFirstContact(body);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(MdtContactGetBody(c, 0), body);
  EXPECT_EQ(MdtContactGetBody(c, 1), nullptr);
  MeVector3 n;
  MdtContactGetNormal(c, n);
  EXPECT_NEAR(n[2], 1, 1e-6);  // towards the ball
  // Pulled away far enough for the AABBs to part: goodbye takes the group.
  MdtBodySetPosition(body, 0, 0, 5);
  MdtBodySetLinearVelocity(body, 0, 0, 0);
  s.step(2);
  EXPECT_EQ(MdtWorldGetConstraintCount(s.u->world), 0u);
}
