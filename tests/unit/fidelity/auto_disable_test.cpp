// auto_disable_test.cpp: auto-disable as the guide describes it (issue 19,
// item 5): a force, torque or impulse above a threshold wakes a disabled
// body (one below does not, and is dropped); the alive window counts in
// each of its three readings (MdtWorld.h, "The alive window").
#include <gtest/gtest.h>

#include "Mdt.h"
#include "support/warning_capture.h"

namespace {

constexpr MeReal kH = (MeReal)0.01;

// One free 1 kg body (inertia 0.4 about every axis, the default) in a world
// without gravity, enabled and at rest.
struct OneBody {
  MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
  MdtBodyID b = MdtBodyCreate(w);
  OneBody() { MdtBodyEnable(b); }
  ~OneBody() { MdtWorldDestroy(w); }
  // Steps until the body is disabled (at most `limit` steps); the count.
  int stepsUntilDisabled(int limit = 1000) {
    for (int i = 1; i <= limit; ++i) {
      MdtWorldStep(w, kH);
      if (!MdtBodyIsEnabled(b)) return i;
    }
    return -1;
  }
  MeReal speed() {
    MeVector3 v;
    MdtBodyGetLinearVelocity(b, v);
    return MeVector3Magnitude(v);
  }
  MeReal spin() {
    MeVector3 v;
    MdtBodyGetAngularVelocity(b, v);
    return MeVector3Magnitude(v);
  }
};

}  // namespace

TEST(AutoDisable, AForceAboveTheThresholdWakesADisabledBody) {
  OneBody s;
  ASSERT_GT(s.stepsUntilDisabled(), 0);
  // |F| / m = 0.3 < 0.5 (the acceleration threshold): stays asleep and the
  // force is dropped, not kept for later.
  MdtBodyAddForce(s.b, (MeReal)0.3, 0, 0);
  MdtWorldStep(s.w, kH);
  EXPECT_FALSE(MdtBodyIsEnabled(s.b));
  MdtBodyEnable(s.b);
  MdtWorldStep(s.w, kH);
  EXPECT_EQ(s.speed(), 0);
  ASSERT_GT(s.stepsUntilDisabled(), 0);
  // |F| / m = 1 > 0.5: woken at the next step, which applies the force.
  MdtBodyAddForce(s.b, 1, 0, 0);
  MdtWorldStep(s.w, kH);
  EXPECT_TRUE(MdtBodyIsEnabled(s.b));
  EXPECT_NEAR(s.speed(), 1 * kH, 1e-6);  // v = h F / m
}

TEST(AutoDisable, ATorqueAboveTheThresholdWakesADisabledBody) {
  OneBody s;
  ASSERT_GT(s.stepsUntilDisabled(), 0);
  // |tau| / I = 0.0005 / 0.4 = 0.00125 < 0.002 rad/s^2: stays asleep.
  MdtBodyAddTorque(s.b, 0, 0, (MeReal)0.0005);
  MdtWorldStep(s.w, kH);
  EXPECT_FALSE(MdtBodyIsEnabled(s.b));
  // 0.004 / 0.4 = 0.01 > 0.002: woken, spun up by h tau / I.
  MdtBodyAddTorque(s.b, 0, 0, (MeReal)0.004);
  MdtWorldStep(s.w, kH);
  EXPECT_TRUE(MdtBodyIsEnabled(s.b));
  EXPECT_NEAR(s.spin(), kH * 0.004 / 0.4, 1e-7);
}

TEST(AutoDisable, AnImpulseAboveTheThresholdWakesADisabledBody) {
  OneBody s;
  ASSERT_GT(s.stepsUntilDisabled(), 0);
  MdtBodyAddImpulse(s.b, (MeReal)0.01, 0, 0);  // 0.01 m/s < 0.02: dropped
  MdtWorldStep(s.w, kH);
  EXPECT_FALSE(MdtBodyIsEnabled(s.b));
  MdtBodyAddImpulse(s.b, (MeReal)0.5, 0, 0);  // 0.5 m/s > 0.02
  MdtWorldStep(s.w, kH);
  EXPECT_TRUE(MdtBodyIsEnabled(s.b));
  EXPECT_NEAR(s.speed(), 0.5, 1e-6);
}

TEST(AutoDisable, ForcesWakeWithAutoDisableOffToo) {
  OneBody s;
  MdtBodyDisable(s.b);
  MdtWorldSetAutoDisable(s.w, 0);
  MdtBodyAddForce(s.b, 0, 2, 0);
  MdtWorldStep(s.w, kH);
  EXPECT_TRUE(MdtBodyIsEnabled(s.b));
}

