// Ball-and-socket and hinge joints against analytic results.
#include <cmath>

#include "mdt_test_support.h"

using namespace mdt_test;

namespace {

// A point-like bob (tiny inertia) of mass 1 hanging at distance L below a
// world anchor at the origin, released at angle theta0 in the x-y plane.
MdtBodyID makeBob(MdtWorldID w, MeReal L, MeReal theta0) {
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, L * std::sin(theta0), -L * std::cos(theta0), 0);
  MeMatrix3 I = {{1e-4f, 0, 0}, {0, 1e-4f, 0}, {0, 0, 1e-4f}};
  MdtBodySetInertiaTensor(b, I);
  MdtBodyEnable(b);
  return b;
}

// Period from the times of successive upward zero crossings of x.
double measurePeriod(MdtWorldID w, MdtBodyID b, MeReal h, int steps) {
  std::vector<double> crossings;
  MeVector3 x;
  MdtBodyGetPosition(b, x);
  double prev = x[0];
  for (int i = 1; i <= steps; ++i) {
    MdtWorldStep(w, h);
    MdtBodyGetPosition(b, x);
    if (prev < 0 && x[0] >= 0) {
      const double frac = prev / (prev - (double)x[0]);
      crossings.push_back(((i - 1) + frac) * (double)h);
    }
    prev = x[0];
  }
  if (crossings.size() < 2) return 0;
  return (crossings.back() - crossings.front()) / (double)(crossings.size() - 1);
}

}  // namespace

TEST(BSJoint, PendulumSmallAnglePeriod) {
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)9.81, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  const MeReal L = 1, h = (MeReal)1 / 240;
  MdtBodyID bob = makeBob(w, L, (MeReal)0.05);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, bob, nullptr);
  MdtBSJointSetPosition(j, 0, 0, 0);
  MdtBSJointEnable(j);
  const double T = measurePeriod(w, bob, h, 240 * 12);
  const double expected = 2 * M_PI * std::sqrt(1.0 / 9.81);
  EXPECT_NEAR(T, expected, 0.01 * expected);
  // The rod length stays L to within a millimetre.
  MeVector3 x;
  MdtBodyGetPosition(bob, x);
  EXPECT_NEAR(MeVector3Magnitude(x), 1.0, 1e-3);
}

TEST(BSJoint, ForceBalancesGravityAtRest) {
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)9.81, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetMass(b, 2);
  MdtBodySetPosition(b, 0, -1, 0);
  MdtBodyEnable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, b, nullptr);
  MdtBSJointSetPosition(j, 0, 0, 0);
  MdtBSJointEnable(j);
  for (int i = 0; i < 100; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 f;
  MdtBSJointGetForce(j, 0, f);
  EXPECT_NEAR(f[1], 2 * 9.81, 2 * 9.81 * 1e-3);
  EXPECT_NEAR(f[0], 0, 1e-3);
}

TEST(Hinge, DoorAnchorDriftUnderOneMillimetre) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  const MeReal doorSize[] = {(MeReal)0.8, (MeReal)2.0, (MeReal)0.04};
  MdtBodyID door = MdtBodyCreate(w);
  MdtBodySetPosition(door, 0, 0, -7);
  MdtBodySetMass(door, 2);
  MdtBodySetAngularVelocity(door, 0, 5, 0);
  MdtBodySetAngularVelocityDamping(door, (MeReal)0.2);
  MdtBodyEnable(door);
  MdtHingeID hinge = MdtHingeCreate(w);
  MdtHingeSetBodies(hinge, door, nullptr);
  MeVector3 p;
  MdtBodyGetPosition(door, p);
  MdtHingeSetPosition(hinge, p[0] - doorSize[0] / 2, p[1], p[2]);
  MdtHingeSetAxis(hinge, 0, 1, 0);
  MdtHingeEnable(hinge);
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    MdtWorldStep(w, (MeReal)0.01);
    worst = std::max(worst, anchorGap(MdtHingeQuaConstraint(hinge)));
  }
  EXPECT_LT(worst, 1e-3);
  // The door turned about the vertical axis only.
  MeVector3 omega;
  MdtBodyGetAngularVelocity(door, omega);
  EXPECT_NEAR(omega[0], 0, 1e-3);
  EXPECT_NEAR(omega[2], 0, 1e-3);
  EXPECT_GT(std::fabs(omega[1]), 0.1);
}

TEST(Hinge, MotorReachesDesiredSpeedWhenTorqueSuffices) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtHingeID hinge = MdtHingeCreate(w);
  MdtHingeSetBodies(hinge, b, nullptr);
  MdtHingeSetAxis(hinge, 0, 0, 1);
  MdtHingeEnable(hinge);
  MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(hinge), 3, 100);
  for (int i = 0; i < 50; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 omega;
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(omega[2], 3, 3e-3);
  EXPECT_NEAR(MdtHingeGetAngleRate(hinge), 3, 3e-3);
}

TEST(Hinge, MotorSaturatesAtPredictedSpeedAgainstDamping) {
  // Torque limit T against angular damping c: terminal speed T / c when the
  // desired speed is higher.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetAngularVelocityDamping(b, 2);
  MdtBodyEnable(b);
  MdtHingeID hinge = MdtHingeCreate(w);
  MdtHingeSetBodies(hinge, b, nullptr);
  MdtHingeSetAxis(hinge, 0, 0, 1);
  MdtHingeEnable(hinge);
  MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(hinge), 100, 5);
  for (int i = 0; i < 2000; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 omega;
  MdtBodyGetAngularVelocity(b, omega);
  EXPECT_NEAR(omega[2], 2.5, 2.5 * 0.01);
}
