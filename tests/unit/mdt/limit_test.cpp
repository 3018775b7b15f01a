// Hinge limits and motors: hard stops with restitution, soft stops, the
// limit API.
#include <cmath>

#include "mdt_test_support.h"
#include "support/spinner.h"

using namespace mdt_test;

namespace {

using karma_test::Spinner;

}  // namespace

TEST(Limit, HardStopReboundsWithRestitution) {
  for (const MeReal e : {(MeReal)0, (MeReal)1}) {
    World w;
    MdtWorldSetAutoDisable(w, FALSE);
    Spinner s(w, 2);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.limit), -(MeReal)0.5);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.limit), (MeReal)0.5);
    s.limit->limit[0].restitution = e;  // the guide writes the member directly
    s.limit->limit[1].restitution = e;
    MdtLimitActivateLimits(s.limit, TRUE);
    double maxAngle = 0;
    for (int i = 0; i < 40; ++i) {  // 0.4 s: reaches the stop at 0.25 s
      MdtWorldStep(w, (MeReal)0.01);
      maxAngle = std::max(maxAngle, (double)MdtHingeGetAngle(s.hinge));
    }
    MeVector3 omega;
    MdtBodyGetAngularVelocity(s.body, omega);
    EXPECT_NEAR(omega[2], -2 * e, 0.02 * 2) << "e " << e;
    EXPECT_LT(maxAngle, 0.5 + 0.03) << "e " << e;
  }
}

TEST(Limit, SoftStopSettlesBeyondByTorqueOverStiffness) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  Spinner s(w, 0);
  MdtBodySetAngularVelocityDamping(s.body, (MeReal)0.5);
  MdtSingleLimitID up = MdtLimitGetUpperLimit(s.limit);
  MdtSingleLimitSetStop(up, (MeReal)0.3);
  MdtSingleLimitSetStiffness(up, 50);
  MdtSingleLimitSetDamping(up, 5);
  MdtLimitSetStiffnessThreshold(s.limit, 100);  // 50 <= 100: soft
  MdtLimitActivateLimits(s.limit, TRUE);
  MdtLimitSetLimitedForceMotor(s.limit, 10, 2);  // pushes up with 2 N m
  for (int i = 0; i < 1000; ++i) MdtWorldStep(w, (MeReal)0.01);
  const double beyond = MdtHingeGetAngle(s.hinge) - 0.3;
  EXPECT_NEAR(beyond, 2.0 / 50, 0.05 * 2.0 / 50);
}

TEST(Limit, MultiTurnStopBeyondPi) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  Spinner s(w, 0);
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.limit), -10);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.limit), (MeReal)(3 * ME_PI));
  MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(s.limit), 0);
  MdtLimitActivateLimits(s.limit, TRUE);
  MdtLimitSetLimitedForceMotor(s.limit, 4, 100);
  for (int i = 0; i < 500; ++i) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_NEAR(MdtHingeGetAngle(s.hinge), 3 * M_PI, 0.03);
  EXPECT_NEAR(MdtLimitGetPosition(s.limit), 3 * M_PI, 0.03);
}

TEST(Limit, DefaultsAndValidation) {
  World w;
  MdtHingeID h = MdtHingeCreate(w);
  MdtLimitID l = MdtHingeGetLimit(h);
  EXPECT_FALSE(MdtLimitIsActive(l));
  EXPECT_FALSE(MdtLimitIsMotorized(l));
  EXPECT_FALSE(MdtLimitPositionIsCalculated(l));
  EXPECT_EQ(MdtLimitGetStiffnessThreshold(l), MEINFINITY);
  EXPECT_EQ(MdtSingleLimitGetRestitution(MdtLimitGetLowerLimit(l)), 1);
  EXPECT_EQ(MdtSingleLimitGetStiffness(MdtLimitGetLowerLimit(l)), MEINFINITY);
  EXPECT_EQ(MdtSingleLimitGetDamping(MdtLimitGetLowerLimit(l)), 0);
  MdtLimitSetLimitedForceMotor(l, 1, 2);
  EXPECT_TRUE(MdtLimitIsMotorized(l));
  EXPECT_TRUE(MdtLimitPositionIsCalculated(l));
  MdtLimitCalculatePosition(l, FALSE);  // cannot clear while motorised
  EXPECT_TRUE(MdtLimitPositionIsCalculated(l));
  MdtLimitSetLimitedForceMotor(l, 1, 0);
  EXPECT_FALSE(MdtLimitIsMotorized(l));
  WarningCapture cap;
  MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(l), (MeReal)1.5);
  MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(l), -1);
  MdtLimitSetLimitedForceMotor(l, 1, -1);
  EXPECT_EQ(cap.count(), 3u);
  // A lower stop above the upper one drags the upper along.
  MdtSingleLimit sl = {2, MEINFINITY, 0, 1};
  MdtLimitSetLowerLimit(l, &sl);
  EXPECT_EQ(MdtSingleLimitGetStop(MdtLimitGetUpperLimit(l)), 2);
}

TEST(Limit, ControllerDrivesToPosition) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  Spinner s(w, 0);
  for (int i = 0; i < 300; ++i) {
    MdtLimitController(s.limit, (MeReal)0.7, (MeReal)0.2, 2, 50);
    MdtWorldStep(w, (MeReal)0.01);
  }
  EXPECT_NEAR(MdtHingeGetAngle(s.hinge), 0.7, 0.01);
}
