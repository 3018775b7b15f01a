// Bad input to constraints and the step: a clear message, a defined outcome,
// the world keeps stepping, never a crash.
#include <cmath>

#include "mdt_test_support.h"

using namespace mdt_test;

// Issue 15: a full constraint pool grows (constraint_slots.cpp) instead of
// refusing, and says so once; nothing asked for is lost.
TEST(BadInput, ConstraintPoolExhaustedGrowsWithOneWarning) {
  World w(4, 1, 1, 2);
  WarningCapture cap;
  EXPECT_NE(MdtBSJointCreate(w), nullptr);
  EXPECT_NE(MdtHingeCreate(w), nullptr);
  EXPECT_EQ(cap.count(), 0u);
  EXPECT_NE(MdtContactCreate(w), nullptr);
  EXPECT_NE(MdtBSJointCreate(w), nullptr);
  EXPECT_EQ(cap.count(), 1u);  // the growth is reported once
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 4u);
  EXPECT_EQ(MdtWorldGetMaxConstraints(w), 2u);  // the size it was created with
}

TEST(BadInput, BodiesOfAJointChangeOnlyWhileDisabled) {
  World w;
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w), c = MdtBodyCreate(w);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointEnable(j);
  WarningCapture cap;
  MdtBSJointSetBodies(j, a, c);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_NE(cap.last().find("disable"), std::string::npos);
  EXPECT_EQ(MdtBSJointGetBody(j, 1), b);
  MdtBSJointDisable(j);
  MdtBSJointSetBodies(j, a, c);
  EXPECT_EQ(MdtBSJointGetBody(j, 1), c);
  MdtBSJointSetBodies(j, nullptr, c);  // body0 may not be the world
  MdtBSJointSetBodies(j, a, a);        // nor the same body twice
  EXPECT_EQ(cap.count(), 3u);
  World other;
  MdtBodyID stranger = MdtBodyCreate(other);
  MdtBSJointSetBodies(j, a, stranger);
  EXPECT_EQ(cap.count(), 4u);
  EXPECT_EQ(MdtBSJointGetBody(j, 5), nullptr);
  EXPECT_EQ(cap.count(), 5u);
}

TEST(BadInput, NonFiniteAndDegenerateGeometryIsRejected) {
  World w;
  MdtBodyID a = MdtBodyCreate(w);
  MdtHingeID h = MdtHingeCreate(w);
  MdtHingeSetBodies(h, a, nullptr);
  MdtHingeSetAxis(h, 0, 0, 1);
  WarningCapture cap;
  MdtHingeSetAxis(h, 0, 0, 0);
  MdtHingeSetAxis(h, NAN, 0, 1);
  MdtHingeSetPosition(h, INFINITY, 0, 0);
  MdtConstraintSetAxes(MdtHingeQuaConstraint(h), 1, 0, 0, 1, 1, 0);  // not orthogonal
  EXPECT_EQ(cap.count(), 4u);
  MeVector3 axis;
  MdtHingeGetAxis(h, axis);
  EXPECT_EQ(axis[2], 1);
  // Wrong type through the typed API.
  MdtHingeGetLimit(reinterpret_cast<MdtHingeID>(MdtBSJointCreate(w)));
  EXPECT_EQ(cap.count(), 5u);
  EXPECT_NE(cap.last().find("where Hinge was expected"), std::string::npos);
}

TEST(BadInput, DestroyingABodyDisablesItsJoints) {
  World w;
  MdtWorldSetGravity(w, 0, -10, 0);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 0, 0);
  MdtBodyEnable(a);
  MdtBodyEnable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointEnable(j);
  WarningCapture cap;
  MdtBodyDestroy(b);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_FALSE(MdtBSJointIsEnabled(j));
  EXPECT_EQ(MdtBSJointGetBody(j, 0), nullptr);
  MdtWorldStep(w, (MeReal)0.01);  // keeps stepping
  EXPECT_TRUE(bodyFinite(a));
}

TEST(BadInput, OverflowingBodyIsStoppedAndDisabledAndOthersContinue) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID wild = MdtBodyCreate(w);
  MdtBodySetPosition(wild, MEINFINITY, 0, 0);
  MdtBodySetLinearVelocity(wild, MEINFINITY, 0, 0);
  MdtBodyEnable(wild);
  MdtBodyID calm = MdtBodyCreate(w);
  MdtBodySetLinearVelocity(calm, 1, 0, 0);
  MdtBodyEnable(calm);
  WarningCapture cap;
  MdtWorldStep(w, 1);
  EXPECT_GE(cap.count(), 1u);
  EXPECT_NE(cap.last().find("disabled"), std::string::npos);
  EXPECT_FALSE(MdtBodyIsEnabled(wild));
  EXPECT_TRUE(bodyFinite(wild));
  MeVector3 x;
  MdtBodyGetPosition(calm, x);
  EXPECT_EQ(x[0], 1);
  MdtWorldStep(w, 1);
  MdtBodyGetPosition(calm, x);
  EXPECT_EQ(x[0], 2);
}

TEST(BadInput, JointToAnOverflowingBodyIsSkippedNotPropagated) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
  MdtBodySetPosition(b, MEINFINITY, 0, 0);
  MdtBodyEnable(a);
  MdtBodyEnable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointEnable(j);
  WarningCapture cap;
  for (int i = 0; i < 3; ++i) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_GE(cap.count(), 1u);
  EXPECT_TRUE(bodyFinite(a));
}
