// The gyroscopic term on a free disc spinning at spin * h = 1 with a small
// wobble. Explicit Euler would multiply the wobble by sqrt(1 + (h Omega)^2)
// = sqrt(2) per step (Omega = spin (Is - Ia) / Ia); the linearly implicit
// term (every body, integrate.cpp) cannot let it grow, with or without a
// fast-spin axis, and never adds kinetic energy.
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

namespace {

struct Disc {
  World w;
  MdtBodyID b;
  Disc() {
    MdtWorldSetGravity(w, 0, 0, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    b = makeBody(w, 0, 0, 0);
    const MeMatrix3 I = {{(MeReal)0.25, 0, 0}, {0, (MeReal)0.5, 0}, {0, 0, (MeReal)0.25}};
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetAngularVelocity(b, (MeReal)0.1, 100, 0);
  }
  double wobble() const {
    MeVector3 w, y;
    MdtBodyGetAngularVelocity(b, w);
    bodyDirection(b, 0, 1, 0, y);
    const double spin = MeVector3Dot(w, y);
    MeVector3MultiplyAdd(w, -(MeReal)spin, y);
    return MeVector3Magnitude(w);
  }
  // (1/2) w . Iw w, from the body-frame inertia diag(0.25, 0.5, 0.25).
  double kineticEnergy() const {
    MeVector3 w, x, y, z;
    MdtBodyGetAngularVelocity(b, w);
    bodyDirection(b, 1, 0, 0, x);
    bodyDirection(b, 0, 1, 0, y);
    bodyDirection(b, 0, 0, 1, z);
    const double wx = MeVector3Dot(w, x), wy = MeVector3Dot(w, y), wz = MeVector3Dot(w, z);
    return 0.5 * (0.25 * wx * wx + 0.5 * wy * wy + 0.25 * wz * wz);
  }
  double spin() const {
    MeVector3 w, y;
    MdtBodyGetAngularVelocity(b, w);
    bodyDirection(b, 0, 1, 0, y);
    return MeVector3Dot(w, y);
  }
};

}  // namespace

TEST(FastSpin, ImplicitGyroscopicTermKeepsAFreeSpinnerBounded) {
  Disc d;
  for (int i = 0; i < 1000; ++i) {
    MeVector3 y;
    bodyDirection(d.b, 0, 1, 0, y);
    MdtBodySetFastSpinAxis(d.b, y[0], y[1], y[2]);
    MdtWorldStep(d.w, (MeReal)0.01);
    ASSERT_TRUE(bodyFinite(d.b)) << "step " << i;
    ASSERT_LE(d.wobble(), 0.1 * (1 + 1e-4)) << "step " << i;
  }
  EXPECT_NEAR(d.spin(), 100, 0.1);  // the spin itself is kept
  EXPECT_TRUE(MdtBodyIsEnabled(d.b));
}

TEST(FastSpin, WithoutAFastSpinAxisTheSpinnerStaysBoundedToo) {
  // Before 2026-11-30 the term was explicit here and this disc overflowed
  // within 200 steps (wobble x32 after 10); a rag doll's rolling capsule
  // limb tore the doll apart the same way.
  Disc d;
  double energy = d.kineticEnergy();
  for (int i = 0; i < 1000; ++i) {
    MdtWorldStep(d.w, (MeReal)0.01);
    ASSERT_TRUE(bodyFinite(d.b)) << "step " << i;
    ASSERT_LE(d.wobble(), 0.1 * (1 + 1e-4)) << "step " << i;
    const double e = d.kineticEnergy();
    ASSERT_LE(e, energy * (1 + 1e-5)) << "step " << i;  // rounding only
    energy = e;
  }
  EXPECT_NEAR(d.spin(), 100, 0.1);
  EXPECT_TRUE(MdtBodyIsEnabled(d.b));
}

TEST(FastSpin, SlowPrecessionKeepsItsWobble) {
  // At h Omega = 0.01 the implicit term's damping, 1 - (h Omega)^2 / 2 per
  // step, removes about 0.5 % of the wobble over 100 steps.
  Disc d;
  MdtBodySetAngularVelocity(d.b, (MeReal)0.1, 1, 0);
  for (int i = 0; i < 100; ++i) MdtWorldStep(d.w, (MeReal)0.01);
  EXPECT_NEAR(d.wobble(), 0.1, 0.1 * 0.01);
  EXPECT_NEAR(d.spin(), 1, 1e-4);
}
