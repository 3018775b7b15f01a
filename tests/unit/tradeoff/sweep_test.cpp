// sweep_test.cpp: karma-tradeoff's sweep syntax (tools/tradeoff/src/settings.h).
#include <gtest/gtest.h>

#include <cmath>

#include "settings.h"

namespace {

using karma::tradeoff::ExpandValues;
using karma::tradeoff::FormatStep;
using karma::tradeoff::ParseSweep;
using karma::tradeoff::Setting;

TEST(TradeoffSweep, TheIssuesExampleExpandsToEveryCombination) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("solver=exact,exact:8,iterative:10,iterative:50 epsilon=1e-4..1e-1 h=1/60..1/480", s, error))
      << error;
  // 4 solvers x 4 epsilons (powers of ten: x10) x 4 steps (x2).
  ASSERT_EQ(s.size(), 64u);
  EXPECT_EQ(s[0].label(), "exact epsilon=0.0001 h=1/60");
  EXPECT_EQ(s[1].label(), "exact epsilon=0.0001 h=1/120");
  EXPECT_EQ(s[3].label(), "exact epsilon=0.0001 h=1/480");
  EXPECT_EQ(s[4].label(), "exact epsilon=0.001 h=1/60");
  EXPECT_EQ(s[16].label(), "exact:8 epsilon=0.0001 h=1/60");
  EXPECT_EQ(s[63].label(), "iterative:50 epsilon=0.1 h=1/480");
  EXPECT_EQ(s[16].method, MdtKeaMethodActiveSet);
  EXPECT_EQ(s[16].iterations, 8);
  EXPECT_EQ(s[63].method, MdtKeaMethodPGS);
  EXPECT_EQ(s[63].iterations, 50);
  EXPECT_DOUBLE_EQ(s[63].h, 1.0 / 480);
  EXPECT_DOUBLE_EQ(s[63].epsilon, 0.1);
}

TEST(TradeoffSweep, ABudgetIsASolverSetting) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("solver=budget:300,exact:8", s, error)) << error;
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].label(), "budget:300 h=1/60");
  EXPECT_DOUBLE_EQ(s[0].budget, 300);
  EXPECT_EQ(s[0].iterations, 0);
  EXPECT_DOUBLE_EQ(s[1].budget, 0);
  EXPECT_FALSE(ParseSweep("solver=budget", s, error));
  EXPECT_NE(error.find("budget:US"), std::string::npos);
}

TEST(TradeoffSweep, RangesAreGeometricWithTheirEndsExact) {
  std::vector<double> v;
  std::string error;
  ASSERT_TRUE(ExpandValues("0.1..0.8", v, error));  // not powers of ten: x2
  ASSERT_EQ(v.size(), 4u);
  EXPECT_DOUBLE_EQ(v[0], 0.1);
  EXPECT_NEAR(v[1], 0.2, 1e-15);
  EXPECT_NEAR(v[2], 0.4, 1e-15);
  EXPECT_DOUBLE_EQ(v[3], 0.8);
  ASSERT_TRUE(ExpandValues("1e-3..1e-1:5", v, error));  // five points: x sqrt(10)
  ASSERT_EQ(v.size(), 5u);
  EXPECT_NEAR(v[1], 1e-3 * std::sqrt(10.0), 1e-15);
  EXPECT_DOUBLE_EQ(v[4], 0.1);
  ASSERT_TRUE(ExpandValues("0.2,1/4", v, error));
  EXPECT_EQ(v, (std::vector<double>{0.2, 0.25}));
}

TEST(TradeoffSweep, KnobsLeftOutKeepTheScenesValues) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("", s, error));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].label(), "exact h=1/60");
  EXPECT_TRUE(std::isnan(s[0].epsilon) && std::isnan(s[0].gamma) && std::isnan(s[0].tolerance));
  EXPECT_LT(s[0].cap, 0);
  ASSERT_TRUE(ParseSweep("gamma=0.2,0.8 cap=12 tolerance=1e-6 h=0.01", s, error));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].label(), "exact gamma=0.8 h=1/100 tolerance=1e-06 cap=12");
  EXPECT_EQ(FormatStep(0.0125), "1/80");
  EXPECT_EQ(FormatStep(0.003), "0.003");
}

