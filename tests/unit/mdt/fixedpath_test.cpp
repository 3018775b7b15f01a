// Fixed-path joint: a pendulum whose top follows an animated path.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "joints_a_support.h"

using namespace mdt_test;

TEST(FixedPath, PendulumTopFollowsACircularPath) {
  // The top of a pendulum (0.5 m above the bob's centre) is carried round a
  // circle of radius 0.3 m at 3 rad/s in the x-z plane, position and
  // velocity set every step. The bob's attachment point stays on the path.
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  const double R = 0.3, omega = 3;
  const MeReal h = (MeReal)1 / 240;
  MdtBodyID bob = makeBody(w, (MeReal)R, -(MeReal)0.5, 0);
  MdtFixedPathID j = MdtFixedPathCreate(w);
  MdtFixedPathSetBodies(j, bob, nullptr);
  MdtFixedPathSetPosition(j, 0, (MeReal)R, 0, 0);
  MdtFixedPathSetPosition(j, 1, (MeReal)R, 0, 0);
  MdtFixedPathEnable(j);
  double worst = 0, gap = 0;
  for (int i = 0; i < 1200; ++i) {
    const double t = i * (double)h;
    MdtFixedPathSetPosition(j, 1, (MeReal)(R * std::cos(omega * t)), 0, (MeReal)(R * std::sin(omega * t)));
    MdtFixedPathSetVelocity(j, 1, (MeReal)(-R * omega * std::sin(omega * t)), 0,
                            (MeReal)(R * omega * std::cos(omega * t)));
    MdtWorldStep(w, h);
    const double t1 = t + (double)h;
    const MeVector3 target = {(MeReal)(R * std::cos(omega * t1)), 0, (MeReal)(R * std::sin(omega * t1))};
    MeVector3 p;
    MdtFixedPathGetPosition(j, 0, p);
    worst = std::max(worst, (double)MeVector3Distance(p, target));
    gap = std::max(gap, anchorGap(MdtFixedPathQuaConstraint(j)));
  }
  printf("fixed path: worst distance to target %.3g m, worst joint gap %.3g m\n", worst, gap);
  EXPECT_LT(worst, 1e-3);
  EXPECT_TRUE(bodyFinite(bob));
}

TEST(FixedPath, ConstantPathVelocityAdvancesByItself) {
  // Only a velocity: the world's point moves at 0.5 m/s along x, so after
  // 2 s it is at x = 1 and the body's point with it; no gravity.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, -1, 0);
  MdtFixedPathID j = MdtFixedPathCreate(w);
  MdtFixedPathSetBodies(j, b, nullptr);
  MdtFixedPathSetPosition(j, 0, 0, 0, 0);
  MdtFixedPathSetPosition(j, 1, 0, 0, 0);
  MdtFixedPathSetVelocity(j, 1, (MeReal)0.5, 0, 0);
  MdtFixedPathEnable(j);
  for (int i = 0; i < 200; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 p0, p1, v;
  MdtFixedPathGetPosition(j, 0, p0);
  MdtFixedPathGetPosition(j, 1, p1);
  EXPECT_NEAR(p1[0], 1.0, 1e-5);
  EXPECT_NEAR(p0[0], 1.0, 1e-3);
  EXPECT_LT(MeVector3Distance(p0, p1), 1e-3);
  MdtFixedPathGetVelocity(j, 1, v);
  EXPECT_EQ(v[0], (MeReal)0.5);
}

TEST(FixedPath, PointMovingWithinTheBody) {
  // The path velocity belongs to body 0 this time (its frame): the joint
  // point slides 0.4 m/s along the body's x axis while the world point stays
  // put, so the body itself must move -0.4 m/s along x.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtFixedPathID j = MdtFixedPathCreate(w);
  MdtFixedPathSetBodies(j, b, nullptr);
  MdtFixedPathSetVelocity(j, 0, (MeReal)0.4, 0, 0);
  MdtFixedPathEnable(j);
  for (int i = 0; i < 100; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 x, v;
  MdtBodyGetPosition(b, x);
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_NEAR(v[0], -0.4, 1e-3);
  EXPECT_NEAR(x[0], -0.4, 2e-3);
  EXPECT_LT(anchorGap(MdtFixedPathQuaConstraint(j)), 1e-3);
}

TEST(FixedPath, FeedsBackTheWeightItCarries) {
  // A 2 kg body hanging at rest from a stationary path point: the joint's
  // force on it is m g upwards.
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 0, -1, 0);
  MdtBodySetMass(b, 2);
  MdtFixedPathID j = MdtFixedPathCreate(w);
  MdtFixedPathSetBodies(j, b, nullptr);
  MdtFixedPathSetPosition(j, 0, 0, 0, 0);
  MdtFixedPathSetPosition(j, 1, 0, 0, 0);
  MdtFixedPathEnable(j);
  for (int i = 0; i < 100; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 f;
  MdtFixedPathGetForce(j, 0, f);
  EXPECT_NEAR(f[1], 2 * kG, 2 * kG * 1e-3);
  EXPECT_NEAR(f[0], 0, 1e-3);
}
