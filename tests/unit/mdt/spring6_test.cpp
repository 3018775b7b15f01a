// Spring6: per-axis linear and angular stiffness against the static
// offsets F / K and T / K, locked and free axes, and bad input.
#include <cmath>

#include "joints_b_support.h"

using namespace mdt_test;

namespace {

// A unit mass (inertia 0.4) at the origin on a Spring6 to the world, frame
// axes x, y; linear stiffness K = (100, 200, 400), damping 20 on each, all
// angular axes locked. Gravity off unless set.
struct Mount {
  World w;
  MdtBodyID b;
  MdtSpring6ID j;
  Mount() {
    MdtWorldSetGravity(w, 0, 0, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    b = makeBody(w, 0, 0, 0);
    j = MdtSpring6Create(w);
    MdtSpring6SetBodies(j, b, nullptr);
    MdtSpring6SetPosition(j, 0, 0, 0);
    MdtSpring6SetAxes(j, 1, 0, 0, 0, 1, 0);
    const MeReal k[3] = {100, 200, 400};
    for (unsigned a = 0; a < 3; ++a) {
      MdtSpring6SetLinearStiffness(j, a, k[a]);
      MdtSpring6SetLinearDamping(j, a, 20);
    }
    MdtSpring6Enable(j);
  }
  void run(int n, const MeVector3 f, const MeVector3 t) {
    for (int i = 0; i < n; ++i) {
      MdtBodyAddForce(b, f[0], f[1], f[2]);
      MdtBodyAddTorque(b, t[0], t[1], t[2]);
      MdtWorldStep(w, (MeReal)0.01);
    }
  }
};

}  // namespace

TEST(Spring6, DefaultsLockAllSixAxes) {
  Mount m;
  for (unsigned a = 0; a < 3; ++a) {
    EXPECT_EQ(MdtSpring6GetAngularStiffness(m.j, a), MEINFINITY);
    EXPECT_EQ(MdtSpring6GetAngularDamping(m.j, a), MEINFINITY);
  }
  MdtSpring6Reset(m.j);
  for (unsigned a = 0; a < 3; ++a) EXPECT_EQ(MdtSpring6GetLinearStiffness(m.j, a), MEINFINITY);
  const MeVector3 f = {3, -2, 1}, t = {(MeReal)0.5, (MeReal)0.2, -(MeReal)0.3};
  m.run(100, f, t);
  MeVector3 x;
  MdtBodyGetPosition(m.b, x);
  EXPECT_LT(MeVector3Magnitude(x), 1e-3);
  EXPECT_LT(rotationAngle(m.b), 1e-3);
  EXPECT_EQ(MdtConstraintDCastSpring6(MdtSpring6QuaConstraint(m.j)), m.j);
}

TEST(Spring6, LinearOffsetIsForceOverStiffnessOnEachAxis) {
  const double k[3] = {100, 200, 400};
  for (int axis = 0; axis < 3; ++axis) {
    Mount m;
    MeVector3 f = {0, 0, 0};
    const MeVector3 t = {0, 0, 0};
    f[axis] = 5;
    m.run(400, f, t);
    MeVector3 x;
    MdtBodyGetPosition(m.b, x);
    const double expected = 5 / k[axis];
    EXPECT_NEAR(x[axis], expected, 0.05 * expected) << "axis " << axis;
    EXPECT_LT(std::fabs(x[(axis + 1) % 3]), 1e-4);
    EXPECT_LT(std::fabs(x[(axis + 2) % 3]), 1e-4);
    EXPECT_LT(rotationAngle(m.b), 1e-3);
  }
}

TEST(Spring6, AngularOffsetIsTorqueOverStiffness) {
  // Angular stiffness 10 about z (damping 2): 1 N m turns it 0.1 rad; the
  // rotation vector makes this exact also for a larger 0.8 rad.
  for (const MeReal torque : {(MeReal)1, (MeReal)8}) {
    Mount m;
    MdtSpring6SetAngularStiffness(m.j, 2, 10);
    MdtSpring6SetAngularDamping(m.j, 2, 2);
    const MeVector3 f = {0, 0, 0}, t = {0, 0, torque};
    m.run(500, f, t);
    const double expected = torque / 10.0;
    EXPECT_NEAR(rotationAngle(m.b), expected, 0.05 * expected);
    MeVector3 y;
    bodyDirection(m.b, 0, 1, 0, y);
    EXPECT_NEAR(y[2], 0, 1e-3);  // the turn is about z only
  }
}

TEST(Spring6, FreeAxisLetsGo) {
  // Stiffness 0 and no damping on linear x: a force accelerates it freely.
  Mount m;
  MdtSpring6SetLinearStiffness(m.j, 0, 0);
  MdtSpring6SetLinearDamping(m.j, 0, 0);
  const MeVector3 f = {2, 0, 0}, t = {0, 0, 0};
  m.run(100, f, t);
  MeVector3 v;
  MdtBodyGetLinearVelocity(m.b, v);
  EXPECT_NEAR(v[0], 2.0, 1e-3);
}

TEST(Spring6, BadInputIsRejectedWithAWarning) {
  WarningCapture warnings;
  Mount m;
  MdtSpring6SetLinearStiffness(m.j, 0, -5);
  EXPECT_NE(warnings.last().find("MdtSpring6SetLinearStiffness"), std::string::npos);
  EXPECT_EQ(MdtSpring6GetLinearStiffness(m.j, 0), 100);
  MdtSpring6SetAngularDamping(m.j, 1, NAN);
  EXPECT_NE(warnings.last().find("MdtSpring6SetAngularDamping"), std::string::npos);
  MdtSpring6SetAngularStiffness(m.j, 3, 1);
  EXPECT_NE(warnings.last().find("axis 3"), std::string::npos);
  EXPECT_EQ(MdtSpring6GetAngularStiffness(m.j, 7), 0);
  MdtSpring6SetAxes(m.j, 0, 0, 0, 0, 1, 0);
  EXPECT_NE(warnings.last().find("MdtSpring6SetAxes"), std::string::npos);
  MdtSpring6SetLinearStiffness(nullptr, 0, 1);
  EXPECT_NE(warnings.last().find("NULL"), std::string::npos);
  MeVector3 p, o;
  MdtSpring6GetAxes(m.j, p, o);
  EXPECT_NEAR(p[0], 1, 1e-6);
}
