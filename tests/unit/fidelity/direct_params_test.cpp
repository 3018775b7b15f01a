// direct_params_test.cpp: values written into world->params directly, as
// the guide's programs do (issue 19, item 3). Each gets the setter's rule
// and warning at the next MdtWorldStep, once: rejected values are replaced
// by the last valid one, gamma above 1 is kept with its warning.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "Mdt.h"
#include "support/warning_capture.h"

using karma_test::WarningCapture;

namespace {

constexpr MeReal kH = (MeReal)1 / 60;

// A 1 kg bob 1 m from a ball joint to the world, released level, under
// 9.81 m/s^2: a one-body pendulum.
struct Pendulum {
  MdtWorldID w = MdtWorldCreate(1, 1, 1, 1);
  MdtBodyID bob = MdtBodyCreate(w);
  Pendulum() {
    w->params.gravity[1] = -(MeReal)9.81;  // the guide's own style
    MdtWorldSetAutoDisable(w, 0);
    MdtBodyEnable(bob);
    MdtBodySetPosition(bob, 1, 0, 0);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, bob, nullptr);
    MdtBSJointSetPosition(j, 0, 0, 0);
    MdtBSJointEnable(j);
  }
  ~Pendulum() { MdtWorldDestroy(w); }
  // Steps for `seconds`; the largest distance of the bob from the pivot.
  MeReal run(MeReal seconds) {
    MeReal far = 0;
    for (int i = 0; i < (int)std::lround(seconds / kH); ++i) {
      MdtWorldStep(w, kH);
      MeVector3 p;
      MdtBodyGetPosition(bob, p);
      far = std::fmax(far, MeVector3Magnitude(p));
    }
    return far;
  }
  void position(MeVector3 p) { MdtBodyGetPosition(bob, p); }
};

}  // namespace

TEST(DirectParams, ValidWritesAreSilentAndUsed) {
  Pendulum p;
  WarningCapture cap;
  p.w->params.epsilon = (MeReal)0.005;  // the guide's stacking sample
  p.w->params.gamma = (MeReal)0.5;
  const MeReal far = p.run(5);
  EXPECT_EQ(cap.count(), 0u);
  EXPECT_EQ(MdtWorldGetEpsilon(p.w), (MeReal)0.005);
  EXPECT_EQ(MdtWorldGetGamma(p.w), (MeReal)0.5);
  EXPECT_LT(far, 1.01);
}

TEST(DirectParams, GammaAboveOneWarnsOnceAtTheNextStepAsTheSetterDoes) {
  Pendulum direct, setter;
  WarningCapture cap;
  direct.w->params.gamma = 5;  // the guide's stacking sample, line 2507
  EXPECT_EQ(cap.count(), 0u);
  MdtWorldStep(direct.w, kH);
  ASSERT_EQ(cap.count(), 1u);
  EXPECT_TRUE(cap.lastMentions("MdtWorldSetGamma"));
  EXPECT_TRUE(cap.lastMentions("r * h"));
  for (int i = 0; i < 10; ++i) MdtWorldStep(direct.w, kH);
  EXPECT_EQ(cap.count(), 1u);  // once
  EXPECT_EQ(direct.w->params.gamma, 5);
  // The same value through the setter: the same warning, the same motion.
  MdtWorldSetGamma(setter.w, 5);
  EXPECT_EQ(cap.count(), 2u);
  for (int i = 0; i < 11; ++i) MdtWorldStep(setter.w, kH);
  EXPECT_EQ(cap.count(), 2u);
  MeVector3 a, b;
  direct.position(a);
  setter.position(b);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k], b[k]);
}

