// Speculative contacts: the collision reports contacts up to how far a pair
// can close in a step, and a contact found apart lets the gap close within
// the step but no further (engine/mdt/bcl/contact.cpp, collisions.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "anchor_scene.h"
#include "step_scene.h"

namespace {

using step_test::Contacts;
using step_test::kH;
using step_test::Scene;

// The highest enabled body of the world.
MdtBodyID TopBody(MdtWorldID w) {
  MdtBodyID top = nullptr;
  MeReal y = -MEINFINITY;
  for (int p = 0; p < MdtWorldGetPartitionCount(w); ++p)
    for (int b = 0; b < MdtWorldGetPartitionBodyCount(w, p); ++b) {
      MdtBodyID body = MdtWorldGetPartitionBody(w, p, b);
      MeVector3 x;
      MdtBodyGetPosition(body, x);
      if (x[1] > y) y = x[1], top = body;
    }
  return top;
}

TEST(Speculative, TheStackWithMillimetreGapsSettlesCalmly) {
  // stack21 (SCENES.md): 21 boxes, each 1 mm above the one below. Without
  // speculative contacts the gaps closed one box per step and the stack
  // rebounded at 4.8 m/s. With them each box falls until it meets the one
  // below, inelastically: the top box falls through all 20 gaps, so it
  // must reach sqrt(2 g 0.020) = 0.626 m/s (a little more as the soft
  // contacts below it sag, at most ~0.1 m/s more at the default epsilon),
  // and then it must come to rest without bouncing back up.
  auto scene = karma::scenes::MakeStack21();
  scene->step();
  MdtBodyID top = TopBody(scene->world());
  ASSERT_NE(top, nullptr);
  double fastestDown = 0, fastestUp = 0;
  for (int i = 1; i < 180; ++i) {
    scene->step();
    MeVector3 v;
    MdtBodyGetLinearVelocity(top, v);
    fastestDown = std::max(fastestDown, -(double)v[1]);
    if (i > 30) fastestUp = std::max(fastestUp, (double)v[1]);
  }
  std::printf("stack21, first 3 s: top box fastest %.3f m/s down; after 0.5 s %.3f m/s up\n", fastestDown, fastestUp);
  EXPECT_GT(fastestDown, 0.62);
  EXPECT_LT(fastestDown, 0.72);
  EXPECT_LT(fastestUp, 0.05);
  EXPECT_LT(scene->finish().maxSpeed, 0.72);
}

TEST(Speculative, AFastBallDoesNotPassAThinWall) {
  // A 5 cm ball (r = 2.5 cm) at 100 m/s, a 10 cm wall, steps of 1/60 s:
  // the ball moves 1.67 m a step, 16 times the wall's thickness.
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  const MeReal r = (MeReal)0.025, face = -(MeReal)0.05;
  s.fixedBox((MeReal)0.1, 4, 4, 0, 0, 0);
  McdModelID ball = s.ball(r, -3, 0, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(ball), 100, 0, 0);
  MeReal farthest = -10;
  for (int i = 0; i < 30; ++i) {
    s.step();
    MeVector3 p;
    Scene::position(ball, p);
    farthest = std::max(farthest, p[0]);
  }
  std::printf("ball at 100 m/s: farthest centre x %.4f m (wall face at %.3f)\n", (double)farthest, (double)face);
  EXPECT_LT(farthest, face - r + (MeReal)0.005);
  MeVector3 v;
  Scene::velocity(ball, v);
  EXPECT_LE(v[0], (MeReal)1e-3);  // stopped (restitution 0), not beyond
}

TEST(Speculative, SteppingToTheSafeTimeThenOnProducesTheContact) {
  Scene s;
  MdtWorldSetEpsilon(s.u->world, (MeReal)1e-6);  // stiff: the impact must not sink by softness
  const MeReal r = (MeReal)0.1;
  McdModelID ball = s.ball(r, 0, 1, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(ball), 0, -40, 0);
  s.step(1);  // the world now knows its step size
  McdModelPair *pair = McdModelPairCreate(ball, s.ground);
  McdHello(pair);
  McdSafeTimeResult st{};
  ASSERT_TRUE(McdSafeTime(pair, kH, &st));
  EXPECT_GT(st.time, 0);
  EXPECT_LT(st.time, kH);
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  MstUniverseStep(s.u, st.time);  // to the moment before impact
  MeVector3 p;
  Scene::position(ball, p);
  EXPECT_NEAR(p[1], r, 1e-3);
  MstUniverseStep(s.u, kH);
  MdtContactID c[4];
  EXPECT_GE(Contacts(ball, c, 4), 1);
  Scene::position(ball, p);
  EXPECT_GT(p[1], r - (MeReal)1e-3) << "the ball went into the ground";
}

TEST(Speculative, AContactApartPushesOnlyToStopTheGapClosing) {
  // A box 2 cm above the ground, falling slowly: it gets its contacts
  // early, but they push nothing until the box would reach the ground.
  Scene s;
  McdModelID b = s.box(1, 1, 1, 0, (MeReal)0.52, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(b), 0, (MeReal)-0.3, 0);
  s.step(1);
  MdtContactID c[8];
  const int n = Contacts(b, c, 8);
  // Whether contacts are already there depends on the margin (0.3 m/s of
  // a 1/60 s step is 5 mm, short of 2 cm); none may push yet.
  for (int k = 0; k < n; ++k) EXPECT_LT(MdtContactGetPenetration(c[k]), 0);
  for (int k = 0; k < n; ++k) EXPECT_EQ(MdtContactGetNormalForce(c[k]), 0);
  MeVector3 v;
  Scene::velocity(b, v);
  EXPECT_NEAR(v[1], (MeReal)-0.3 - step_test::kG * kH, 1e-4);  // free fall
  s.step(120);
  MeVector3 p;
  Scene::position(b, p);
  // Landed and resting, as deep as the world's softness eps lets four
  // contacts sink under m g: at rest gamma d / h = eps lambda with
  // lambda = m g h / 4, so d = eps m g h^2 / (4 gamma).
  const MeReal m = 100, eps = MdtWorldGetEpsilon(s.u->world), gamma = MdtWorldGetGamma(s.u->world);
  EXPECT_NEAR(0.5 - p[1], eps * m * step_test::kG * kH * kH / (4 * gamma), 1e-5);
}

TEST(Speculative, AnAdhesiveContactDoesNotPullFromADistance) {
  Scene s;
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  MdtContactParamsID params = MstBridgeGetContactParams(s.u->bridge, 0, 0);
  MdtContactParamsSetMaxAdhesiveForce(params, MEINFINITY);
  McdModelID b = s.box(1, 1, 1, 0, (MeReal)0.52, 0);  // 2 cm above the ground
  s.step(1);
  // Leaving at 1.5 m/s: the margin (2.5 cm) reaches the ground, so the
  // pair has a contact 2 cm apart, adhesive; it must not pull.
  MdtBodySetLinearVelocity(McdModelGetBody(b), 0, (MeReal)1.5, 0);
  s.step(1);
  MeVector3 v;
  Scene::velocity(b, v);
  EXPECT_NEAR(v[1], 1.5, 1e-4);
}

}  // namespace
