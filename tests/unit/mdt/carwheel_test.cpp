// CarWheel: defaults, static sag, stops, steering lock, motors, getters and
// bad input (the fast-spinning wheel is in carwheel_spin_test.cpp).
#include <algorithm>
#include <cmath>

#include "joints_b_support.h"

using namespace mdt_test;

namespace {

// A chassis at the origin and a wheel 0.4 below it, z up, steering axis z,
// hinge axis y.
struct Rig {
  World w;
  MdtBodyID chassis, wheel;
  MdtCarWheelID j;
  explicit Rig(MeReal chassisMass = 100) {
    MdtWorldSetGravity(w, 0, 0, -(MeReal)kG);
    MdtWorldSetAutoDisable(w, FALSE);
    chassis = makeBody(w, 0, 0, 0);
    MdtBodySetMass(chassis, chassisMass);
    setDiagonalInertia(chassis, chassisMass, chassisMass, chassisMass);
    wheel = makeBody(w, 0, 0, -(MeReal)0.4);
    MdtBodySetMass(wheel, 10);
    setDiagonalInertia(wheel, (MeReal)0.225, (MeReal)0.45, (MeReal)0.225);
    j = MdtCarWheelCreate(w);
    MdtCarWheelSetBodies(j, chassis, wheel);
    MdtCarWheelSetPosition(j, 0, 0, -(MeReal)0.4);
    MdtCarWheelSetSteeringAndHingeAxes(j, 0, 0, 1, 0, 1, 0);
  }
  void run(int steps, MeReal h = (MeReal)0.01) {
    for (int i = 0; i < steps; ++i) MdtWorldStep(w, h);
  }
};

}  // namespace

TEST(CarWheel, DefaultsFollowAppendixA) {
  Rig r;
  MdtCarWheelID j = r.j;
  EXPECT_FALSE(MdtCarWheelIsSteeringLocked(j));
  EXPECT_EQ(MdtCarWheelGetSteeringMotorMaxForce(j), (MeReal)1e9);
  EXPECT_EQ(MdtCarWheelGetSteeringMotorDesiredVelocity(j), 0);
  EXPECT_EQ(MdtCarWheelGetHingeMotorMaxForce(j), 0);
  EXPECT_EQ(MdtCarWheelGetSuspensionKp(j), 0);
  EXPECT_EQ(MdtCarWheelGetSuspensionKd(j), 0);
  EXPECT_EQ(MdtCarWheelGetSuspensionLimitSoftness(j), 0);
  EXPECT_EQ(MdtCarWheelGetSuspensionLowLimit(j), (MeReal)-1e9);
  EXPECT_EQ(MdtCarWheelGetSuspensionHighLimit(j), (MeReal)1e9);
  EXPECT_EQ(MdtCarWheelGetSuspensionReference(j), 0);
  MeVector3 s, h;
  MdtCarWheelGetSteeringAxis(j, s);
  MdtCarWheelGetHingeAxis(j, h);
  EXPECT_NEAR(s[2], 1, 1e-6);
  EXPECT_NEAR(h[1], 1, 1e-6);
  EXPECT_NEAR(MdtCarWheelGetSteeringAngle(j), 0, 1e-6);
  EXPECT_NEAR(MdtCarWheelGetHingeAngle(j), 0, 1e-6);
  EXPECT_NEAR(MdtCarWheelGetSuspensionHeight(j), 0, 1e-6);
  EXPECT_EQ(MdtConstraintGetType(MdtCarWheelQuaConstraint(j)), MdtConstraintTypeCarWheel);
  EXPECT_EQ(MdtConstraintDCastCarWheel(MdtCarWheelQuaConstraint(j)), j);
}

TEST(CarWheel, StaticSagIsLoadOverKp) {
  // The wheel is pinned to the world; the chassis (100 kg, orientation held)
  // hangs on the suspension: sag = M g / Kp = 0.0196 m.
  Rig r;
  MdtAngular3ID hold = MdtAngular3Create(r.w);
  MdtAngular3SetBodies(hold, r.chassis, nullptr);
  MdtAngular3Enable(hold);
  pinToWorld(r.w, r.wheel);
  const MeReal kp = 50000, kd = 3000;
  MdtCarWheelSetSuspension(r.j, kp, kd, 0, -(MeReal)0.2, (MeReal)0.2, 0);
  MdtCarWheelSetSteeringLock(r.j, TRUE);
  MdtCarWheelEnable(r.j);
  r.run(300);
  const double sag = MdtCarWheelGetSuspensionHeight(r.j);
  const double expected = 100 * kG / kp;
  RecordProperty("sag_m", std::to_string(sag));
  EXPECT_NEAR(sag, expected, 0.05 * expected);
  EXPECT_NEAR(sag, expected, 0.01 * expected);  // it is in fact within 1%
  // The chassis has dropped by the sag relative to the wheel (the wheel's
  // own pin gives way by the world softness, eps F h^2 / gamma ~ 5 mm).
  MeVector3 xc, xw;
  MdtBodyGetPosition(r.chassis, xc);
  MdtBodyGetPosition(r.wheel, xw);
  EXPECT_NEAR(xw[2] - xc[2], -(0.4 - expected), 0.05 * expected);
}

