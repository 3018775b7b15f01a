// Skeletal: the elliptical swing cone (both half-angles), the twist limit,
// soft limits, and bad input.
#include <algorithm>
#include <cmath>

#include "joints_b_support.h"

using namespace mdt_test;

namespace {

// A base pinned to the world at the origin and a limb whose centre is 0.5
// along x, joined at the origin; cone axis x, secondary y. No gravity.
struct Limb {
  World w;
  MdtBodyID base, limb;
  MdtSkeletalID j;
  Limb() {
    MdtWorldSetGravity(w, 0, 0, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    base = makeBody(w, 0, 0, 0);
    pinToWorld(w, base);
    limb = makeBody(w, (MeReal)0.5, 0, 0);
    j = MdtSkeletalCreate(w);
    MdtSkeletalSetBodies(j, base, limb);
    MdtSkeletalSetPosition(j, 0, 0, 0);
    MdtSkeletalSetAxes(j, 1, 0, 0, 0, 1, 0);
    MdtSkeletalSetConePrimaryLimitAngle(j, (MeReal)0.3);
    MdtSkeletalSetConeSecondaryLimitAngle(j, (MeReal)0.6);
    MdtSkeletalSetTwistLimitAngle(j, (MeReal)0.4);
    MdtSkeletalEnable(j);
  }
  // Pushes the limb with a world torque for n steps; returns the largest
  // swing angle seen.
  double push(MeReal tx, MeReal ty, MeReal tz, int n) {
    double worst = 0;
    for (int i = 0; i < n; ++i) {
      MdtBodyAddTorque(limb, tx, ty, tz);
      MdtWorldStep(w, (MeReal)0.01);
      worst = std::max(worst, (double)MdtSkeletalGetSwingAngle(j));
    }
    return worst;
  }
  // The limb's x axis in the base frame.
  void axis(MeVector3 out) const { directionIn(limb, base, 1, 0, 0, out); }
};

}  // namespace

TEST(Skeletal, Defaults) {
  World w;
  MdtBodyID b = makeBody(w, 0, 0, 0);
  MdtSkeletalID j = MdtSkeletalCreate(w);
  MdtSkeletalSetBodies(j, b, nullptr);
  EXPECT_NEAR(MdtSkeletalGetConePrimaryLimitAngle(j), M_PI / 4, 1e-6);
  EXPECT_NEAR(MdtSkeletalGetConeSecondaryLimitAngle(j), M_PI / 4, 1e-6);
  EXPECT_NEAR(MdtSkeletalGetTwistLimitAngle(j), M_PI / 4, 1e-6);
  EXPECT_EQ(MdtSkeletalGetConeStiffness(j), MEINFINITY);
  EXPECT_EQ(MdtSkeletalGetTwistStiffness(j), MEINFINITY);
  EXPECT_EQ(MdtSkeletalGetConeDamping(j), 0);
  EXPECT_EQ(MdtConstraintDCastSkeletal(MdtSkeletalQuaConstraint(j)), j);
}

TEST(Skeletal, PrimarySwingStopsAtThePrimaryHalfAngle) {
  // A torque about z swings the limb's axis towards y (psi = 0): limit P.
  Limb l;
  const double worst = l.push(0, 0, 5, 200);
  RecordProperty("primary_swing_rad", std::to_string(MdtSkeletalGetSwingAngle(l.j)));
  EXPECT_NEAR(MdtSkeletalGetSwingAngle(l.j), 0.3, 2e-3);
  EXPECT_LT(worst, 0.3 + 5e-3);
  MeVector3 a;
  l.axis(a);
  EXPECT_NEAR(std::atan2(a[1], a[0]), 0.3, 2e-3);  // towards +y
  EXPECT_NEAR(a[2], 0, 1e-3);
  EXPECT_LT(anchorGap(MdtSkeletalQuaConstraint(l.j)), 1e-3);
}

TEST(Skeletal, SecondarySwingStopsAtTheSecondaryHalfAngle) {
  // A torque about -y swings it towards z (psi = pi/2): limit S.
  Limb l;
  const double worst = l.push(0, -5, 0, 200);
  RecordProperty("secondary_swing_rad", std::to_string(MdtSkeletalGetSwingAngle(l.j)));
  EXPECT_NEAR(MdtSkeletalGetSwingAngle(l.j), 0.6, 3e-3);
  EXPECT_LT(worst, 0.6 + 5e-3);
  MeVector3 a;
  l.axis(a);
  EXPECT_NEAR(std::atan2(a[2], a[0]), 0.6, 3e-3);
}

TEST(Skeletal, DiagonalSwingStopsOnTheEllipse) {
  // Pushed towards psi = 45 degrees, the axis ends on the ellipse
  // 1 / sqrt(cos^2/P^2 + sin^2/S^2) (it may slide along the cone, so check
  // the ellipse equation at whatever psi it settles).
  Limb l;
  l.push(0, -4, 4, 300);
  MeVector3 a;
  l.axis(a);
  const double theta = std::atan2(std::hypot(a[1], a[2]), a[0]);
  const double psi = std::atan2(a[2], a[1]);
  const double r = 1 / std::sqrt(std::pow(std::cos(psi) / 0.3, 2) + std::pow(std::sin(psi) / 0.6, 2));
  EXPECT_NEAR(theta, r, 5e-3);
  EXPECT_GT(psi, 0.1);  // strictly between the two axes
  EXPECT_LT(psi, M_PI / 2 - 0.1);
}

TEST(Skeletal, TwistStopsAtItsLimitBothWays) {
  Limb l;
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    MdtBodyAddTorque(l.limb, 3, 0, 0);  // about the limb's own axis
    MdtWorldStep(l.w, (MeReal)0.01);
    worst = std::max(worst, (double)MdtSkeletalGetTwistAngle(l.j));
  }
  RecordProperty("twist_rad", std::to_string(MdtSkeletalGetTwistAngle(l.j)));
  EXPECT_NEAR(MdtSkeletalGetTwistAngle(l.j), 0.4, 2e-3);
  EXPECT_LT(worst, 0.4 + 5e-3);
  for (int i = 0; i < 300; ++i) {
    MdtBodyAddTorque(l.limb, -3, 0, 0);
    MdtWorldStep(l.w, (MeReal)0.01);
  }
  EXPECT_NEAR(MdtSkeletalGetTwistAngle(l.j), -0.4, 2e-3);
  EXPECT_LT(MdtSkeletalGetSwingAngle(l.j), 1e-3);  // twisting does not swing
}