TEST(AutoDisable, DefaultWindowIsSecondsBelowEveryThreshold) {
  OneBody s;
  EXPECT_EQ(MdtWorldGetAutoDisableAliveWindowMode(s.w), MdtAliveWindowIdleSeconds);
  // At rest from the start: disabled after 0.2 s (20 steps of 0.01 s, one
  // more if the summed step lands just below 0.2).
  const int n = s.stepsUntilDisabled();
  EXPECT_GE(n, 20);
  EXPECT_LE(n, 21);
  // Moving for 1 s, then stopped: again 0.2 s of rest first.
  MdtBodyEnable(s.b);
  MdtBodySetLinearVelocity(s.b, 1, 0, 0);
  for (int i = 0; i < 100; ++i) MdtWorldStep(s.w, kH);
  ASSERT_TRUE(MdtBodyIsEnabled(s.b));
  MdtBodySetLinearVelocity(s.b, 0, 0, 0);
  const int m = s.stepsUntilDisabled();
  EXPECT_GE(m, 20);
  EXPECT_LE(m, 21);
}

TEST(AutoDisable, AZeroIdleWindowStillWaitsForRest) {
  // A window of 0 s puts a body to sleep at its first step at rest, and
  // never while it moves.
  OneBody s;
  MdtWorldSetAutoDisableAliveWindow(s.w, 0);
  MdtBodySetLinearVelocity(s.b, 5, 0, 0);
  for (int i = 0; i < 10; ++i) {
    MdtWorldStep(s.w, kH);
    ASSERT_TRUE(MdtBodyIsEnabled(s.b)) << "step " << i;
  }
  EXPECT_NEAR(s.speed(), 5, 1e-5);
  MdtBodySetLinearVelocity(s.b, 0, 0, 0);
  EXPECT_EQ(s.stepsUntilDisabled(), 1);
}

TEST(AutoDisable, AwakeSecondsWindowCountsFromWaking) {
  OneBody s;
  MdtWorldSetAutoDisableAliveWindowMode(s.w, MdtAliveWindowAwakeSeconds);
  EXPECT_EQ(MdtWorldGetAutoDisableAliveWindowMode(s.w), MdtAliveWindowAwakeSeconds);
  const int n = s.stepsUntilDisabled();  // enabled 0.2 s ago and at rest
  EXPECT_GE(n, 20);
  EXPECT_LE(n, 21);
  // Awake for 1 s, then stopped: disabled at the first step at rest.
  MdtBodyEnable(s.b);
  MdtBodySetLinearVelocity(s.b, 1, 0, 0);
  for (int i = 0; i < 100; ++i) MdtWorldStep(s.w, kH);
  ASSERT_TRUE(MdtBodyIsEnabled(s.b));
  MdtBodySetLinearVelocity(s.b, 0, 0, 0);
  EXPECT_EQ(s.stepsUntilDisabled(), 1);
}

TEST(AutoDisable, AwakeStepsWindowIsANumberOfSteps) {
  OneBody s;
  MdtWorldSetAutoDisableAliveWindowMode(s.w, MdtAliveWindowAwakeSteps);
  MdtWorldSetAutoDisableAliveWindow(s.w, 3);
  EXPECT_EQ(s.stepsUntilDisabled(), 3);
  // Woken by a force: not disabled again within 3 steps, whatever the speed.
  MdtBodyAddImpulse(s.b, (MeReal)0.5, 0, 0);
  MdtWorldStep(s.w, kH);  // step 1 awake, moving
  ASSERT_TRUE(MdtBodyIsEnabled(s.b));
  MdtBodySetLinearVelocity(s.b, 0, 0, 0);
  EXPECT_EQ(s.stepsUntilDisabled(), 2);  // steps 2 and 3
}

TEST(AutoDisable, AnUnknownWindowModeIsRejected) {
  OneBody s;
  karma_test::WarningCapture cap;
  MdtWorldSetAutoDisableAliveWindowMode(s.w, (MdtAliveWindowMode)7);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_EQ(MdtWorldGetAutoDisableAliveWindowMode(s.w), MdtAliveWindowIdleSeconds);
}

TEST(AutoDisable, TheFaqReadingLetsForcesWaitForAnEnable) {
  // The guide's Q&A: a force on a disabled body does not enable it; it
  // accumulates until something enables the body.
  OneBody s;
  EXPECT_TRUE(MdtWorldGetWakeByForce(s.w));
  MdtWorldSetWakeByForce(s.w, 0);
  EXPECT_FALSE(MdtWorldGetWakeByForce(s.w));
  ASSERT_GT(s.stepsUntilDisabled(), 0);
  for (int i = 0; i < 3; ++i) {
    MdtBodyAddForce(s.b, 10, 0, 0);
    MdtWorldStep(s.w, kH);
    EXPECT_FALSE(MdtBodyIsEnabled(s.b));
  }
  MdtBodyEnable(s.b);
  MdtWorldStep(s.w, kH);
  EXPECT_NEAR(s.speed(), 3 * 10 * kH, 1e-5);  // the three forces at once
}
