// Fast-spin integration: a free disc spinning at spin * h = 1 with a small
// wobble. The explicit gyroscopic term multiplies the wobble by
// sqrt(1 + (h Omega)^2) = sqrt(2) per step (Omega = spin (Is - Ia) / Ia);
// with a fast-spin axis the term is linearly implicit and the wobble cannot
// grow.
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

TEST(FastSpin, ExplicitGyroscopicTermBlowsUpTheSameSpinner) {
  // Without the fast-spin axis: the wobble grows by ~sqrt(2) per step.
  WarningCapture warnings;
  Disc d;
  double after10 = 0;
  for (int i = 0; i < 200 && MdtBodyIsEnabled(d.b); ++i) {
    MdtWorldStep(d.w, (MeReal)0.01);
    if (i == 9) after10 = d.wobble();
  }
  EXPECT_GT(after10, 0.1 * 10);  // sqrt(2)^10 = 32 ideally
  // Eventually the state overflows; the body is stopped with a warning.
  EXPECT_FALSE(MdtBodyIsEnabled(d.b));
  EXPECT_NE(warnings.last().find("overflowed"), std::string::npos);
}
