// run_test.cpp: one run of a built-in scene: deterministic, its errors
// against itself zero, the figures it reports bounded by what the scene
// must do, and every built-in scene builds and steps.
#include <gtest/gtest.h>

#include <cmath>

#include "run.h"
#include "scene.h"

namespace {

using namespace karma::tradeoff;

SceneEntry Scene(const char *name) {
  SceneEntry e;
  std::string error;
  EXPECT_TRUE(FindScene(name, e, error)) << error;
  return e;
}

TEST(TradeoffRun, ARunIsDeterministicAndMatchesItself) {
  const SceneEntry car = Scene("car");
  Setting s;
  s.h = 1.0 / 120;
  RunRecord a, b;
  ASSERT_TRUE(RunScene(car, s, 0.5, a));
  ASSERT_TRUE(RunScene(car, s, 0.5, b));
  EXPECT_EQ(a.steps, 60);
  ASSERT_EQ(a.trajectory.positions.size(), 30u);  // one sample per 1/60 s
  EXPECT_EQ(a.trajectory.positions, b.trajectory.positions);
  EXPECT_EQ(a.trajectory.energy, b.trajectory.energy);
  const Errors e = CompareWithReference(a, b);
  EXPECT_EQ(e.drift, 0);
  EXPECT_EQ(e.energy, 0);
  EXPECT_EQ(e.momentum, 0);
  EXPECT_TRUE(a.held());
  // The car starts from rest under a known acceleration: after 0.5 s the
  // chassis is within a few centimetres of a t^2/2 = 0.40 m.
  EXPECT_LT(a.outcome.sceneError, 0.05);
}

TEST(TradeoffRun, SmallerStepsApproachTheReference) {
  // The rag doll falls freely for 0.5 s, then lands: the exact solver's
  // drift from a 1/960 s reference shrinks as h does.
  const SceneEntry ragdoll = Scene("ragdoll");
  Setting reference, coarse, fine;
  reference.h = 1.0 / 960;
  coarse.h = 1.0 / 60;
  fine.h = 1.0 / 240;
  RunRecord r, c, f;
  ASSERT_TRUE(RunScene(ragdoll, reference, 1.0, r));
  ASSERT_TRUE(RunScene(ragdoll, coarse, 1.0, c));
  ASSERT_TRUE(RunScene(ragdoll, fine, 1.0, f));
  const double dc = CompareWithReference(c, r).drift, df = CompareWithReference(f, r).drift;
  EXPECT_GT(dc, 0);
  EXPECT_LT(df, dc);
  // The joints hold to a few centimetres at the landing.
  EXPECT_GT(c.jointError, 0);
  EXPECT_LT(c.jointError, 0.1);
}

TEST(TradeoffRun, MechanicalEnergyMatchesTheIntegratorsClosedForm) {
  // The chain falls freely for its first 0.5 s (the ball's lowest point
  // starts 1.7 m up and falls g t^2/2 = 1.23 m). A step v' = v - g h,
  // x' = x + v' h changes kinetic + potential energy by -m g^2 h^2 / 2,
  // so after t seconds the energy has moved by -m g^2 h t / 2.
  const SceneEntry chain = Scene("chain");
  Setting s;
  s.h = 1.0 / 240;
  RunRecord run;
  ASSERT_TRUE(RunScene(chain, s, 0.5, run));
  const double mass = 20 * 0.2 + 20, g = 9.81;
  const double expected = -mass * g * g * s.h * 0.5 / 2;
  // The first sample is at 1/60 s, after 4 steps: the energy at t = 0 is
  // that sample's plus 4 steps' change.
  const double start = run.trajectory.energy.front() + 4 * mass * g * g * s.h * s.h / 2;
  const double moved = run.trajectory.energy.back() - start;
  EXPECT_NEAR(moved, expected, 0.01 * std::fabs(expected)) << "energy moved by " << moved;
}

TEST(TradeoffRun, EveryBuiltInSceneBuildsAndSteps) {
  for (const SceneEntry &e : Catalogue()) {
    SCOPED_TRACE(e.name);
    RunRecord run;
    Setting s;
    ASSERT_TRUE(RunScene(e, s, 2.0 / 60, run));
    EXPECT_EQ(run.steps, 2);
    EXPECT_TRUE(run.finite);
    EXPECT_FALSE(run.trajectory.positions.back().empty());
  }
}

}  // namespace
