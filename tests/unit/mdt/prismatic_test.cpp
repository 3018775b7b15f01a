// Prismatic joint: free slide against g sin(theta) kinematics, rotation
// lock, hard stops, motor.
#include <algorithm>
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

namespace {

// A body on a prismatic joint to the world along a slope of `deg` degrees
// in the x-y plane, gravity -y.
struct Slope {
  World w;
  MdtBodyID b;
  MdtPrismaticID j;
  MeVector3 axis;
  explicit Slope(double deg) {
    MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    b = makeBody(w, 0, 0, 0);
    j = MdtPrismaticCreate(w);
    MdtPrismaticSetBodies(j, b, nullptr);
    const double t = deg * M_PI / 180;
    MdtPrismaticSetAxis(j, (MeReal)std::cos(t), (MeReal)std::sin(t), 0);
    MdtPrismaticEnable(j);
    MdtPrismaticGetAxis(j, axis);
  }
  // Slide of the body's origin along the axis from where it started.
  double slide() const {
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    return MeVector3Dot(x, axis);
  }
  double lateral() const {
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    const double s = MeVector3Dot(x, axis);
    MeVector3MultiplyAdd(x, -(MeReal)s, axis);
    return MeVector3Magnitude(x);
  }
};

}  // namespace

TEST(Prismatic, FreeSlideFollowsGSinTheta) {
  // Semi-implicit Euler with constant acceleration a: after n steps of h,
  // s = a h^2 n (n + 1) / 2, i.e. a t (t + h) / 2 with t = n h.
  Slope s(30);
  const MeReal h = (MeReal)0.01;
  const int n = 100;
  for (int i = 0; i < n; ++i) MdtWorldStep(s.w, h);
  const double t = n * (double)h;
  const double expected = -0.5 * kG * 0.5 * t * (t + (double)h);  // -2.477 m
  EXPECT_NEAR(s.slide(), expected, 1e-3 * std::fabs(expected));
  // Across the axis the rows give way by the world softness: the lateral
  // reaction (8.5 N) and its 2.5 m lever on the angular rows leave
  // eps F h^2 / gamma ~ 1e-4 rad of tilt, i.e. ~0.25 mm at the body.
  EXPECT_LT(s.lateral(), 1e-3);
  MeVector3 v;
  MdtBodyGetLinearVelocity(s.b, v);
  EXPECT_NEAR(MeVector3Dot(v, s.axis), -kG * 0.5 * t, 1e-3 * kG * 0.5 * t);
}

TEST(Prismatic, RotationStaysLockedUnderTorque) {
  Slope s(30);
  for (int i = 0; i < 200; ++i) {
    MdtBodyAddTorque(s.b, (MeReal)0.3, -(MeReal)0.5, (MeReal)0.7);
    MdtWorldStep(s.w, (MeReal)0.01);
  }
  // Unresisted, the torque would have turned the body ~4.5 rad.
  EXPECT_LT(rotationAngle(s.b), 1e-3);
  MeVector3 omega;
  MdtBodyGetAngularVelocity(s.b, omega);
  EXPECT_LT(MeVector3Magnitude(omega), 1e-3);
}

TEST(Prismatic, TwoBodiesStayOnTheirCommonAxis) {
  // Force across the axis on body 0 only. The pair (1 kg each) takes the
  // momentum F t together, turns as one (the force is off the pair's centre)
  // and body 1 stays on body 0's slide axis.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID a = makeBody(w, 0, 0, 0);
  MdtBodyID b = makeBody(w, 1, 0, 0);
  MdtPrismaticID j = MdtPrismaticCreate(w);
  MdtPrismaticSetBodies(j, a, b);
  MdtPrismaticSetAxis(j, 1, 0, 0);
  MdtPrismaticEnable(j);
  double worstAngle = 0, worstLateral = 0;
  for (int i = 0; i < 100; ++i) {
    MdtBodyAddForce(a, 0, 2, 0);
    MdtWorldStep(w, (MeReal)0.01);
    worstAngle = std::max(worstAngle, relativeAngle(a, b));
    MeVector3 xa, xb, axis, d;
    MdtBodyGetPosition(a, xa);
    MdtBodyGetPosition(b, xb);
    MdtPrismaticGetAxis(j, axis);
    MeVector3Subtract(d, xb, xa);
    MeVector3MultiplyAdd(d, -MeVector3Dot(d, axis), axis);
    worstLateral = std::max(worstLateral, (double)MeVector3Magnitude(d));
  }
  MeVector3 va, vb, wa, wb;
  MdtBodyGetLinearVelocity(a, va);
  MdtBodyGetLinearVelocity(b, vb);
  EXPECT_NEAR(va[1] + vb[1], 2.0, 1e-4);
  EXPECT_NEAR(va[0] + vb[0], 0.0, 1e-4);
  MdtBodyGetAngularVelocity(a, wa);
  MdtBodyGetAngularVelocity(b, wb);
  EXPECT_LT(wa[2], -0.5);  // it does turn (torque -1 N m about the pair's centre)
  EXPECT_NEAR(wa[2], wb[2], 1e-3);
  EXPECT_LT(worstAngle, 1e-3);
  EXPECT_LT(worstLateral, 1e-3);
}

