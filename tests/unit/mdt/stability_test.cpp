// Hard cases that must stay numerically stable over 60 s: no NaN, bounded
// joint error, no energy growth.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mdt_test_support.h"

using namespace mdt_test;

namespace {

const MeReal g = (MeReal)9.81;

double kinetic(MdtBodyID b) {
  MeVector3 v, w;
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, w);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);  // diagonal in these tests, so frame-free
  double e = 0.5 * (double)MdtBodyGetMass(b) * (double)MeVector3MagnitudeSqr(v);
  for (int k = 0; k < 3; ++k) e += 0.5 * (double)I[k][k] * (double)w[k] * (double)w[k];
  return e;
}

double energy(const std::vector<MdtBodyID> &bodies) {
  double e = 0;
  for (MdtBodyID b : bodies) {
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    e += kinetic(b) + (double)MdtBodyGetMass(b) * g * (double)x[1];
  }
  return e;
}

struct ChainResult {
  double worstGap = 0;
  double energyGrowth = 0;  // max(E) - E0
  bool finite = true;
};

// A horizontal chain of `links` bodies 0.2 m apart, hinged by BSJoints to
// the world at x = 0, released to swing down; the last body is
// `ratio` times heavier than the others (0.1 kg).
ChainResult runChain(int links, double ratio, double seconds, MeReal stabilisation = 1) {
  World w((unsigned)links + 1, 1, 1, (unsigned)links + 1);
  MdtWorldSetGeometricStiffness(w, stabilisation);
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  std::vector<MdtBodyID> bodies;
  std::vector<MdtConstraintID> joints;
  for (int i = 0; i < links; ++i) {
    MdtBodyID b = MdtBodyCreate(w);
    const MeReal m = (MeReal)(i == links - 1 ? 0.1 * ratio : 0.1);
    MdtBodySetMass(b, m);
    const MeReal inertia = (MeReal)0.4 * m * (MeReal)0.01;  // a 0.1 m ball
    MeMatrix3 I = {{inertia, 0, 0}, {0, inertia, 0}, {0, 0, inertia}};
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetPosition(b, (MeReal)0.2 * (MeReal)(i + 1), 0, 0);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, b, i == 0 ? nullptr : bodies.back());
    MdtBSJointSetPosition(j, (MeReal)0.2 * (MeReal)i + (MeReal)0.1 * (i > 0), 0, 0);
    if (i == 0) MdtBSJointSetPosition(j, 0, 0, 0);
    MdtBSJointEnable(j);
    bodies.push_back(b);
    joints.push_back(MdtBSJointQuaConstraint(j));
  }
  ChainResult r;
  const double e0 = energy(bodies);
  const int steps = (int)(seconds / 0.01);
  for (int s = 0; s < steps; ++s) {
    MdtWorldStep(w, (MeReal)0.01);
    for (MdtConstraintID j : joints) r.worstGap = std::max(r.worstGap, anchorGap(j));
    r.energyGrowth = std::max(r.energyGrowth, energy(bodies) - e0);
  }
  for (MdtBodyID b : bodies) r.finite = r.finite && bodyFinite(b);
  return r;
}

}  // namespace

TEST(Stability, HangingChainMassRatio100) {
  const ChainResult r = runChain(8, 100, 60);
  std::printf("chain 100:1  worst joint gap %.3g m, energy growth %.3g J\n", r.worstGap, r.energyGrowth);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.worstGap, 0.01);
  EXPECT_LE(r.energyGrowth, 1e-3);  // constraint error correction and epsilon only dissipate
}

TEST(Stability, HangingChainMassRatio1000StaysFinite) {
  const ChainResult r = runChain(8, 1000, 60);
  std::printf("chain 1000:1 worst joint gap %.3g m, energy growth %.3g J\n", r.worstGap, r.energyGrowth);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.worstGap, 0.05);  // beyond the guide's advised 100:1: bounded, not accurate
}

TEST(Stability, WithoutStabilisationTheHeavyChainBlowsUp) {
  // Why MdtWorldSetGeometricStiffness exists: the light links' alignment mode
  // (w^2 ~ tension * lever / inertia) is faster than 2/h at h = 0.01, and the
  // plain velocity-level step feeds it energy until the joints come apart.
  const ChainResult r = runChain(8, 100, 10, 0);
  std::printf("chain 100:1 without stabilisation: worst joint gap %.3g m, energy growth %.3g J\n", r.worstGap,
              r.energyGrowth);
  EXPECT_GT(r.worstGap, 0.05);
}

