// Issue 17: limits and motors write rows only while they act. A hard stop
// has a row only when the joint reaches it within the step, a soft stop only
// past it, a motor only when it is on (engine/mdt/rows.cpp, addStopRow and
// addLimitRows).
#include "mdt/mdt_test_support.h"
#include "support/spinner.h"

using namespace mdt_test;

namespace {

constexpr MeReal kH = (MeReal)0.01;
constexpr int kHingeRows = 5;  // the hinge alone: three linear, two angular

using karma_test::Spinner;

// A spinner (support/spinner.h) in a world that does not put it to sleep.
Spinner AwakeSpinner(MdtWorldID w, MeReal rate) {
  MdtWorldSetAutoDisable(w, FALSE);
  return Spinner(w, rate);
}

int stepRows(MdtWorldID w) {
  MdtWorldStep(w, kH);
  return MdtWorldGetPartitionRowCount(w, 0);
}

}  // namespace

TEST(LimitRows, AHardStopHasARowOnlyWhenReachedWithinTheStep) {
  // Spinning at 1 rad/s towards a hard stop at 0.5 rad with restitution 1:
  // a row exactly in the steps that start with angle + rate h >= 0.5 (the
  // stop within reach), none before the impact or after the rebound.
  World w;
  Spinner s = AwakeSpinner(w, 1);
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.limit), -(MeReal)0.5);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.limit), (MeReal)0.5);
  MdtLimitActivateLimits(s.limit, TRUE);
  int withRow = 0;
  for (int i = 0; i < 90; ++i) {
    const MeReal reach = MdtHingeGetAngle(s.hinge) + s.rate() * kH;
    const int rows = stepRows(w);
    if (std::fabs(reach - (MeReal)0.5) > (MeReal)1e-4) {
      EXPECT_EQ(rows, reach >= (MeReal)0.5 ? kHingeRows + 1 : kHingeRows) << "step " << i << " reach " << reach;
    }
    withRow += rows - kHingeRows;
  }
  EXPECT_GE(withRow, 1);
  EXPECT_LE(withRow, 2);
  EXPECT_LT(s.rate(), -(MeReal)0.9);  // it bounced
  EXPECT_EQ(stepRows(w), kHingeRows);
}

TEST(LimitRows, ASoftStopHasARowOnlyPastTheStop) {
  World w;
  Spinner s = AwakeSpinner(w, 1);
  MdtSingleLimitID up = MdtLimitGetUpperLimit(s.limit);
  MdtSingleLimitSetStop(up, (MeReal)0.3);
  MdtSingleLimitSetStiffness(up, 20);
  MdtSingleLimitSetDamping(up, 1);
  MdtLimitActivateLimits(s.limit, TRUE);
  int past = 0;
  for (int i = 0; i < 60; ++i) {
    const MeReal angle = MdtHingeGetAngle(s.hinge);
    const int rows = stepRows(w);
    if (std::fabs(angle - (MeReal)0.3) > (MeReal)1e-4) {
      EXPECT_EQ(rows, angle >= (MeReal)0.3 ? kHingeRows + 1 : kHingeRows) << "step " << i << " angle " << angle;
    }
    past += angle > (MeReal)0.3 ? 1 : 0;
  }
  EXPECT_GT(past, 5);  // it did go past and the spring acted
}

TEST(LimitRows, LimitsSwitchedOnButFarAwayCostNothing) {
  World w;
  Spinner s = AwakeSpinner(w, 0);
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.limit), -1);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.limit), 1);
  MdtLimitActivateLimits(s.limit, TRUE);
  EXPECT_EQ(stepRows(w), kHingeRows);
}

TEST(LimitRows, AMotorHasARowOnlyWhenOn) {
  World w;
  Spinner s = AwakeSpinner(w, 0);
  EXPECT_EQ(stepRows(w), kHingeRows);           // default: no motor
  MdtLimitSetLimitedForceMotor(s.limit, 2, 0);  // zero force: off
  EXPECT_EQ(stepRows(w), kHingeRows);
  MdtLimitSetLimitedForceMotor(s.limit, 2, 10);
  EXPECT_EQ(stepRows(w), kHingeRows + 1);
  MdtLimitActivateMotor(s.limit, FALSE);
  EXPECT_EQ(stepRows(w), kHingeRows);
  MdtLimitActivateMotor(s.limit, TRUE);
  EXPECT_EQ(stepRows(w), kHingeRows + 1);
  MdtLimitSetLimitedForceMotor(s.limit, 0, 10);  // a brake (desired speed 0) is on
  EXPECT_EQ(stepRows(w), kHingeRows + 1);
}

TEST(LimitRows, ACarWheelHingeMotorHasARowOnlyWhenOn) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID chassis = MdtBodyCreate(w), wheel = MdtBodyCreate(w);
  MdtBodySetPosition(wheel, 1, 0, 0);
  MdtBodyEnable(chassis);
  MdtBodyEnable(wheel);
  MdtCarWheelID j = MdtCarWheelCreate(w);
  MdtCarWheelSetBodies(j, chassis, wheel);
  MdtCarWheelSetPosition(j, 1, 0, 0);
  MdtCarWheelSetSteeringAndHingeAxes(j, 0, 1, 0, 1, 0, 0);
  MdtCarWheelEnable(j);
  const int off = stepRows(w);
  MdtCarWheelSetHingeLimitedForceMotor(j, 3, 0);
  EXPECT_EQ(stepRows(w), off);
  MdtCarWheelSetHingeLimitedForceMotor(j, 3, 50);
  EXPECT_EQ(stepRows(w), off + 1);
  MdtCarWheelSetHingeLimitedForceMotor(j, 3, 0);
  EXPECT_EQ(stepRows(w), off);
}