TEST(CarWheel, SuspensionStopsHoldTheLoad) {
  // Kp too weak for the load: the chassis settles on the low-limit stop
  // (height may not exceed the high limit 0.05: the wheel cannot rise further).
  Rig r;
  MdtAngular3ID hold = MdtAngular3Create(r.w);
  MdtAngular3SetBodies(hold, r.chassis, nullptr);
  MdtAngular3Enable(hold);
  pinToWorld(r.w, r.wheel);
  MdtCarWheelSetSuspension(r.j, 1000, 500, 0, -(MeReal)0.05, (MeReal)0.05, 0);
  MdtCarWheelEnable(r.j);
  r.run(300);
  // The stop carries M g - Kp 0.05 = 931 N; a rigid row gives way by
  // eps F h^2 / gamma at rest (4.7 mm with the defaults).
  const double f = 100 * kG - 1000 * 0.05;
  const double give = MdtWorldGetEpsilon(r.w) * f * 1e-4 / MdtWorldGetGamma(r.w);
  EXPECT_NEAR(MdtCarWheelGetSuspensionHeight(r.j), 0.05 + give, 0.1 * give);
  // With limit softness 1e-4 (a hundredth of the world's) it gives way
  // about 100 times less.
  MdtCarWheelSetSuspension(r.j, 1000, 500, (MeReal)1e-4, -(MeReal)0.05, (MeReal)0.05, 0);
  r.run(300);
  EXPECT_NEAR(MdtCarWheelGetSuspensionHeight(r.j), 0.05 + give / 100, 0.2 * give / 100);
}

TEST(CarWheel, SteeringLockHoldsAgainstTorque) {
  Rig r;
  pinToWorld(r.w, r.chassis);
  MdtCarWheelSetSuspension(r.j, 50000, 3000, 0, -(MeReal)0.1, (MeReal)0.1, 0);
  MdtCarWheelSetSteeringLimitedForceMotor(r.j, 0, 0);  // no motor: only the lock
  MdtCarWheelSetSteeringLock(r.j, TRUE);
  EXPECT_TRUE(MdtCarWheelIsSteeringLocked(r.j));
  MdtCarWheelEnable(r.j);
  for (int i = 0; i < 200; ++i) {
    MdtBodyAddTorque(r.wheel, 0, 0, 20);  // about the steering axis
    MdtWorldStep(r.w, (MeReal)0.01);
  }
  EXPECT_LT(std::fabs(MdtCarWheelGetSteeringAngle(r.j)), 1e-3);
  EXPECT_LT(std::fabs(MdtCarWheelGetSteeringAngleRate(r.j)), 1e-3);
  // Unlocked without a motor the same torque turns the wheel.
  MdtCarWheelSetSteeringLock(r.j, FALSE);
  for (int i = 0; i < 20; ++i) {
    MdtBodyAddTorque(r.wheel, 0, 0, 2);
    MdtWorldStep(r.w, (MeReal)0.01);
  }
  // The wheel turns positively about z; the reported angle is the chassis
  // relative to the wheel (MdtCarWheel.h), so it is negative.
  EXPECT_LT(MdtCarWheelGetSteeringAngle(r.j), -0.05);
  EXPECT_LT(MdtCarWheelGetSteeringAngleRate(r.j), -1);
}

TEST(CarWheel, SteeringMotorReachesItsSpeedAndSaturates) {
  Rig r;
  pinToWorld(r.w, r.chassis);
  MdtCarWheelSetSuspension(r.j, 50000, 3000, 0, -(MeReal)0.1, (MeReal)0.1, 0);
  MdtCarWheelSetSteeringLimitedForceMotor(r.j, (MeReal)0.5, 100);
  MdtCarWheelEnable(r.j);
  r.run(50);
  // The motor drives the wheel relative to the chassis; the angle and its
  // rate read the other way round (MdtCarWheel.h).
  EXPECT_NEAR(MdtCarWheelGetSteeringAngleRate(r.j), -0.5, 1e-3);
  EXPECT_NEAR(MdtCarWheelGetSteeringAngle(r.j), -0.25, 0.02);
  EXPECT_EQ(MdtCarWheelGetSteeringMotorDesiredVelocity(r.j), (MeReal)0.5);
  EXPECT_EQ(MdtCarWheelGetSteeringMotorMaxForce(r.j), 100);
}

