// Centre of mass offset from the body frame.
#include <cmath>

#include "mdt_test_support.h"

using namespace mdt_test;

TEST(CenterOfMass, DefaultsAtOriginAndRoundTrips) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MeVector3 c;
  MdtBodyGetCenterOfMassRelativePosition(b, c);
  EXPECT_EQ(c[0], 0);
  const MeVector3 off = {1, 2, 3};
  MdtBodySetCenterOfMassRelativePosition(b, off);
  MdtBodySetPosition(b, 10, 0, 0);
  MdtBodyGetCenterOfMassPosition(b, c);
  EXPECT_EQ(c[0], 11);
  EXPECT_EQ(c[2], 3);
  WarningCapture cap;
  MeMatrix4 bad = {{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  MdtBodySetCenterOfMassRelativeTransform(b, bad);
  EXPECT_EQ(cap.count(), 1u);
}

TEST(CenterOfMass, PendulumSwingsAboutTheOffsetCentreOfMass) {
  // The joint sits at the body origin; the mass is 0.5 below it (point-like).
  // Small-angle period 2 pi sqrt(0.5 / g).
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)9.81, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  const MeVector3 off = {0, -(MeReal)0.5, 0};
  MdtBodySetCenterOfMassRelativePosition(b, off);
  MeMatrix3 I = {{1e-4f, 0, 0}, {0, 1e-4f, 0}, {0, 0, 1e-4f}};
  MdtBodySetInertiaTensor(b, I);
  MdtBodyEnable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, b, nullptr);
  MdtBSJointSetPosition(j, 0, 0, 0);
  MdtBSJointEnable(j);
  MdtBodySetAngularVelocity(b, 0, 0, (MeReal)0.2);  // kick
  std::vector<double> ups;
  MeVector3 c;
  MdtBodyGetCenterOfMassPosition(b, c);
  double prev = c[0];
  const MeReal h = (MeReal)1 / 240;
  for (int i = 1; i <= 240 * 6; ++i) {
    MdtWorldStep(w, h);
    MdtBodyGetCenterOfMassPosition(b, c);
    if (prev < 0 && c[0] >= 0) ups.push_back((i - 1 + prev / (prev - c[0])) * (double)h);
    prev = c[0];
  }
  ASSERT_GE(ups.size(), 3u);
  const double T = (ups.back() - ups.front()) / (double)(ups.size() - 1);
  const double expected = 2 * M_PI * std::sqrt(0.5 / 9.81);
  EXPECT_NEAR(T, expected, 0.01 * expected);
  // The body origin stays at the joint.
  MeVector3 x;
  MdtBodyGetPosition(b, x);
  EXPECT_LT(MeVector3Magnitude(x), 1e-3);
}

TEST(CenterOfMass, ForceAtTheBodyOriginTurnsAnOffsetBody) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = MdtBodyCreate(w);
  const MeVector3 off = {1, 0, 0};
  MdtBodySetCenterOfMassRelativePosition(b, off);
  MdtBodyEnable(b);
  // Force +y at the origin, 1 m from the centre of mass: torque -1 about z.
  MdtBodyAddForceAtPosition(b, 0, 1, 0, 0, 0, 0);
  MdtWorldStep(w, (MeReal)0.1);
  MeVector3 wv, v;
  MdtBodyGetAngularVelocity(b, wv);
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_NEAR(wv[2], -0.1 / 0.4, 1e-5);  // tau h / I, I = 0.4
  EXPECT_NEAR(v[1], 0.1, 1e-6);
}
