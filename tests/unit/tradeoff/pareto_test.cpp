// pareto_test.cpp: the Pareto front of (µs per step, error) points, on a
// constructed data set whose front is known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "pareto.h"
#include "results.h"

namespace {

using karma::tradeoff::CostError;
using karma::tradeoff::ParetoFront;

TEST(TradeoffPareto, TheFrontIsTheUndominatedValidPoints) {
  //   point      cost  error   on the front?
  const std::vector<CostError> points = {
      {10, 1.0, true},    // 0 yes: the cheapest
      {20, 0.5, true},    // 1 yes
      {25, 0.6, true},    // 2 no: 1 is cheaper and better
      {40, 0.1, true},    // 3 yes
      {40, 0.2, true},    // 4 no: 3 costs the same and is better
      {80, 0.1, true},    // 5 no: 3 is as good and cheaper
      {100, 0.01, true},  // 6 yes: the most accurate
      {5, 0.001, false},  // 7 no: failed (and it must not dominate anyone)
      {15, NAN, true},    // 8 no: no error measured
      {20, 0.5, true},    // 9 yes: equal to 1, neither dominates the other
  };
  const std::vector<bool> front = ParetoFront(points);
  const std::vector<bool> expected = {true, true, false, true, false, false, true, false, false, true};
  EXPECT_EQ(front, expected);
}

TEST(TradeoffPareto, EmptyAndSingleSets) {
  EXPECT_TRUE(ParetoFront({}).empty());
  EXPECT_EQ(ParetoFront({{3, 3, true}}), std::vector<bool>{true});
  EXPECT_EQ(ParetoFront({{3, 3, false}}), std::vector<bool>{false});
}

// The fronts of a scene's rows skip the peers and the other scenes, and
// the summary names the knob that buys most accuracy per microsecond.
TEST(TradeoffPareto, RowsFrontsAndTheirSummary) {
  using karma::tradeoff::ResultRow;
  auto row = [](const char *scene, double us, double drift, double h, int pgs, const char *engine = "karma") {
    ResultRow r;
    r.scene = scene;
    r.engine = engine;
    r.micros = {us};
    r.drift = drift;
    r.sceneError = drift;
    r.setting.h = h;
    if (pgs > 0) r.setting.method = MdtKeaMethodPGS, r.setting.iterations = pgs;
    return r;
  };
  std::vector<ResultRow> rows = {row("a", 10, 1.0, 1.0 / 60, 10),       row("a", 12, 0.9, 1.0 / 60, 0),
                                 row("a", 20, 0.05, 1.0 / 120, 10),     row("a", 50, 0.04, 1.0 / 120, 0),
                                 row("a", 1, 1e-6, 1.0 / 60, 0, "ode"), row("b", 1, 1e-6, 1.0 / 60, 0)};
  karma::tradeoff::MarkFronts(rows, "a");
  EXPECT_TRUE(rows[0].frontDrift && rows[1].frontDrift && rows[2].frontDrift && rows[3].frontDrift);
  EXPECT_FALSE(rows[4].frontDrift);  // a peer: drawn, never on Karma's front
  EXPECT_FALSE(rows[5].frontDrift);  // another scene
  const std::string summary = karma::tradeoff::FrontSummary(rows, "a", false);
  // Steepest segment: exact 1/60 -> iterative:10 1/120, error /18 for x1.7.
  EXPECT_NE(summary.find("changing solver and h (`exact h=1/60` to `iterative:10 h=1/120`"), std::string::npos)
      << summary;
}

}  // namespace