TEST(CarWheel, HingeMotorReachesItsSpeedAndSaturates) {
  Rig r;
  pinToWorld(r.w, r.chassis);
  MdtCarWheelSetSuspension(r.j, 50000, 3000, 0, -(MeReal)0.1, (MeReal)0.1, 0);
  MdtCarWheelSetSteeringLock(r.j, TRUE);
  MdtCarWheelSetHingeLimitedForceMotor(r.j, 10, 5);
  MdtCarWheelEnable(r.j);
  // Unopposed, 5 N m on 0.45 kg m^2 reaches 10 rad/s in 0.9 s.
  r.run(150);
  EXPECT_NEAR(MdtCarWheelGetHingeAngleRate(r.j), 10, 1e-2);
  const double angle = MdtCarWheelGetHingeAngle(r.j);
  EXPECT_GE(angle, 0);
  EXPECT_LT(angle, 2 * M_PI);
  // Against 8 N m the motor (5 N m) gives way: the wheel accelerates
  // backwards at (8 - 5) / 0.45 = 6.67 rad/s^2.
  const double before = MdtCarWheelGetHingeAngleRate(r.j);
  for (int i = 0; i < 30; ++i) {
    MdtBodyAddTorque(r.wheel, 0, -8, 0);
    MdtWorldStep(r.w, (MeReal)0.01);
  }
  const double accel = (MdtCarWheelGetHingeAngleRate(r.j) - before) / 0.3;
  EXPECT_NEAR(accel, -3.0 / 0.45, 0.05 * 3.0 / 0.45);
}

TEST(CarWheel, HingeAngleIsTheWheelTurnInZeroToTwoPi) {
  Rig r;
  pinToWorld(r.w, r.chassis);
  MdtCarWheelSetSteeringLock(r.j, TRUE);
  MdtCarWheelSetSuspension(r.j, 50000, 3000, 0, -(MeReal)0.1, (MeReal)0.1, 0);
  MdtCarWheelSetHingeLimitedForceMotor(r.j, -1, 1e4);  // negative: the angle wraps below 0
  MdtCarWheelEnable(r.j);
  r.run(50);  // 0.5 rad backwards
  EXPECT_NEAR(MdtCarWheelGetHingeAngle(r.j), 2 * M_PI - 0.5, 0.02);
  EXPECT_NEAR(MdtCarWheelGetHingeAngleRate(r.j), -1, 1e-3);
}

TEST(CarWheel, BadInputIsRejectedWithAWarning) {
  WarningCapture warnings;
  Rig r;
  MdtCarWheelSetSteeringAndHingeAxes(r.j, 0, 0, 1, 0, 0, 1);  // parallel
  EXPECT_NE(warnings.last().find("MdtCarWheelSetSteeringAndHingeAxes"), std::string::npos);
  MdtCarWheelSetSteeringAndHingeAxes(r.j, 0, 0, 0, 0, 1, 0);  // zero
  EXPECT_NE(warnings.last().find("zero"), std::string::npos);
  MdtCarWheelSetSuspension(r.j, -1, 0, 0, -1, 1, 0);
  EXPECT_NE(warnings.last().find("MdtCarWheelSetSuspension"), std::string::npos);
  EXPECT_EQ(MdtCarWheelGetSuspensionKp(r.j), 0);
  MdtCarWheelSetSuspension(r.j, NAN, 0, 0, -1, 1, 0);
  EXPECT_EQ(MdtCarWheelGetSuspensionKp(r.j), 0);
  MdtCarWheelSetHingeLimitedForceMotor(r.j, 1, -5);
  EXPECT_EQ(MdtCarWheelGetHingeMotorMaxForce(r.j), 0);
  const size_t before = warnings.count();
  EXPECT_EQ(MdtCarWheelGetHingeAngle(nullptr), 0);
  EXPECT_EQ(warnings.count(), before + 1);
  MdtHingeID hinge = MdtHingeCreate(r.w);
  EXPECT_EQ(MdtConstraintDCastCarWheel(MdtHingeQuaConstraint(hinge)), nullptr);
  MdtCarWheelSetSteeringLock((MdtCarWheelID)(void *)hinge, TRUE);
  EXPECT_NE(warnings.last().find("where CarWheel was expected"), std::string::npos);
  MeVector3 s, h;
  MdtCarWheelGetSteeringAxis(r.j, s);
  MdtCarWheelGetHingeAxis(r.j, h);
  EXPECT_NEAR(s[2], 1, 1e-6);  // unchanged by the rejected calls
  EXPECT_NEAR(h[1], 1, 1e-6);
}
