// Stale handles: a destroyed body's handle is refused with a warning, and a
// collision model whose body was destroyed does not drive the body that
// takes the freed slot next.
#include "scene_support.h"
#include "support/warning_capture.h"

using namespace hard;
using karma_test::WarningCapture;

TEST(HardCases, DestroyedBodyHandleIsRefused) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtBodyDestroy(b);
  ASSERT_EQ(MdtWorldGetBodyCount(w), 0u);
  WarningCapture warnings;
  MdtBodyEnable(b);  // stale
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  EXPECT_FALSE(MdtBodyIsEnabled(b));
  MdtBodyDestroy(b);  // destroyed twice
  EXPECT_EQ(MdtWorldGetBodyCount(w), 0u);
  EXPECT_GE(warnings.count(), 3u);
  EXPECT_TRUE(warnings.saw("destroyed"));
}

// Every getter and setter of a body refuses a destroyed one with a warning:
// setters change nothing, getters leave their output untouched and return
// zero.
TEST(HardCases, StaleHandleGettersAndSettersAreRefused) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyID other = MdtBodyCreate(w);
  MdtBSJointID joint = MdtBSJointCreate(w);
  MdtBodyDestroy(b);
  WarningCapture warnings;
  MdtBodySetPosition(b, 1, 2, 3);
  MdtBodySetLinearVelocity(b, 1, 0, 0);
  MdtBodySetMass(b, 5);
  MdtBodyAddForce(b, 1, 0, 0);
  MdtBodyAddImpulse(b, 1, 0, 0);
  EXPECT_EQ(warnings.count(), 5u);
  MeVector3 out = {7, 7, 7};
  MdtBodyGetPosition(b, out);
  MdtBodyGetLinearVelocity(b, out);
  MdtBodyGetForce(b, out);
  EXPECT_EQ(out[0], 7);
  EXPECT_EQ(out[1], 7);
  EXPECT_EQ(out[2], 7);
  EXPECT_EQ(MdtBodyGetMass(b), 0);
  EXPECT_EQ(MdtBodyGetUserData(b), nullptr);
  EXPECT_EQ(MdtBodyGetWorld(b), nullptr);
  EXPECT_EQ(warnings.count(), 11u);
  EXPECT_TRUE(warnings.saw("destroyed"));
  MdtBSJointSetBodies(joint, other, b);  // a stale body is not attached
  EXPECT_EQ(MdtBSJointGetBody(joint, 0), nullptr);
  EXPECT_EQ(warnings.count(), 12u);
}

// A destroyed body's slot is not handed out again while the pool has other
// free slots, so its handle stays detectable; once the pool is full, the
// oldest destroyed slot is reused.
TEST(HardCases, DestroyedSlotIsReusedLast) {
  World w(3);
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodyDestroy(a);
  MdtBodyID b = MdtBodyCreate(w);
  EXPECT_NE(b, a);
  {
    WarningCapture warnings;
    MdtBodyEnable(a);
    EXPECT_TRUE(warnings.saw("destroyed"));
  }
  MdtBodyID c = MdtBodyCreate(w);
  EXPECT_NE(c, a);
  EXPECT_EQ(MdtWorldGetBodyCount(w), 2u);
  MdtBodyID d = MdtBodyCreate(w);  // the pool is full: the retired slot comes back
  EXPECT_EQ(d, a);
  EXPECT_EQ(MdtWorldGetBodyCount(w), 3u);
  WarningCapture warnings;
  MdtBodyEnable(d);
  EXPECT_TRUE(MdtBodyIsEnabled(d));
  EXPECT_EQ(warnings.count(), 0u);
  EXPECT_EQ(MdtBodyCreate(w), nullptr);  // and then the pool is exhausted
}

TEST(HardCases, ModelOfADestroyedBodyDoesNotDriveTheNextBody) {
  Universe U;
  McdModelID m = addBox(U, 1, 1, 1, 1, 0, 5, 0);
  MdtBodyID old = bodyOf(m);
  WarningCapture warnings;
  MdtBodyDestroy(old);  // the model still refers to it
  EXPECT_TRUE(warnings.saw("model"));
  EXPECT_EQ(McdModelGetBody(m), nullptr);
  // The next body takes the freed slot; it must stay the model-less body it is.
  MdtBodyID next = MdtBodyCreate(U.world());
  MdtBodySetPosition(next, 100, 0.5, 0);
  MdtBodyEnable(next);
  for (int i = 0; i < 60; ++i) U.step(1.0 / 60);
  EXPECT_EQ(McdModelGetBody(m), nullptr);
  double p[3];
  position(next, p);
  // Model-less, it falls freely through where the ground is: 1 s of fall.
  EXPECT_NEAR(p[1], 0.5 - kG / 2, kG / 60 + 1e-3);
}
