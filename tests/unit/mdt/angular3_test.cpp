// Angular3 joint: orientation lock, Angular2 (rotation enabled), soft spring.
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

TEST(Angular3, LocksRelativeOrientationLeavesPositionFree) {
  // Two free unit-mass bodies (inertia 0.4 each) 2 m apart; torque and force
  // on body 0 only. They turn as one: angular acceleration T / 0.8 about the
  // torque's axis, while body 0 alone takes the force (a = F / m).
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID a = makeBody(w, 0, 0, 0);
  MdtBodyID b = makeBody(w, 2, 0, 0);
  MdtAngular3ID j = MdtAngular3Create(w);
  MdtAngular3SetBodies(j, a, b);
  MdtAngular3Enable(j);
  const MeVector3 T = {(MeReal)0.2, -(MeReal)0.3, (MeReal)0.4};
  const int n = 100;
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    MdtBodyAddTorque(a, T[0], T[1], T[2]);
    MdtBodyAddForce(a, 1, 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
    worst = std::max(worst, relativeAngle(a, b));
  }
  EXPECT_LT(worst, 0.01);
  MeVector3 wa, wb, va, vb;
  MdtBodyGetAngularVelocity(a, wa);
  MdtBodyGetAngularVelocity(b, wb);
  MdtBodyGetLinearVelocity(a, va);
  MdtBodyGetLinearVelocity(b, vb);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(wa[k], T[k] / 0.8, 0.01 * 0.5);
    EXPECT_NEAR(wb[k], T[k] / 0.8, 0.01 * 0.5);
  }
  EXPECT_NEAR(va[0], 1.0, 1e-5);
  EXPECT_NEAR(MeVector3Magnitude(vb), 0, 1e-5);
}

TEST(Angular3, TorqueAgainstTheWorldIsHeld) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtAngular3ID j = MdtAngular3Create(w);
  MdtAngular3SetBodies(j, b, nullptr);
  MdtAngular3Enable(j);
  for (int i = 0; i < 200; ++i) {
    MdtBodyAddTorque(b, 5, -3, 2);
    MdtWorldStep(w, (MeReal)0.01);
  }
  EXPECT_LT(rotationAngle(b), 0.01);
  MeVector3 t;
  MdtAngular3GetTorque(j, 0, t);
  EXPECT_NEAR(t[0], -5, 0.01);
  EXPECT_NEAR(t[1], 3, 0.01);
  EXPECT_NEAR(t[2], -2, 0.01);
}

TEST(Angular3, EnableRotationFreesThePrimaryAxis) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtAngular3ID j = MdtAngular3Create(w);
  MdtAngular3SetBodies(j, b, nullptr);
  MdtAngular3SetAxis(j, 0, 0, 1);
  EXPECT_FALSE(MdtAngular3RotationIsEnabled(j));
  MdtAngular3EnableRotation(j, TRUE);
  EXPECT_TRUE(MdtAngular3RotationIsEnabled(j));
  MdtAngular3Enable(j);
  for (int i = 0; i < 100; ++i) {
    MdtBodyAddTorque(b, 1, 1, 1);
    MdtWorldStep(w, (MeReal)0.01);
  }
  // About z: T t / I = 1 * 1 / 0.4 = 2.5 rad/s; x and y stay locked even
  // though the body has turned 1.25 rad about z.
  MeVector3 omega, z;
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(omega[2], 2.5, 2.5e-3);
  EXPECT_NEAR(omega[0], 0, 1e-3);
  EXPECT_NEAR(omega[1], 0, 1e-3);
  // Semi-implicit Euler: angle = 2.5 h^2 n (n + 1) / 2 = 1.2625 rad.
  EXPECT_NEAR(rotationAngle(b), 1.2625, 1e-3);
  bodyDirection(b, 0, 0, 1, z);
  EXPECT_NEAR(z[2], 1, 1e-4);
  // Locking again stops the spin about z where it is (no snapping back).
  const double before = rotationAngle(b);
  MdtAngular3EnableRotation(j, FALSE);
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.01);
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_LT(MeVector3Magnitude(omega), 1e-3);
  EXPECT_NEAR(rotationAngle(b), before, 1e-3);
}

TEST(Angular3, SoftSpringSettlesAtTorqueOverStiffness) {
  // k = 20 N m/rad, c = 4 N m s/rad, T = 2 N m about x: 0.1 rad.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtAngular3ID j = MdtAngular3Create(w);
  MdtAngular3SetBodies(j, b, nullptr);
  EXPECT_EQ(MdtAngular3GetStiffness(j), MEINFINITY);
  EXPECT_EQ(MdtAngular3GetDamping(j), MEINFINITY);
  MdtAngular3SetStiffness(j, 20);
  MdtAngular3SetDamping(j, 4);
  MdtAngular3Enable(j);
  for (int i = 0; i < 500; ++i) {
    MdtBodyAddTorque(b, 2, 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
  }
  EXPECT_NEAR(rotationAngle(b), 0.1, 0.1 * 0.05);
  MeVector3 x;
  bodyDirection(b, 0, 1, 0, x);
  EXPECT_NEAR(std::atan2((double)x[2], (double)x[1]), 0.1, 0.1 * 0.05);
}
