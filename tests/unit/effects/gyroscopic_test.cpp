// Issue 17: the gyroscopic term is computed only where it can change the
// result (engine/mdt/gyroscopic.cpp), with a per-body switch
// (MdtBodySetGyroscopicMode); damping only where its coefficient is set.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mdt/mdt_test_support.h"

using namespace mdt_test;

namespace {

constexpr MeReal kH = (MeReal)1 / 60;

struct State {
  MeVector3 x, v, w;
  MeVector4 q;
  bool operator==(const State &o) const {
    for (int k = 0; k < 3; ++k)
      if (x[k] != o.x[k] || v[k] != o.v[k] || w[k] != o.w[k]) return false;
    for (int k = 0; k < 4; ++k)
      if (q[k] != o.q[k]) return false;
    return true;
  }
};

State stateOf(MdtBodyID b) {
  State s;
  MdtBodyGetPosition(b, s.x);
  MdtBodyGetLinearVelocity(b, s.v);
  MdtBodyGetAngularVelocity(b, s.w);
  MdtBodyGetQuaternion(b, s.q);
  return s;
}

// The angular velocity in the body's axes: wb[i] = (body axis i) . w.
void bodyRate(MdtBodyID b, MeVector3 wb) {
  MeMatrix3 R;
  MeVector3 w;
  MdtBodyGetOrientation(b, R);
  MdtBodyGetAngularVelocity(b, w);
  for (int i = 0; i < 3; ++i) wb[i] = MeVector3Dot(R[i], w);
}

// A free body (no gravity) with principal moments (i0, i1, i2), tilted so
// that its axes are not the world's, spinning at w (world frame).
struct Spinning {
  World world;
  MdtBodyID body;
  Spinning(MeReal i0, MeReal i1, MeReal i2, const MeVector3 w, MdtGyroscopicMode mode) {
    MdtWorldSetAutoDisable(world, FALSE);
    body = MdtBodyCreate(world);
    MeMatrix3 I = {{i0, 0, 0}, {0, i1, 0}, {0, 0, i2}};
    MdtBodySetInertiaTensor(body, I);
    MdtBodySetQuaternion(body, (MeReal)0.9, (MeReal)0.3, (MeReal)-0.2, (MeReal)0.25);
    MdtBodySetAngularVelocity(body, w[0], w[1], w[2]);
    MdtBodySetLinearVelocity(body, 1, 2, 3);
    MdtBodySetGyroscopicMode(body, mode);
    MdtBodyEnable(body);
  }
  void step(int n) {
    for (int i = 0; i < n; ++i) MdtWorldStep(world, kH);
  }
};

}  // namespace

TEST(Gyroscopic, DefaultsToAuto) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  EXPECT_EQ(MdtBodyGetGyroscopicMode(b), MdtGyroscopicAuto);
  MdtBodySetGyroscopicMode(b, MdtGyroscopicAlways);
  EXPECT_EQ(MdtBodyGetGyroscopicMode(b), MdtGyroscopicAlways);
  MdtBodySetGyroscopicMode(b, MdtGyroscopicNever);
  EXPECT_EQ(MdtBodyGetGyroscopicMode(b), MdtGyroscopicNever);
}

TEST(Gyroscopic, TheSwitchRejectsBadValuesWithAWarning) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetGyroscopicMode(b, MdtGyroscopicNever);
  WarningCapture warnings;
  MdtBodySetGyroscopicMode(b, (MdtGyroscopicMode)3);
  ASSERT_EQ(warnings.count(), 1u);
  EXPECT_TRUE(warnings.lastMentions("MdtBodySetGyroscopicMode"));
  EXPECT_EQ(MdtBodyGetGyroscopicMode(b), MdtGyroscopicNever);  // unchanged
  MdtBodySetGyroscopicMode(b, (MdtGyroscopicMode)-1);
  EXPECT_EQ(warnings.count(), 2u);
  EXPECT_EQ(MdtBodyGetGyroscopicMode(b), MdtGyroscopicNever);
  MdtBodySetGyroscopicMode(nullptr, MdtGyroscopicAuto);
  EXPECT_EQ(warnings.count(), 3u);
  EXPECT_TRUE(warnings.lastMentions("MdtBodySetGyroscopicMode"));
}

TEST(Gyroscopic, ASpinningSphereIsTheSameInEveryMode) {
  // Spherical inertia: L = s w, so the term w x Iw w is exactly zero and the
  // angular velocity of a free sphere stays what it was, bit for bit.
  const MeVector3 w0 = {3, 5, -2};
  Spinning autoMode(2, 2, 2, w0, MdtGyroscopicAuto);
  Spinning always(2, 2, 2, w0, MdtGyroscopicAlways);
  Spinning never(2, 2, 2, w0, MdtGyroscopicNever);
  for (int i = 0; i < 10; ++i) {
    autoMode.step(60);
    always.step(60);
    never.step(60);
    const State a = stateOf(autoMode.body);
    EXPECT_TRUE(a == stateOf(always.body)) << "after " << (i + 1) << " s";
    EXPECT_TRUE(a == stateOf(never.body)) << "after " << (i + 1) << " s";
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.w[k], w0[k]);
  }
}

