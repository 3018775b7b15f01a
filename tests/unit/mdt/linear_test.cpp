// Linear1 (point on a plane) and Linear2 (point on a line).
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

TEST(Linear1, RemovesOnlyTheNormalDirection) {
  // Plane through the origin with normal y, gravity -y, a force in the plane
  // and a torque: the body stays on the plane, slides freely in x and z
  // (v = F t / m) and turns freely (w = T t / I).
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtLinear1ID j = MdtLinear1Create(w);
  MdtLinear1SetBodies(j, b, nullptr);
  MdtLinear1SetAxis(j, 0, 1, 0);
  MdtLinear1Enable(j);
  double worst = 0;
  for (int i = 0; i < 100; ++i) {
    MdtBodyAddForce(b, 1, 0, 2);
    MdtBodyAddTorque(b, 0, (MeReal)0.4, 0);
    MdtWorldStep(w, (MeReal)0.01);
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    worst = std::max(worst, std::fabs((double)x[1]));
  }
  EXPECT_LT(worst, 1e-4);
  MeVector3 v, omega, n;
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(v[0], 1, 1e-5);
  EXPECT_NEAR(v[2], 2, 1e-5);
  EXPECT_NEAR(v[1], 0, 1e-3);
  EXPECT_NEAR(omega[1], 1, 1e-5);
  MdtLinear1GetAxis(j, n);
  EXPECT_NEAR(n[1], 1, 1e-6);
  MeVector3 f;
  MdtLinear1GetForce(j, 0, f);
  EXPECT_NEAR(f[1], kG, 1e-2);  // carries the weight
}

TEST(Linear1, OffsetPointLetsTheBodyPivot) {
  // The constrained point is 1 m to the side of the body's centre on a
  // horizontal plane; gravity swings the body down about it: the point stays
  // on the plane while the centre falls. The rows are linear in the
  // velocities, so a point swinging at w about the centre drifts off by about
  // h^2 w^2 r per step, corrected at the rate gamma: h^2 w^2 r / gamma. The
  // centre falls straight down (no horizontal force), so w peaks at
  // sqrt(2 m g r / I) = 7 rad/s after a quarter turn: 4.3 mm at h = 1/240.
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtLinear1ID j = MdtLinear1Create(w);
  MdtLinear1SetBodies(j, b, nullptr);
  MdtLinear1SetPosition(j, 1, 0, 0);
  MdtLinear1SetAxis(j, 0, 1, 0);
  MdtLinear1Enable(j);
  double worst = 0;
  for (int i = 0; i < 240; ++i) {
    MdtWorldStep(w, (MeReal)1 / 240);
    MeVector3 p;
    MdtConstraintBodyGetPosition(MdtLinear1QuaConstraint(j), 0, p);
    worst = std::max(worst, std::fabs((double)p[1]));
  }
  EXPECT_LT(worst, 5e-3);
  MeVector3 x;
  MdtBodyGetPosition(b, x);
  EXPECT_LT(x[1], -0.1);
}

TEST(Linear2, PointSlidesOnlyAlongTheLine) {
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtLinear2ID j = MdtLinear2Create(w);
  MdtLinear2SetBodies(j, b, nullptr);
  MdtLinear2SetDirection(j, 1, 0, 0);
  MdtLinear2Enable(j);
  double worst = 0;
  for (int i = 0; i < 100; ++i) {
    MdtBodyAddForce(b, 1, 0, 3);
    MdtBodyAddTorque(b, (MeReal)0.4, 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    worst = std::max(worst, std::hypot((double)x[1], (double)x[2]));
  }
  EXPECT_LT(worst, 1e-4);
  MeVector3 v, omega, d;
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(v[0], 1, 1e-5);
  EXPECT_NEAR(std::hypot((double)v[1], (double)v[2]), 0, 1e-3);
  EXPECT_NEAR(omega[0], 1, 1e-5);
  MdtLinear2GetDirection(j, d);
  EXPECT_NEAR(d[0], 1, 1e-6);
}

TEST(Linear2, BeadOnARailCarriedByAMovingBody) {
  // Body 1 is a rail along x moving at 1 m/s in z; body 0 is a bead on it.
  // The bead is dragged along z (both share the momentum: 0.5 m/s each) and
  // stays on the rail.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID bead = makeBody(w, 0, 0, 0);
  MdtBodyID rail = makeBody(w, 0, 0, 0);
  MdtBodySetLinearVelocity(rail, 0, 0, 1);
  MdtLinear2ID j = MdtLinear2Create(w);
  MdtLinear2SetBodies(j, bead, rail);
  MdtLinear2SetDirection(j, 1, 0, 0);
  MdtLinear2Enable(j);
  for (int i = 0; i < 100; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 v0, v1, x0, x1;
  MdtBodyGetLinearVelocity(bead, v0);
  MdtBodyGetLinearVelocity(rail, v1);
  EXPECT_NEAR(v0[2], 0.5, 1e-3);
  EXPECT_NEAR(v1[2], 0.5, 1e-3);
  MdtBodyGetPosition(bead, x0);
  MdtBodyGetPosition(rail, x1);
  EXPECT_NEAR(x0[2], x1[2], 1e-3);
}
