// steering_sign_test.cpp: the guide's QuadBike steering controller (PASTE_12)
// and its handlebar controller (PASTE_13), exactly as printed, on a chassis
// held still: the wheel settles at the commanded turn instead of turning round
// without end, and the wheel and the bars turn the same way (issue 19,
// item 1; MdtCarWheel.h explains the signs).
#include <gtest/gtest.h>

#include <cmath>

#include "Mdt.h"

namespace {

// The guide's controller settings as the tutorial uses them (vehicle.c):
// full lock `width` rad, 5 rad/s per radian, the rate clipped by pgap.
constexpr MeReal kWidth = (MeReal)0.5, kMaxSpeed = 5, kPgap = (MeReal)0.4, kMaxForce = 500;

MeReal clip(MeReal x, MeReal lo, MeReal hi) { return x < lo ? lo : (x > hi ? hi : x); }

// y up: a 100 kg chassis fixed in place (world-pinned by a zero-offset
// ball joint and an Angular3), a wheel 0.4 below on a car wheel (steering y,
// hinge z), and handlebars above on a y hinge, chassis first as in PASTE_09.
struct Bike {
  MdtWorldID w = MdtWorldCreate(4, 8, 1, 1);
  MdtBodyID chassis = MdtBodyCreate(w), wheel = MdtBodyCreate(w), bars = MdtBodyCreate(w);
  MdtCarWheelID wheelJoint = MdtCarWheelCreate(w);
  MdtHingeID barJoint = MdtHingeCreate(w);
  Bike() {
    MdtWorldSetAutoDisable(w, 0);
    for (MdtBodyID b : {chassis, wheel, bars}) MdtBodyEnable(b);
    MdtBodySetMass(chassis, 100);
    MdtBodySetPosition(wheel, 0, -(MeReal)0.4, 0);
    MdtBodySetPosition(bars, 0, (MeReal)0.5, 0);
    MdtBSJointID pin = MdtBSJointCreate(w);
    MdtBSJointSetBodies(pin, chassis, nullptr);
    MdtBSJointEnable(pin);
    MdtAngular3ID hold = MdtAngular3Create(w);
    MdtAngular3SetBodies(hold, chassis, nullptr);
    MdtAngular3Enable(hold);
    MdtCarWheelSetBodies(wheelJoint, chassis, wheel);
    MdtCarWheelSetPosition(wheelJoint, 0, -(MeReal)0.4, 0);
    MdtCarWheelSetSteeringAndHingeAxes(wheelJoint, 0, 1, 0, 0, 0, 1);
    MdtCarWheelEnable(wheelJoint);
    MdtHingeSetBodies(barJoint, chassis, bars);
    MdtHingeSetAxis(barJoint, 0, 1, 0);
    MdtHingeSetPosition(barJoint, 0, (MeReal)0.5, 0);
    MdtHingeEnable(barJoint);
  }
  ~Bike() { MdtWorldDestroy(w); }
  // One step of PASTE_12 and PASTE_13 with the given steering input.
  void step(MeReal steeringInput) {
    MeReal theta, desired_vel;
    theta = MdtCarWheelGetSteeringAngle(wheelJoint);
    desired_vel = steeringInput * kWidth + theta;
    desired_vel = clip(desired_vel, -kPgap, kPgap);
    MdtCarWheelSetSteeringLimitedForceMotor(wheelJoint, kMaxSpeed * desired_vel, kMaxForce);
    MdtLimitController(MdtHingeGetLimit(barJoint), -steeringInput * kWidth, kPgap, kMaxSpeed, kMaxForce);
    MdtWorldStep(w, (MeReal)1 / 60);
  }
  // The turn of a body's x axis about world y (positive: from +x towards -z).
  static MeReal yaw(MdtBodyID b) {
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
    return std::atan2(-tm[0][2], tm[0][0]);
  }
};

}  // namespace

TEST(GuideSteering, PasteTwelveSettlesAtTheCommandedTurn) {
  for (MeReal input : {(MeReal)1, (MeReal)-0.4}) {
    Bike bike;
    MeReal maxAbs = 0;
    for (int i = 0; i < 120; ++i) {  // 2 s
      bike.step(input);
      maxAbs = std::fmax(maxAbs, std::fabs(MdtCarWheelGetSteeringAngle(bike.wheelJoint)));
    }
    // The controller's fixed point: input * width + angle = 0.
    EXPECT_NEAR(MdtCarWheelGetSteeringAngle(bike.wheelJoint), -input * kWidth, 2e-3);
    EXPECT_LT(maxAbs, std::fabs(input * kWidth) + (MeReal)0.02);  // no overshoot past lock
    // The wheel is turned +input * width about y (left for positive input),
    // the handlebars the same way.
    EXPECT_NEAR(Bike::yaw(bike.wheel), input * kWidth, 5e-3);
    EXPECT_NEAR(Bike::yaw(bike.bars), input * kWidth, 5e-3);
    EXPECT_NEAR(MdtHingeGetAngle(bike.barJoint), -input * kWidth, 5e-3);
  }
}

TEST(GuideSteering, AngleRateIsTheDerivativeOfTheAngle) {
  Bike bike;
  bike.step(1);
  const MeReal a0 = MdtCarWheelGetSteeringAngle(bike.wheelJoint);
  bike.step(1);
  const MeReal a1 = MdtCarWheelGetSteeringAngle(bike.wheelJoint);
  const MeReal rate = MdtCarWheelGetSteeringAngleRate(bike.wheelJoint);
  EXPECT_LT(rate, 0);  // the wheel turns positively, the reported angle falls
  EXPECT_NEAR((a1 - a0) * 60, rate, 0.05 * std::fabs(rate));
}
