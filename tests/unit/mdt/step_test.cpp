// step_test.cpp: the unconstrained step against closed forms.
#include <cstring>
#include <vector>

#include "mdt_test_support.h"

using namespace mdt_test;

// The guide's basic-steps program: one unit body, gravity (-0.3, -0.3, 0),
// 599 steps of 0.01 s. Semi-implicit Euler from rest gives
// v_n = n h g and x_n = x_0 + h^2 g n (n + 1) / 2.
TEST(MdtStep, BasicStepsMatchesSemiImplicitEulerClosedForm) {
  World w(1, 0 + 1, 1);
  MdtWorldSetGravity(w, -(MeReal)0.3, -(MeReal)0.3, 0);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  const MeReal h = (MeReal)0.01;
  const int steps = 599;
  for (int i = 0; i < steps; ++i) MdtWorldStep(w, h);
  MeVector3 x, v, a;
  MdtBodyGetPosition(b, x);
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetLinearAcceleration(b, a);
  const double hd = (double)h, n = steps;
  const double xExpect = hd * hd * -0.3 * n * (n + 1) / 2;
  const double vExpect = n * hd * -0.3;
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(x[k], xExpect, tol(std::fabs(xExpect), n)) << k;
    EXPECT_NEAR(v[k], vExpect, tol(std::fabs(vExpect), n)) << k;
    EXPECT_NEAR(a[k], -0.3, tol(0.3, 1e4)) << k;
  }
  EXPECT_EQ(x[2], 0);
  EXPECT_EQ(v[2], 0);
  MeVector4 q;
  MdtBodyGetQuaternion(b, q);
  EXPECT_TRUE(q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0);
  EXPECT_EQ(MdtBodyGetTransformPtr(b)[3][0], x[0]);
}

TEST(MdtStep, DisabledBodiesDoNotMoveAndKeepTheirForces) {
  World w(2);
  // The guide's Q&A reading: a force does not enable a body (by default it
  // does, the chapter's reading; MdtWorld.h, "Waking by force").
  MdtWorldSetWakeByForce(w, 0);
  MdtWorldSetGravity(w, 0, -10, 0);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 2, 3);
  MdtBodySetLinearVelocity(b, 1, 1, 1);
  MdtBodyAddForce(b, 5, 0, 0);
  MeMatrix4 before;
  MdtBodyGetTransform(b, before);
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.1);
  EXPECT_EQ(std::memcmp(before, MdtBodyGetTransformPtr(b), sizeof before), 0);
  MeVector3 f;
  MdtBodyGetForce(b, f);
  EXPECT_EQ(f[0], 5);  // waits for the first step in which the body is enabled
  MdtBodyEnable(b);
  MdtWorldSetGravity(w, 0, 0, 0);
  MdtBodySetLinearVelocity(b, 0, 0, 0);
  MdtWorldStep(w, (MeReal)0.5);
  MeVector3 v;
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_EQ(v[0], (MeReal)2.5);  // h F / m
  MdtBodyGetForce(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
}