TEST(Gyroscopic, ALongBoxSpinningAboutItsMiddleAxisFlipsWithAutoAsWithAlways) {
  // The tennis-racket effect: principal moments (3, 2, 1), spin 5 rad/s
  // about the intermediate axis with 0.2% off it. The spin about the middle
  // axis is unstable (growth rate 5 sqrt((3-2)(2-1)/(3*1)) = 2.9 /s), so
  // within 5 s the body-frame rate about that axis turns over to about -5.
  MeVector3 w0;
  {
    // World rate whose body-frame image is (0.01, 5, 0.01).
    const MeVector3 rest = {0, 0, 0};
    Spinning probe(3, 2, 1, rest, MdtGyroscopicAuto);
    MeMatrix3 R;
    MdtBodyGetOrientation(probe.body, R);
    const MeVector3 wb = {(MeReal)0.01, 5, (MeReal)0.01};
    for (int k = 0; k < 3; ++k) w0[k] = wb[0] * R[0][k] + wb[1] * R[1][k] + wb[2] * R[2][k];
  }
  Spinning autoMode(3, 2, 1, w0, MdtGyroscopicAuto);
  Spinning always(3, 2, 1, w0, MdtGyroscopicAlways);
  Spinning never(3, 2, 1, w0, MdtGyroscopicNever);
  MeReal lowest[3] = {5, 5, 5};
  bool same = true;
  for (int i = 0; i < 300; ++i) {
    autoMode.step(1);
    always.step(1);
    never.step(1);
    same = same && stateOf(autoMode.body) == stateOf(always.body);
    Spinning *runs[3] = {&autoMode, &always, &never};
    for (int r = 0; r < 3; ++r) {
      MeVector3 wb;
      bodyRate(runs[r]->body, wb);
      lowest[r] = std::min(lowest[r], wb[1]);
    }
  }
  std::printf("middle-axis spin 5 rad/s, lowest body rate about it in 5 s: auto %.3f, always %.3f, never %.3f\n",
              (double)lowest[0], (double)lowest[1], (double)lowest[2]);
  EXPECT_LT(lowest[0], -4.5);  // flipped
  EXPECT_LT(lowest[1], -4.5);
  EXPECT_GT(lowest[2], 4.9);  // without the term: no flip
  EXPECT_TRUE(same);          // the term matters here every step: Auto computes it as Always does
}

TEST(Gyroscopic, ASpinExactlyAboutAPrincipalAxisLeavesItOut) {
  // With w exactly along a principal axis (here the body's z, rotated to
  // the world's z, stable), w x Iw w = 0: Auto does what Never does, and
  // Always, which computes it, stays within rounding of that.
  World worlds[3];
  MdtBodyID bodies[3];
  const MdtGyroscopicMode modes[3] = {MdtGyroscopicAuto, MdtGyroscopicNever, MdtGyroscopicAlways};
  for (int r = 0; r < 3; ++r) {
    MdtWorldSetAutoDisable(worlds[r], FALSE);
    bodies[r] = MdtBodyCreate(worlds[r]);
    MeMatrix3 I = {{3, 0, 0}, {0, 2, 0}, {0, 0, 1}};
    MdtBodySetInertiaTensor(bodies[r], I);
    MdtBodySetAngularVelocity(bodies[r], 0, 0, 4);
    MdtBodySetGyroscopicMode(bodies[r], modes[r]);
    MdtBodyEnable(bodies[r]);
  }
  for (int i = 0; i < 300; ++i)
    for (int r = 0; r < 3; ++r) MdtWorldStep(worlds[r], kH);
  const State a = stateOf(bodies[0]), n = stateOf(bodies[1]), al = stateOf(bodies[2]);
  EXPECT_TRUE(a == n);
  EXPECT_EQ(a.w[2], 4);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(al.q[k], a.q[k], 1e-4);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(al.w[k], a.w[k], 1e-4);
}

TEST(Gyroscopic, AutoKeepsTheAngularMomentumOfATumblingBody) {
  // Where the term acts Auto computes it: the world angular momentum of a
  // free body with distinct moments stays fixed (Always is tested equal to
  // Auto above; Never lets it wander).
  const MeVector3 w0 = {1, 2, 3};
  Spinning s(3, 2, 1, w0, MdtGyroscopicAuto);
  auto momentum = [&](MeVector3 L) {
    MeMatrix3 R;
    MeVector3 w, wb;
    MdtBodyGetOrientation(s.body, R);
    MdtBodyGetAngularVelocity(s.body, w);
    for (int i = 0; i < 3; ++i) wb[i] = MeVector3Dot(R[i], w);
    const MeReal I[3] = {3, 2, 1};
    for (int k = 0; k < 3; ++k) L[k] = I[0] * wb[0] * R[0][k] + I[1] * wb[1] * R[1][k] + I[2] * wb[2] * R[2][k];
  };
  MeVector3 L0, L1;
  momentum(L0);
  s.step(600);
  momentum(L1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(L1[k], L0[k], 1e-3 * MeVector3Magnitude(L0));
}

TEST(Damping, ZeroDampingLeavesAFreeBodyExactlyAlone) {
  // No damping, no gravity: the velocities stay exactly what they were; with
  // damping d the linear speed of a unit mass falls as (1 - d h) per step.
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetMass(b, 1);
  MdtBodySetLinearVelocity(b, 1, -2, 3);
  MdtBodyEnable(b);
  for (int i = 0; i < 60; ++i) MdtWorldStep(w, kH);
  MeVector3 v;
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], -2);
  EXPECT_EQ(v[2], 3);
  MdtBodySetLinearVelocityDamping(b, (MeReal)0.5);
  for (int i = 0; i < 60; ++i) MdtWorldStep(w, kH);
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_NEAR(v[0], std::pow(1 - 0.5 / 60, 60), 1e-5);
}