TEST(TradeoffSweep, JointProjectionIsAKnob) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("projection=0,2", s, error)) << error;
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].label(), "exact h=1/60 projection=0");
  EXPECT_EQ(s[1].label(), "exact h=1/60 projection=2");
  MdtWorldID world = MdtWorldCreate(1, 1, 1, 1);
  s[1].apply(world, nullptr);
  EXPECT_EQ(MdtWorldGetJointProjection(world), 2);
  s[0].apply(world, nullptr);
  EXPECT_EQ(MdtWorldGetJointProjection(world), 0);
  Setting{}.apply(world, nullptr);  // left out: the world keeps its own
  EXPECT_EQ(MdtWorldGetJointProjection(world), 0);
  MdtWorldDestroy(world);
  EXPECT_FALSE(ParseSweep("projection=1.5", s, error));
  EXPECT_FALSE(ParseSweep("projection=-1", s, error));
}

TEST(TradeoffSweep, TheWarmKnobKeepsOrSolvesWarmStarts) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("warm=1,0", s, error)) << error;
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].label(), "exact h=1/60 warm=1");
  EXPECT_EQ(s[1].label(), "exact h=1/60 warm=0");
  EXPECT_EQ(Setting{}.label(), "exact h=1/60");  // left out: the scene's own
  EXPECT_FALSE(ParseSweep("warm=2", s, error));
  EXPECT_FALSE(ParseSweep("warm=0.5", s, error));
  MdtWorldID world = MdtWorldCreate(4, 4, 1, 1);
  ASSERT_NE(world, nullptr);
  ASSERT_TRUE(ParseSweep("warm=0", s, error)) << error;
  s[0].apply(world, nullptr);
  EXPECT_EQ(MdtWorldGetKeaAcceptWarmStart(world), 0);
  ASSERT_TRUE(ParseSweep("warm=1", s, error)) << error;
  s[0].apply(world, nullptr);
  EXPECT_EQ(MdtWorldGetKeaAcceptWarmStart(world), 1);
  MdtWorldDestroy(world);
}

TEST(TradeoffSweep, TheReuseKnobSetsTheContactReuseDistance) {
  std::vector<Setting> s;
  std::string error;
  ASSERT_TRUE(ParseSweep("reuse=0,1e-3", s, error)) << error;
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].label(), "exact h=1/60 reuse=0");
  EXPECT_EQ(s[1].label(), "exact h=1/60 reuse=0.001");
  EXPECT_FALSE(ParseSweep("reuse=-1", s, error));
  MdtWorldID world = MdtWorldCreate(4, 4, 1, 1);
  McdFrameworkID framework = McdInit(0, 4, 4, 1);
  ASSERT_NE(world, nullptr);
  ASSERT_NE(framework, nullptr);
  const MeReal initial = McdFrameworkGetContactReuseDistance(framework);
  Setting{}.apply(world, framework);  // left out: the framework keeps its own
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(framework), initial);
  ASSERT_TRUE(ParseSweep("reuse=0,1e-3", s, error)) << error;
  s[0].apply(world, framework);
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(framework), 0);
  s[1].apply(world, framework);
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(framework), (MeReal)1e-3);
  s[0].apply(world, nullptr);  // a scene without collision: nothing to set
  EXPECT_EQ(McdFrameworkGetContactReuseDistance(framework), (MeReal)1e-3);
  McdTerm(framework);
  MdtWorldDestroy(world);
}

TEST(TradeoffSweep, BadSweepsSayWhatIsWrong) {
  std::vector<Setting> s;
  std::string error;
  EXPECT_FALSE(ParseSweep("solver=fast", s, error));
  EXPECT_NE(error.find("bad solver 'fast'"), std::string::npos) << error;
  EXPECT_FALSE(ParseSweep("solver=iterative", s, error));  // PGS needs its sweep count
  EXPECT_FALSE(ParseSweep("h=0", s, error));
  EXPECT_FALSE(ParseSweep("epsilon=-1", s, error));
  EXPECT_FALSE(ParseSweep("colour=red", s, error));
  EXPECT_FALSE(ParseSweep("h=1/0", s, error));
  EXPECT_FALSE(ParseSweep("epsilon", s, error));
  EXPECT_NE(error.find("knob=values"), std::string::npos) << error;
  EXPECT_FALSE(ParseSweep("h=0..1/60", s, error));
  EXPECT_FALSE(ParseSweep("cap=2.5", s, error));
}

}  // namespace