TEST(Prismatic, HardStopsHold) {
  // Lower stop 0.5 m down the 30-degree slope: the body slides into it and
  // stays there. The stop row appears in the step after the stop is passed,
  // so the deepest overshoot is at most one step of travel at impact speed
  // sqrt(2 a d) = 2.21 m/s, i.e. 22 mm at h = 0.01; it is then removed.
  Slope s(30);
  MdtLimitID lim = MdtPrismaticGetLimit(s.j);
  lim->limit[0].restitution = 0;
  lim->limit[1].restitution = 0;
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(lim), -(MeReal)0.5);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(lim), (MeReal)0.4);
  MdtLimitActivateLimits(lim, TRUE);
  const MeReal h = (MeReal)0.01;
  double lowest = 0;
  for (int i = 0; i < 300; ++i) {
    MdtWorldStep(s.w, h);
    lowest = std::min(lowest, s.slide());
  }
  const double impact = std::sqrt(2 * kG * 0.5 * 0.5);
  EXPECT_GT(lowest, -0.5 - impact * (double)h - 1e-3);
  EXPECT_NEAR(s.slide(), -0.5, 2e-3);
  EXPECT_NEAR(MdtLimitGetPosition(lim), -0.5, 2e-3);
  // A motor pushing up the slope (20 N > m g sin(theta) = 4.9 N) drives it
  // to the upper stop, where it stays.
  MdtLimitSetLimitedForceMotor(lim, 1, 20);
  double highest = -1;
  for (int i = 0; i < 300; ++i) {
    MdtWorldStep(s.w, h);
    highest = std::max(highest, s.slide());
  }
  EXPECT_LT(highest, 0.4 + 1.0 * (double)h + 1e-3);
  EXPECT_NEAR(s.slide(), 0.4, 2e-3);
}

TEST(Prismatic, MotorReachesItsSpeed) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtPrismaticID j = MdtPrismaticCreate(w);
  MdtPrismaticSetBodies(j, b, nullptr);
  MdtPrismaticSetAxis(j, 1, 1, 1);
  MdtPrismaticEnable(j);
  MdtLimitSetLimitedForceMotor(MdtPrismaticGetLimit(j), (MeReal)0.7, 50);
  for (int i = 0; i < 50; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 v, axis;
  MdtBodyGetLinearVelocity(b, v);
  MdtPrismaticGetAxis(j, axis);
  EXPECT_NEAR(axis[0], 1 / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(MeVector3Dot(v, axis), 0.7, 1e-3);
  EXPECT_NEAR(MeVector3Magnitude(v), 0.7, 1e-3);  // no motion across the axis
  EXPECT_NEAR(MdtLimitGetVelocity(MdtPrismaticGetLimit(j)), 0.7, 1e-3);
}

TEST(Prismatic, MotorSaturatesAtForceLimit) {
  // 3 N on 1 kg: 3 m/s^2 until the 10 m/s target, so 0.3 m/s after 0.1 s.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtPrismaticID j = MdtPrismaticCreate(w);
  MdtPrismaticSetBodies(j, b, nullptr);
  MdtPrismaticSetAxis(j, 0, 0, 1);
  MdtPrismaticEnable(j);
  MdtLimitSetLimitedForceMotor(MdtPrismaticGetLimit(j), 10, 3);
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 v;
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_NEAR(v[2], 0.3, 1e-4);
}
