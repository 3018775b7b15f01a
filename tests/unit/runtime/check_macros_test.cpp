// The check-build validation macros of MeAssert.h, in the configured mode
// (ME_CHECK_ENABLED follows KARMA_CHECK here) and forced on and off.
#include <gtest/gtest.h>

#include "MeConfig.h"
#include "runtime_test_support.h"

#define PROBE_NAME configuredProbe
#define PROBE_MODE "configured"
#include "check_macros_probe_impl.h"

using karma_test::MessageCapture;

namespace {

TEST(CheckMacrosTest, ConfiguredModeFollowsKarmaCheck) {
  EXPECT_EQ(ME_CHECK_ENABLED, KARMA_CHECK);
  EXPECT_EQ(configuredProbe.checksOn, KARMA_CHECK != 0);
  EXPECT_TRUE(forcedOnProbe.checksOn);
  EXPECT_FALSE(forcedOffProbe.checksOn);
}

// Parameter: index into probes (an integer keeps CTest's test names stable).
const CheckProbe *const probes[] = {&configuredProbe, &forcedOnProbe, &forcedOffProbe};

class CheckMacrosModeTest : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override { *current().evaluations = 0; }
  static const CheckProbe &current() { return *probes[GetParam()]; }
};

TEST_P(CheckMacrosModeTest, PassingChecksAreSilentAndContinue) {
  const CheckProbe &probe = current();
  MessageCapture capture;
  int reached = 0;
  probe.checkArg(3, &reached);
  EXPECT_EQ(reached, 1);
  EXPECT_EQ(probe.checkArgRet(4), 8);
  EXPECT_EQ(probe.checkWarn(5), 5);
  probe.assertPositive(1);
  EXPECT_TRUE(capture.warnings().empty());
  EXPECT_EQ(*probe.evaluations, probe.checksOn ? 4 : 0);
}

TEST_P(CheckMacrosModeTest, FailingCheckArgWarnsAndReturnsOnlyWhenChecksAreOn) {
  const CheckProbe &probe = current();
  MessageCapture capture;
  int reached = 0;
  probe.checkArg(-7, &reached);
  const int doubled = probe.checkArgRet(-7);
  const int warned = probe.checkWarn(12);
  EXPECT_EQ(warned, 12) << "ME_CHECK_WARN never returns early";
  if (probe.checksOn) {
    EXPECT_EQ(reached, 0);
    EXPECT_EQ(doubled, -1);
    ASSERT_EQ(capture.warnings().size(), 3u);
    EXPECT_EQ(capture.warnings()[0].text, "checkArg: x must be positive, got -7");
    EXPECT_EQ(capture.warnings()[1].text, "checkArgRet: x must be positive, got -7");
    EXPECT_EQ(capture.warnings()[2].text, "checkWarn: x=12 is large");
  } else {
    EXPECT_EQ(reached, 1);
    EXPECT_EQ(doubled, -14);
    EXPECT_TRUE(capture.warnings().empty());
    EXPECT_EQ(*probe.evaluations, 0) << "conditions are not evaluated when checks are off";
  }
}

TEST_P(CheckMacrosModeTest, RequireFormsAreAlwaysOn) {
  const CheckProbe &probe = current();
  MessageCapture capture;
  int reached = 0;
  probe.requireArg(0, &reached);
  EXPECT_EQ(reached, 0);
  EXPECT_EQ(probe.requireArgRet(0), -1);
  probe.requireArg(1, &reached);
  EXPECT_EQ(reached, 1);
  EXPECT_EQ(probe.requireArgRet(9), 9);
  ASSERT_EQ(capture.warnings().size(), 2u);
  EXPECT_EQ(capture.warnings()[0].text, "requireArg: x is zero");
  EXPECT_EQ(capture.warnings()[1].text, "requireArgRet: x is zero");
}

TEST_P(CheckMacrosModeTest, FailingAssertIsFatalOnlyWhenChecksAreOn) {
  const CheckProbe &probe = current();
  if (probe.checksOn) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(probe.assertPositive(-1),
                 "Karma fatal error: assertion failed: counted\\(x > 0\\) "
                 "\\(.*check_macros_probe_impl\\.h:[0-9]+\\)");
  } else {
    probe.assertPositive(-1);  // compiled away: nothing happens
    EXPECT_EQ(*probe.evaluations, 0);
  }
}

std::string modeName(const ::testing::TestParamInfo<int> &info) {
  std::string name = probes[info.param]->mode;
  for (char &c : name)
    if (c == ' ') c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Modes, CheckMacrosModeTest, ::testing::Values(0, 1, 2), modeName);

}  // namespace