namespace {

struct RedundantResult {
  double worstGap = 0, energyGrowth = 0;
  int unsolved = 0;
  bool finite = true;
};

// A plate hinged to a heavy post that hangs from the world; with `extra`, two
// ball joints on the hinge axis as well: 11 rows of rank 5 on one pair.
RedundantResult runRedundant(bool extra) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID post = MdtBodyCreate(w);
  MdtBodySetMass(post, 100);
  MdtBodyEnable(post);
  MdtBSJointID fix = MdtBSJointCreate(w);
  MdtBSJointSetBodies(fix, post, nullptr);
  MdtBSJointSetPosition(fix, 0, 0, 0);
  MdtBSJointEnable(fix);
  MdtBodyID plate = MdtBodyCreate(w);
  MdtBodySetPosition(plate, (MeReal)0.5, 0, 0);
  MdtBodyEnable(plate);
  MdtHingeID h = MdtHingeCreate(w);
  MdtHingeSetBodies(h, plate, post);
  MdtHingeSetPosition(h, 0, 0, 0);
  MdtHingeSetAxis(h, 0, 0, 1);
  MdtHingeEnable(h);
  std::vector<MdtConstraintID> joints = {MdtHingeQuaConstraint(h)};
  for (int k = 0; extra && k < 2; ++k) {
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, plate, post);
    MdtBSJointSetPosition(j, 0, 0, k ? (MeReal)0.3 : -(MeReal)0.3);
    MdtBSJointEnable(j);
    joints.push_back(MdtBSJointQuaConstraint(j));
  }
  const std::vector<MdtBodyID> bodies = {post, plate};
  const double e0 = energy(bodies);
  RedundantResult r;
  for (int s = 0; s < 6000; ++s) {
    MdtWorldStep(w, (MeReal)0.01);
    for (MdtConstraintID j : joints) r.worstGap = std::max(r.worstGap, anchorGap(j));
    r.energyGrowth = std::max(r.energyGrowth, energy(bodies) - e0);
    MdtWorldStepStats st;
    MdtWorldGetStepStats(w, &st);
    r.unsolved += st.keaUnsolved;
  }
  r.finite = bodyFinite(plate) && bodyFinite(post);
  return r;
}

}  // namespace

TEST(Stability, RedundantConstraintsOnOnePair) {
  // Epsilon keeps the rank-deficient matrix positive definite: Kea solves
  // every step, and the redundant joints track no worse than the hinge alone
  // (whose error is the velocity-level step's, ~ r w^2 h^2 / (2 gamma)).
  const RedundantResult alone = runRedundant(false);
  const RedundantResult both = runRedundant(true);
  std::printf("hinge alone: gap %.3g m; hinge + 2 ball joints: gap %.3g m, energy growth %.3g J\n", alone.worstGap,
              both.worstGap, both.energyGrowth);
  EXPECT_EQ(both.unsolved, 0);
  EXPECT_TRUE(both.finite);
  EXPECT_LT(both.worstGap, 1.5 * alone.worstGap + 1e-4);
  EXPECT_LT(both.worstGap, 5e-3);
  EXPECT_LE(both.energyGrowth, 1e-3);
}

namespace {

// Small-angle pendulum period in units of sqrt(L/g), in a world whose
// length scale is L (so epsilon, thresholds and inertia defaults scale).
double scaledPeriod(MeReal L) {
  World w(2, L, 1, 2);
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  const MeReal inertia = (MeReal)1e-4 * L * L;
  MeMatrix3 I = {{inertia, 0, 0}, {0, inertia, 0}, {0, 0, inertia}};
  MdtBodySetInertiaTensor(b, I);
  const MeReal th = (MeReal)0.05;
  MdtBodySetPosition(b, L * std::sin(th), -L * std::cos(th), 0);
  MdtBodyEnable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, b, nullptr);
  MdtBSJointSetPosition(j, 0, 0, 0);
  MdtBSJointEnable(j);
  const double unit = std::sqrt((double)L / 9.81);
  const MeReal h = (MeReal)(unit * 2 * M_PI / 240);  // 240 steps per period
  std::vector<double> ups;
  MeVector3 x;
  MdtBodyGetPosition(b, x);
  double prev = x[0];
  for (int i = 1; i <= 240 * 6; ++i) {
    MdtWorldStep(w, h);
    MdtBodyGetPosition(b, x);
    if (prev < 0 && x[0] >= 0) ups.push_back((i - 1 + prev / (prev - x[0])) * (double)h);
    prev = x[0];
  }
  if (ups.size() < 2) return 0;
  return (ups.back() - ups.front()) / (double)(ups.size() - 1) / unit;
}

}  // namespace

TEST(Stability, PendulumBehavesTheSameAtLengthScales) {
  const double small = scaledPeriod((MeReal)0.01);
  const double unit = scaledPeriod(1);
  const double large = scaledPeriod(100);
  std::printf("scaled periods: L=0.01 %.5f, L=1 %.5f, L=100 %.5f (2 pi = %.5f)\n", small, unit, large, 2 * M_PI);
  EXPECT_NEAR(small, unit, 0.01 * unit);
  EXPECT_NEAR(large, unit, 0.01 * unit);
  EXPECT_NEAR(unit, 2 * M_PI, 0.01 * 2 * M_PI);
}