TEST(DirectParams, ThePendulumThatBlewUpIsToldFirst) {
  // gamma 5 corrects five times the error each step: the one-body pendulum
  // leaves its 1 m radius within 5 s whichever way gamma is set (in single
  // precision it overflows and the step stops and disables the bob, with a
  // warning of its own). The gamma warning now comes at the first step,
  // before anything has moved, and only once.
  Pendulum p;
  WarningCapture cap;
  p.w->params.gamma = 5;
  MdtWorldStep(p.w, kH);
  ASSERT_EQ(cap.count(), 1u);
  EXPECT_TRUE(cap.lastMentions("MdtWorldSetGamma"));
  const MeReal far = p.run(5);
  std::printf("gamma 5 written directly: the bob reached %g m from the pivot\n", (double)far);
  EXPECT_GT(far, 2);  // the blow-up happens, but not silently
  int gammaWarnings = 0;
  for (const std::string &m : WarningCapture::log()) gammaWarnings += m.find("MdtWorldSetGamma") != std::string::npos;
  EXPECT_EQ(gammaWarnings, 1);
}

TEST(DirectParams, RejectedValuesAreReplacedByTheLastValidOne) {
  Pendulum p, reference;
  WarningCapture cap;
  p.w->params.epsilon = -1;
  p.w->params.gamma = std::numeric_limits<MeReal>::quiet_NaN();
  p.w->params.gravity[0] = std::numeric_limits<MeReal>::infinity();
  p.w->params.keaMaxIterations = -3;
  MdtWorldStep(p.w, kH);
  EXPECT_EQ(cap.count(), 4u);
  EXPECT_TRUE(cap.saw("MdtWorldSetEpsilon"));
  EXPECT_TRUE(cap.saw("MdtWorldSetGamma"));
  EXPECT_TRUE(cap.saw("MdtWorldSetGravity"));
  EXPECT_TRUE(cap.saw("MdtWorldSetKeaMaxIterations"));
  EXPECT_EQ(MdtWorldGetEpsilon(p.w), (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetGamma(p.w), (MeReal)0.2);
  EXPECT_EQ(p.w->params.gravity[0], 0);
  EXPECT_EQ(p.w->params.keaMaxIterations, 0);
  // The pendulum swings as if nothing had been written: bit-identical, and
  // bounded for 5 s.
  MdtWorldStep(reference.w, kH);
  EXPECT_LT(p.run(5), 1.01);
  reference.run(5);
  EXPECT_EQ(cap.count(), 4u);
  MeVector3 a, b;
  p.position(a);
  reference.position(b);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k], b[k]);
}

TEST(DirectParams, SetterValuesAreNotCheckedTwice) {
  Pendulum p;
  WarningCapture cap;
  MdtWorldSetGamma(p.w, 3);
  EXPECT_EQ(cap.count(), 1u);
  MdtWorldStep(p.w, kH);
  EXPECT_EQ(cap.count(), 1u);
  // A rejected setter call leaves the direct-write check nothing to report.
  MdtWorldSetEpsilon(p.w, -2);
  EXPECT_EQ(cap.count(), 2u);
  MdtWorldStep(p.w, kH);
  EXPECT_EQ(cap.count(), 2u);
}

TEST(DirectParams, TheSolverChoiceFieldsKeepTheirSettersLastValue) {
  // A direct write the setter would reject goes back to the setter's last
  // value (not the default, which it would be if the setter did not store
  // into the checked copy), and a direct keaAcceptWarmStart is read as a
  // boolean, as autoDisable is.
  Pendulum p;
  WarningCapture cap;
  MdtWorldSetKeaIterativeRows(p.w, 50);
  p.w->params.keaIterativeRows = -1;  // before any step: the setter's value is the last valid one
  p.w->params.keaAcceptWarmStart = 7;
  MdtWorldStep(p.w, kH);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_TRUE(cap.saw("MdtWorldSetKeaIterativeRows"));
  EXPECT_EQ(MdtWorldGetKeaIterativeRows(p.w), 50);
  EXPECT_EQ(p.w->params.keaAcceptWarmStart, 1);
  MdtWorldStep(p.w, kH);
  EXPECT_EQ(cap.count(), 1u);  // once
}
