// The common constraint API on CarWheel, Spring, Spring6, RPROJoint and
// Skeletal: names, casts, life cycle, user data, sort keys, world joins,
// Reset, and a wrongly typed handle.
#include <cstring>

#include "joints_b_support.h"

using namespace mdt_test;

TEST(JointsBCommon, TypeNamesAreRegistered) {
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeCarWheel), "CarWheel");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeSpring), "Spring");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeSpring6), "Spring6");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeRPROJoint), "RPROJoint");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeSkeletal), "Skeletal");
}

TEST(JointsBCommon, LifeCycleUserDataSortKeysAndForces) {
  World w(8, 1, 1, 16);
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtBodyID c = makeBody(w, 0, 1, 0);  // a second body for the wheel
  const MdtConstraintID all[5] = {
      MdtCarWheelQuaConstraint(MdtCarWheelCreate(w)), MdtSpringQuaConstraint(MdtSpringCreate(w)),
      MdtSpring6QuaConstraint(MdtSpring6Create(w)), MdtRPROJointQuaConstraint(MdtRPROJointCreate(w)),
      MdtSkeletalQuaConstraint(MdtSkeletalCreate(w))};
  int tag[5];
  for (int i = 0; i < 5; ++i) {
    ASSERT_NE(all[i], nullptr);
    EXPECT_FALSE(MdtConstraintIsEnabled(all[i]));
    MdtConstraintSetBodies(all[i], i == 0 ? c : b, i == 0 ? b : nullptr);  // NULL: the world
    EXPECT_EQ(MdtConstraintGetBody(all[i], 1), i == 0 ? b : nullptr);
    MdtConstraintSetUserData(all[i], &tag[i]);
    MdtConstraintSetSortKey(all[i], 10 - i);
    MdtConstraintEnable(all[i]);
    EXPECT_TRUE(MdtConstraintIsEnabled(all[i]));
  }
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 5u);
  for (int s = 0; s < 20; ++s) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_TRUE(bodyFinite(b));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(MdtConstraintGetUserData(all[i]), &tag[i]);
    EXPECT_EQ(MdtConstraintGetSortKey(all[i]), 10 - i);
    EXPECT_EQ(MdtConstraintGetWorld(all[i]), w.id);
    MeVector3 f;
    MdtConstraintGetForce(all[i], 0, f);
    EXPECT_TRUE(MeVector3AllFinite(f));
    MdtConstraintDisable(all[i]);
    EXPECT_FALSE(MdtConstraintIsEnabled(all[i]));
    MdtConstraintDestroy(all[i]);
  }
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 0u);
}

TEST(JointsBCommon, ResetKeepsTheBodiesAndRestoresDefaults) {
  World w;
  MdtBodyID a = makeBody(w, 0, 0, 0), b = makeBody(w, 0, -2, 0);
  MdtSpringID s = MdtSpringCreate(w);
  MdtSpringSetBodies(s, a, b);
  EXPECT_NEAR(MdtSpringGetNaturalLength(s), 2, 1e-6);  // each body's own origin
  MdtSpringSetNaturalLength(s, 5);
  MdtSpringSetStiffness(s, 99);
  MdtSpringReset(s);
  EXPECT_EQ(MdtSpringGetBody(s, 1), b);
  EXPECT_NEAR(MdtSpringGetNaturalLength(s), 2, 1e-6);
  EXPECT_EQ(MdtSpringGetStiffness(s), 10);

  MdtSkeletalID k = MdtSkeletalCreate(w);
  MdtSkeletalSetBodies(k, a, b);
  MdtSkeletalSetTwistLimitAngle(k, 1);
  MdtSkeletalReset(k);
  EXPECT_NEAR(MdtSkeletalGetTwistLimitAngle(k), M_PI / 4, 1e-6);
  EXPECT_EQ(MdtSkeletalGetBody(k, 0), a);

  MdtCarWheelID c = MdtCarWheelCreate(w);
  MdtCarWheelSetBodies(c, a, b);
  MdtCarWheelSetSteeringLock(c, TRUE);
  MdtCarWheelReset(c);
  EXPECT_FALSE(MdtCarWheelIsSteeringLocked(c));
}

TEST(JointsBCommon, WronglyTypedHandlesAndNullsWarn) {
  WarningCapture warnings;
  World w;
  MdtBodyID a = makeBody(w, 0, 0, 0);
  MdtHingeID h = MdtHingeCreate(w);
  MdtHingeSetBodies(h, a, nullptr);
  const MdtConstraintID hc = MdtHingeQuaConstraint(h);
  EXPECT_EQ(MdtConstraintDCastSpring(hc), nullptr);
  EXPECT_EQ(MdtConstraintDCastSpring6(hc), nullptr);
  EXPECT_EQ(MdtConstraintDCastRPROJoint(hc), nullptr);
  EXPECT_EQ(MdtConstraintDCastSkeletal(hc), nullptr);
  EXPECT_EQ(MdtConstraintDCastCarWheel(hc), nullptr);
  MdtSpringSetStiffness((MdtSpringID)(void *)h, 1);
  EXPECT_NE(warnings.last().find("MdtSpringSetStiffness: the constraint is of type Hinge"), std::string::npos);
  MdtSkeletalReset((MdtSkeletalID)(void *)h);
  EXPECT_NE(warnings.last().find("MdtSkeletalReset"), std::string::npos);
  MdtRPROJointSetLinearStrength(nullptr, 1, 1, 1);
  EXPECT_NE(warnings.last().find("constraint is NULL"), std::string::npos);
  EXPECT_EQ(MdtCarWheelCreate(nullptr), nullptr);
  EXPECT_NE(warnings.last().find("MdtCarWheelCreate"), std::string::npos);
  MdtSpringSetBodies(MdtSpringCreate(w), nullptr, a);
  EXPECT_NE(warnings.last().find("body0 is NULL"), std::string::npos);
}