TEST(Skeletal, TwistLimitHoldsWhileSwung) {
  // Swung to the primary limit and twisted about the limb's own axis.
  Limb l;
  for (int i = 0; i < 300; ++i) {
    MeVector3 a;
    bodyDirection(l.limb, 1, 0, 0, a);
    MdtBodyAddTorque(l.limb, 3 * a[0], 3 * a[1], 5 + 3 * a[2]);
    MdtWorldStep(l.w, (MeReal)0.01);
  }
  EXPECT_NEAR(MdtSkeletalGetTwistAngle(l.j), 0.4, 5e-3);
  EXPECT_NEAR(MdtSkeletalGetSwingAngle(l.j), 0.3, 5e-3);
}

TEST(Skeletal, SoftConeGivesWayByTorqueOverStiffness) {
  // Stiffness 50 N m/rad, damping 5: a 5 N m push settles 0.1 rad past P.
  Limb l;
  MdtSkeletalSetConeStiffness(l.j, 50);
  MdtSkeletalSetConeDamping(l.j, 5);
  l.push(0, 0, 5, 500);
  EXPECT_NEAR(MdtSkeletalGetSwingAngle(l.j), 0.3 + 0.1, 0.05 * 0.1);
}

TEST(Skeletal, BadInputIsRejectedWithAWarning) {
  WarningCapture warnings;
  Limb l;
  MdtSkeletalSetConePrimaryLimitAngle(l.j, 0);
  EXPECT_NE(warnings.last().find("MdtSkeletalSetConePrimaryLimitAngle"), std::string::npos);
  MdtSkeletalSetConeSecondaryLimitAngle(l.j, NAN);
  MdtSkeletalSetTwistLimitAngle(l.j, 4);
  EXPECT_NE(warnings.last().find("MdtSkeletalSetTwistLimitAngle"), std::string::npos);
  MdtSkeletalSetConeStiffness(l.j, -1);
  EXPECT_NE(warnings.last().find("must be >= 0"), std::string::npos);
  MdtSkeletalSetTwistDamping(l.j, NAN);
  MdtSkeletalSetAxes(l.j, 1, 0, 0, 1, 0, 0);
  EXPECT_NE(warnings.last().find("not orthogonal"), std::string::npos);
  EXPECT_NEAR(MdtSkeletalGetConePrimaryLimitAngle(l.j), 0.3, 1e-6);
  EXPECT_NEAR(MdtSkeletalGetConeSecondaryLimitAngle(l.j), 0.6, 1e-6);
  EXPECT_NEAR(MdtSkeletalGetTwistLimitAngle(l.j), 0.4, 1e-6);
  EXPECT_EQ(MdtSkeletalGetConeStiffness(l.j), MEINFINITY);
  EXPECT_EQ(MdtSkeletalGetTwistDamping(l.j), 0);
  EXPECT_EQ(MdtSkeletalGetSwingAngle(nullptr), 0);
}
