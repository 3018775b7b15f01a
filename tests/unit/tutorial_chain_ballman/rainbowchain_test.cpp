// RainbowChain's behaviour, without MeViewer: the chain swings from its
// pivot, lands on the ground and stays whole. Joint error = the distance
// between a joint's point as carried by each of its two bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "chain.h"

namespace {

struct ChainRun {
  double worstError = 0;  // m, over every step
  double lowest = 1e9;    // lowest ball centre over the run, m
  bool finite = true;
};

// `steps` steps; from `pullFrom` to `pullTo` the mouse force (fx, 0, fz) on
// the last ball, reset at `resetAt` (< 0: never).
ChainRun RunChain(int steps, int pullFrom = -1, int pullTo = -1, MeReal fx = 0, MeReal fz = 0, int resetAt = -1) {
  RainbowChain *c = RainbowChainCreate();
  EXPECT_NE(c, nullptr);
  ChainRun r;
  for (int s = 0; s < steps; ++s) {
    if (s == pullFrom) RainbowChainSetEndForce(c, fx, 0, fz);
    if (s == pullTo) RainbowChainSetEndForce(c, 0, 0, 0);
    if (s == resetAt) RainbowChainReset(c);
    RainbowChainStep(c);
    r.worstError = std::fmax(r.worstError, (double)RainbowChainJointError(c));
    for (McdModelID m : c->ball) {
      MeVector3 x;
      MdtBodyGetPosition(McdModelGetBody(m), x);
      r.lowest = std::fmin(r.lowest, (double)x[1]);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) r.finite = false;
    }
  }
  RainbowChainDestroy(c);
  return r;
}

TEST(RainbowChain, StartsStraightAndJoined) {
  RainbowChain *c = RainbowChainCreate();
  ASSERT_NE(c, nullptr);
  EXPECT_LT(RainbowChainJointError(c), 1e-6);
  // Every ball's model uses the one sphere geometry.
  for (McdModelID m : c->ball) EXPECT_EQ(McdModelGetGeometry(m), c->ballGeometry);
  RainbowChainDestroy(c);
}

TEST(RainbowChain, JointErrorStaysUnder5mmAsItFallsAndLands) {
  // 5 s: the swing, the landing on the ground (at about 1 s), the chain
  // swinging on the floor.
  const ChainRun r = RunChain(300);
  std::printf("rainbowchain: joint error max %.3f mm over 300 frames, lowest centre %.3f m\n", r.worstError * 1e3,
              r.lowest);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.worstError, 0.005);
  // It lands on the ground and does not go through it.
  EXPECT_LT(r.lowest, 0.6);
  EXPECT_GT(r.lowest, 0.5 - 0.02);
}

TEST(RainbowChain, JointErrorStaysUnder5mmWhenPulledAndReset) {
  // The golden test's script: a pull on the end ball, then a reset.
  const ChainRun r = RunChain(360, 150, 250, 20, -10, 300);
  std::printf("rainbowchain (pulled, reset): joint error max %.3f mm\n", r.worstError * 1e3);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.worstError, 0.005);
}

TEST(RainbowChain, ResetRestoresTheStart) {
  RainbowChain *c = RainbowChainCreate();
  MeVector3 start[RC_NBALLS];
  for (int i = 0; i < RC_NBALLS; ++i) MdtBodyGetPosition(McdModelGetBody(c->ball[i]), start[i]);
  for (int s = 0; s < 100; ++s) RainbowChainStep(c);
  RainbowChainReset(c);
  for (int i = 0; i < RC_NBALLS; ++i) {
    MeVector3 x, v;
    MdtBodyGetPosition(McdModelGetBody(c->ball[i]), x);
    MdtBodyGetLinearVelocity(McdModelGetBody(c->ball[i]), v);
    EXPECT_EQ(x[0], start[i][0]);
    EXPECT_EQ(x[1], start[i][1]);
    EXPECT_EQ(x[2], start[i][2]);
    EXPECT_EQ(MeVector3Magnitude(v), 0);
  }
  RainbowChainDestroy(c);
}

TEST(RainbowChain, EndForcePullsTheEnd) {
  // A steady sideways pull moves the last ball along it.
  RainbowChain *a = RainbowChainCreate(), *b = RainbowChainCreate();
  RainbowChainSetEndForce(b, 0, 0, 30);
  for (int s = 0; s < 60; ++s) RainbowChainStep(a), RainbowChainStep(b);
  MeVector3 xa, xb;
  MdtBodyGetPosition(McdModelGetBody(a->ball[RC_NBALLS - 1]), xa);
  MdtBodyGetPosition(McdModelGetBody(b->ball[RC_NBALLS - 1]), xb);
  std::printf("rainbowchain: 30 N pull for 1 s moves the end ball %.3f m along z\n", (double)(xb[2] - xa[2]));
  EXPECT_GT(xb[2] - xa[2], 0.5);
  RainbowChainDestroy(a);
  RainbowChainDestroy(b);
}

}  // namespace
