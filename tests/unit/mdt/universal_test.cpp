// Universal joint and cone limit: the guide's cone-limited universal, the
// 90-degree bend, the twist lock, a soft cone.
#include <algorithm>
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

TEST(Universal, DefaultAxesAreXInBody0AndYInBody1) {
  World w;
  MdtBodyID b = makeBody(w, 1, 2, 3);
  MdtUniversalID j = MdtUniversalCreate(w);
  MdtUniversalSetBodies(j, b, nullptr);
  MeVector3 a0, a1, p;
  MdtUniversalGetAxis(j, 0, a0);
  MdtUniversalGetAxis(j, 1, a1);
  EXPECT_EQ(a0[0], 1);
  EXPECT_EQ(a1[1], 1);
  MdtUniversalGetPosition(j, p);
  EXPECT_EQ(p[2], 3);
}

TEST(Universal, ConeLimitedUniversalRestsOnTheCone) {
  // The guide's example: a body at (2,0,0) on a universal to the world at
  // (-2,0,0) with axes z (body) and y (world), and a cone limit of half-angle
  // pi/3 on the bodies' x axes. It swings down under gravity and comes to
  // rest on the cone: 60 degrees below the horizontal.
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID body = makeBody(w, 2, 0, 0);
  MdtUniversalID u = MdtUniversalCreate(w);
  MdtUniversalSetBodies(u, body, nullptr);
  MdtUniversalSetPosition(u, -2, 0, 0);
  MdtUniversalSetAxis(u, 0, 0, 0, 1);
  MdtUniversalSetAxis(u, 1, 0, 1, 0);
  MdtUniversalEnable(u);
  MdtConeLimitID cone = MdtConeLimitCreate(w);
  MdtConeLimitSetBodies(cone, body, nullptr);
  MdtConeLimitSetConeHalfAngle(cone, (MeReal)(ME_PI / 3.));
  MdtConeLimitEnable(cone);
  double widest = 0;
  for (int i = 0; i < 1000; ++i) {
    MdtWorldStep(w, (MeReal)0.01);
    widest = std::max(widest, (double)MdtConeLimitGetAngle(cone));
  }
  const double alpha = M_PI / 3;
  EXPECT_NEAR(MdtConeLimitGetAngle(cone), alpha, 0.02 * alpha);
  EXPECT_LT(widest, alpha * 1.02);
  MeVector3 x, omega;
  MdtBodyGetPosition(body, x);
  EXPECT_NEAR(x[0], -2 + 4 * std::cos(alpha), 0.02 * 4);
  EXPECT_NEAR(x[1], -4 * std::sin(alpha), 0.02 * 4);
  EXPECT_NEAR(x[2], 0, 1e-3);
  MdtBodyGetAngularVelocity(body, omega);
  EXPECT_LT(MeVector3Magnitude(omega), 1e-2);
  EXPECT_LT(anchorGap(MdtUniversalQuaConstraint(u)), 1e-3);
}

TEST(Universal, BendThroughNinetyDegreesStaysFinite) {
  // Torques about both free axes spin the stick round and round through the
  // 90-degree bend (the stick along the world's y axis, body 1's joint axis)
  // for 60 s. The state must stay finite and the joint must hold.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 1, 0, 0);
  MdtBodySetAngularVelocityDamping(b, (MeReal)0.5);
  MdtUniversalID j = MdtUniversalCreate(w);
  MdtUniversalSetBodies(j, b, nullptr);
  MdtUniversalSetPosition(j, 0, 0, 0);
  MdtUniversalSetAxis(j, 0, 0, 0, 1);
  MdtUniversalSetAxis(j, 1, 0, 1, 0);
  MdtUniversalEnable(j);
  double maxBend = 0, worstGap = 0, worstDot = 0;
  bool finite = true;
  for (int i = 0; i < 6000 && finite; ++i) {
    MdtBodyAddTorque(b, 0, (MeReal)0.3, 2);
    MdtWorldStep(w, (MeReal)0.01);
    finite = bodyFinite(b);
    MeVector3 stick, a0, b1;
    bodyDirection(b, 1, 0, 0, stick);
    const MeVector3 x = {1, 0, 0};
    maxBend = std::max(maxBend, angleBetween(stick, x));
    worstGap = std::max(worstGap, anchorGap(MdtUniversalQuaConstraint(j)));
    MdtUniversalGetAxis(j, 0, a0);
    MdtUniversalGetAxis(j, 1, b1);
    worstDot = std::max(worstDot, std::fabs((double)MeVector3Dot(a0, b1)));
  }
  EXPECT_TRUE(finite);
  EXPECT_GT(maxBend, M_PI / 2);  // it did pass 90 degrees
  EXPECT_LT(worstGap, 5e-3);
  EXPECT_LT(worstDot, 5e-3);
}