TEST(MdtStep, AccumulatorsClearedAfterStep) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtBodyAddForce(b, 1, 2, 3);
  MdtBodyAddForce(b, 1, 0, 0);
  MdtBodyAddTorque(b, 0, 1, 0);
  MdtBodyAddImpulse(b, 0, 0, 1);
  MdtBodyAddImpulseAtPosition(b, 0, 1, 0, 1, 0, 0);
  MeVector3 f;
  MdtBodyGetForce(b, f);
  EXPECT_TRUE(f[0] == 2 && f[1] == 2 && f[2] == 3);
  MdtWorldStep(w, (MeReal)0.01);
  MdtBodyGetForce(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  MdtBodyGetTorque(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  MdtBodyGetImpulse(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  MdtBodyGetAngularImpulse(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  // Explicit resets.
  MdtBodyAddForce(b, 1, 0, 0);
  MdtBodyAddImpulse(b, 1, 0, 0);
  MdtBodyResetForces(b);
  MdtBodyResetImpulses(b);
  MdtBodyGetForce(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  MdtBodyGetImpulse(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
}

TEST(MdtStep, ImpulseChangesVelocityByJOverMIndependentOfStep) {
  for (MeReal h : {(MeReal)0.001, (MeReal)0.1}) {
    World w;
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetMass(b, 4);
    MdtBodyEnable(b);
    MdtBodyAddImpulse(b, 2, 0, -8);
    MdtWorldStep(w, h);
    MeVector3 v;
    MdtBodyGetLinearVelocity(b, v);
    EXPECT_EQ(v[0], (MeReal)0.5);
    EXPECT_EQ(v[2], -2);
    MdtWorldStep(w, h);  // used once only
    MdtBodyGetLinearVelocity(b, v);
    EXPECT_EQ(v[0], (MeReal)0.5);
  }
}

TEST(MdtStep, ForceAtPositionGivesTorqueRCrossF) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 1, 1);
  MdtBodyAddForceAtPosition(b, 0, 3, 0, 3, 1, 1);  // r = (2,0,0), F = (0,3,0)
  MeVector3 f, t;
  MdtBodyGetForce(b, f);
  MdtBodyGetTorque(b, t);
  EXPECT_TRUE(f[0] == 0 && f[1] == 3 && f[2] == 0);
  EXPECT_TRUE(t[0] == 0 && t[1] == 0 && t[2] == 6);
  // With I = 0.4 I and h = 0.1, one step gives w_z = h * 6 / 0.4.
  MdtBodyEnable(b);
  MdtWorldStep(w, (MeReal)0.1);
  MeVector3 wv;
  MdtBodyGetAngularVelocity(b, wv);
  EXPECT_NEAR(wv[2], 1.5, 1e-5);
  EXPECT_NEAR(wv[0], 0, 1e-7);
}

// Spin about a principal axis of an asymmetric body, in a turned frame:
// angular momentum and angular velocity stay put and the orientation turns
// at omega.
TEST(MdtStep, TorqueFreeSpinAboutPrincipalAxis) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MeMatrix3 I = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  MdtBodySetInertiaTensor(b, I);
  MeMatrix3 R;
  MeMatrix3FromEulerAngles(R, (MeReal)0.3, (MeReal)-0.7, (MeReal)1.1);
  MdtBodySetOrientation(b, R);
  MeVector4 q0;
  MdtBodyGetQuaternion(b, q0);
  const MeReal speed = 5;
  MeVector3 axis;
  MeVector3Copy(axis, MdtBodyGetTransformPtr(b)[1]);  // body y in world
  MdtBodySetAngularVelocity(b, speed * axis[0], speed * axis[1], speed * axis[2]);
  MdtBodyEnable(b);
  const MeReal h = (MeReal)0.01;
  const int steps = 200;
  for (int i = 0; i < steps; ++i) MdtWorldStep(w, h);
  MeVector3 wv;
  MdtBodyGetAngularVelocity(b, wv);
  EXPECT_NEAR(MeVector3Magnitude(wv), speed, 1e-3);
  // |L| = I_yy |w|.
  EXPECT_NEAR(2 * MeVector3Magnitude(wv), 2 * speed, 2e-3);
  MeVector4 expect, turn, q;
  MeQuaternionMake(turn, axis, speed * h * steps);
  MeQuaternionMultiply(expect, q0, turn);
  MdtBodyGetQuaternion(b, q);
  const MeReal sign = MeVector4Dot(q, expect) < 0 ? -1 : 1;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(q[k], sign * expect[k], 2e-4) << k;
}

TEST(MdtStep, DampingDecaysVelocityGeometrically) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetMass(b, 2);
  MdtBodySetLinearVelocityDamping(b, (MeReal)0.5);
  MdtBodySetAngularVelocityDamping(b, (MeReal)0.1);
  MdtBodySetLinearVelocity(b, 3, 0, 0);
  MdtBodySetAngularVelocity(b, 0, 0, 4);
  MdtBodyEnable(b);
  const MeReal h = (MeReal)0.02;
  const int steps = 100;
  for (int i = 0; i < steps; ++i) MdtWorldStep(w, h);
  MeVector3 v, wv;
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, wv);
  // v_n = v_0 (1 - h c / m)^n, w_n = w_0 (1 - h c / I)^n with I = 0.4.
  EXPECT_NEAR(v[0], 3 * std::pow(1 - 0.02 * 0.5 / 2, steps), 1e-4);
  EXPECT_NEAR(wv[2], 4 * std::pow(1 - 0.02 * 0.1 / 0.4, steps), 1e-4);
}

TEST(MdtStep, FastSpinAxisAlongOmegaMatchesPlainRotation) {
  World w(2);
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetFastSpinAxis(b, 1, 0, 0);
  for (MdtBodyID x : {a, b}) {
    MdtBodySetAngularVelocity(x, 50, 0, 0);
    MdtBodyEnable(x);
  }
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.01);
  MeVector4 qa, qb;
  MdtBodyGetQuaternion(a, qa);
  MdtBodyGetQuaternion(b, qb);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(qa[k], qb[k], 1e-6);
  // With an off-axis part the result stays a unit quaternion.
  MdtBodySetAngularVelocity(b, 50, (MeReal)0.1, 0);
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.01);
  MdtBodyGetQuaternion(b, qb);
  EXPECT_TRUE(MeQuaternionIsUnit(qb, (MeReal)1e-5));
}

namespace {

// Runs a small scene and returns the raw bytes of every body's state.
std::vector<unsigned char> runScene() {
  World w(6);
  MdtWorldSetGravity(w, 0, (MeReal)-9.81, (MeReal)0.5);
  std::vector<MdtBodyID> bodies;
  for (int i = 0; i < 6; ++i) {
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetSortKey(b, (i * 7) % 3);
    MdtBodySetPosition(b, (MeReal)i, (MeReal)(i * i), 0);
    MdtBodySetAngularVelocity(b, (MeReal)(0.3 * i), 1, (MeReal)-0.2);
    MeMatrix3 I = {{1, (MeReal)0.1, 0}, {(MeReal)0.1, 2, 0}, {0, 0, (MeReal)(3 + i)}};
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetLinearVelocityDamping(b, (MeReal)0.01 * i);
    MdtBodyEnable(b);
    bodies.push_back(b);
  }
  std::vector<unsigned char> out;
  for (int s = 0; s < 300; ++s) {
    for (int i = 0; i < 6; ++i) MdtBodyAddForceAtPosition(bodies[i], 1, 0, (MeReal)(0.1 * i), 0, 1, 0);
    MdtWorldStep(w, (MeReal)(1.0 / 60));
  }
  for (MdtBodyID b : bodies) {
    MeVector3 v, wv, a;
    MeVector4 q;
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, wv);
    MdtBodyGetAngularAcceleration(b, a);
    MdtBodyGetQuaternion(b, q);
    auto put = [&out](const void *p, size_t n) {
      const auto *c = static_cast<const unsigned char *>(p);
      out.insert(out.end(), c, c + n);
    };
    put(MdtBodyGetTransformPtr(b), sizeof(MeMatrix4));
    put(v, sizeof v);
    put(wv, sizeof wv);
    put(a, sizeof a);
    put(q, sizeof q);
  }
  return out;
}

}  // namespace

TEST(MdtStep, TwoIdenticalRunsAreBitIdentical) {
  const std::vector<unsigned char> a = runScene();
  const std::vector<unsigned char> b = runScene();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size()), 0);
}