TEST(Universal, TwistIsLocked) {
  // A torque about the stick (the axis orthogonal to both joint axes) is
  // resisted entirely.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 1, 0, 0);
  MdtUniversalID j = MdtUniversalCreate(w);
  MdtUniversalSetBodies(j, b, nullptr);
  MdtUniversalSetPosition(j, 0, 0, 0);
  MdtUniversalSetAxes(j, 0, 0, 0, 1, 0, 1, 0);  // body 0 axis z
  MdtUniversalSetAxes(j, 1, 0, 0, 1, 0, 1, 0);  // body 1 axis y (secondary)
  MdtUniversalEnable(j);
  for (int i = 0; i < 100; ++i) {
    MdtBodyAddTorque(b, 1, 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
  }
  MeVector3 omega;
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_LT(MeVector3Magnitude(omega), 1e-3);
  MeVector3 t;
  MdtUniversalGetTorque(j, 0, t);
  EXPECT_NEAR(t[0], -1, 1e-2);
}

TEST(ConeLimit, SoftConeSettlesAtTorqueOverStiffness) {
  // Ball joint at the body's centre, no gravity, torque T = 1 about z: the
  // x axis turns out until the soft cone (alpha = 0.5, k = 10) balances it
  // at alpha + T / k = 0.6 rad.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtBSJointID ball = MdtBSJointCreate(w);
  MdtBSJointSetBodies(ball, b, nullptr);
  MdtBSJointEnable(ball);
  MdtConeLimitID cone = MdtConeLimitCreate(w);
  MdtConeLimitSetBodies(cone, b, nullptr);
  MdtConeLimitSetConeHalfAngle(cone, (MeReal)0.5);
  MdtConeLimitSetStiffness(cone, 10);
  MdtConeLimitSetDamping(cone, 2);
  MdtConeLimitEnable(cone);
  for (int i = 0; i < 1000; ++i) {
    MdtBodyAddTorque(b, 0, 0, 1);
    MdtWorldStep(w, (MeReal)0.01);
  }
  EXPECT_NEAR(MdtConeLimitGetAngle(cone), 0.6, 0.6 * 0.02);
  EXPECT_NEAR(rotationAngle(b), 0.6, 0.6 * 0.02);
}

TEST(ConeLimit, DefaultConeDoesNothing) {
  World w;
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtConeLimitID cone = MdtConeLimitCreate(w);
  MdtConeLimitSetBodies(cone, b, nullptr);
  EXPECT_NEAR(MdtConeLimitGetConeHalfAngle(cone), M_PI, 1e-6);
  EXPECT_EQ(MdtConeLimitGetStiffness(cone), MEINFINITY);
  EXPECT_EQ(MdtConeLimitGetDamping(cone), MEINFINITY);
  MdtConeLimitEnable(cone);
  MdtBodySetAngularVelocity(b, 0, 0, 3);
  for (int i = 0; i < 200; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 omega;
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(omega[2], 3, 1e-5);  // spins through 6 rad unhindered
}
