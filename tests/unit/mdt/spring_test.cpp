// Spring: string, elastic (period and damping against the closed form),
// rod, a very stiff spring over 60 s, and bad input.
#include <algorithm>
#include <cmath>
#include <vector>

#include "joints_a_support.h"

using namespace mdt_test;

namespace {

// A unit mass at (0, -y0, 0) on a spring to the world point (0, 0, 0).
struct Hanging {
  World w;
  MdtBodyID b;
  MdtSpringID s;
  Hanging(double y0, double gravity) {
    MdtWorldSetGravity(w, 0, -(MeReal)gravity, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    b = makeBody(w, 0, -(MeReal)y0, 0);
    s = MdtSpringCreate(w);
    MdtSpringSetBodies(s, b, nullptr);
    MdtSpringSetPosition(s, 1, 0, 0, 0);
  }
  double y() const {
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    return x[1];
  }
};

}  // namespace

TEST(Spring, DefaultsAndNaturalLengthFollowTheSeparation) {
  Hanging h(2, 0);
  EXPECT_NEAR(MdtSpringGetNaturalLength(h.s), 2, 1e-6);  // set by SetPosition
  EXPECT_NEAR(MdtSpringGetLength(h.s), 2, 1e-6);
  EXPECT_EQ(MdtSpringGetStiffness(h.s), 10);
  EXPECT_EQ(MdtSpringGetDamping(h.s), 1);
  MeVector3 p;
  MdtSpringGetPosition(h.s, p, 0);
  EXPECT_NEAR(p[1], -2, 1e-6);
  MdtSpringSetNaturalLength(h.s, 3);
  MdtSpringSetPosition(h.s, 1, 0, 1, 0);  // no longer changes the natural length
  EXPECT_NEAR(MdtSpringGetNaturalLength(h.s), 3, 1e-6);
  EXPECT_EQ(MdtConstraintDCastSpring(MdtSpringQuaConstraint(h.s)), h.s);
}

TEST(Spring, StringGoesSlackWhenShortAndHoldsAtItsLength) {
  // Natural length 1, lower side off, upper side hard. The mass starts 0.5
  // below the anchor: it falls freely until the string is taut.
  Hanging h(0.5, kG);
  MdtSpringSetNaturalLength(h.s, 1);
  MdtLimitID l = MdtSpringGetLimit(h.s);
  MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(l), 0);
  MdtSingleLimitSetDamping(MdtLimitGetLowerLimit(l), 0);
  MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(l), MEINFINITY);
  MdtSpringEnable(h.s);
  const MeReal dt = (MeReal)0.01;
  for (int i = 0; i < 20; ++i) MdtWorldStep(h.w, dt);
  // Free fall (semi-implicit Euler: g t (t + h) / 2 after n steps).
  const double t = 0.2;
  EXPECT_NEAR(h.y(), -0.5 - 0.5 * kG * t * (t + 0.01), 1e-5);
  MeVector3 f;
  MdtSpringGetForce(h.s, 0, f);
  EXPECT_EQ(MeVector3Magnitude(f), 0);
  // Then it catches the mass (restitution 0) and holds it at length 1.
  for (int i = 0; i < 300; ++i) MdtWorldStep(h.w, dt);
  EXPECT_NEAR(MdtSpringGetLength(h.s), 1, 1e-3);
  MdtSpringGetForce(h.s, 0, f);
  EXPECT_NEAR(f[1], kG, 1e-3 * kG);
}

// Period of the mass on a default (two-sided, soft) spring: k = 100, m = 1,
// no gravity, released 0.1 stretched. Returns the mean period over the run
// and the amplitude decay rate fitted from the first and last peaks.
void oscillate(double c, double h, double *period, double *decay) {
  Hanging s(1.1, 0);
  MdtSpringSetNaturalLength(s.s, 1);
  MdtSpringSetStiffness(s.s, 100);
  MdtSpringSetDamping(s.s, (MeReal)c);
  MdtSpringEnable(s.s);
  std::vector<double> crossings, peakT, peakA;
  double prev = s.y() + 1, prevT = 0;
  double ext = 0;
  for (int i = 1; i * h <= 4.0; ++i) {
    MdtWorldStep(s.w, (MeReal)h);
    const double x = s.y() + 1, t = i * h;
    if (prev < 0 && x >= 0) crossings.push_back(prevT + h * (-prev) / (x - prev));
    if (std::fabs(x) > ext) ext = std::fabs(x);
    if (prev < 0 && x >= 0) {  // one upward crossing per period: record the swing's extreme
      peakT.push_back(t);
      peakA.push_back(ext);
      ext = 0;
    }
    prev = x;
    prevT = t;
  }
  ASSERT_GE(crossings.size(), 3u);
  *period = (crossings.back() - crossings.front()) / (double)(crossings.size() - 1);
  *decay = std::log(peakA[1] / peakA.back()) / (peakT.back() - peakT[1]);
}

TEST(Spring, ElasticPeriodIsTwoPiRootMOverK) {
  double period = 0, decay = 0;
  oscillate(0, 1e-3, &period, &decay);
  const double expected = 2 * M_PI * std::sqrt(1.0 / 100);
  RecordProperty("period_s", std::to_string(period));
  EXPECT_NEAR(period, expected, 0.01 * expected);
}

TEST(Spring, ElasticDampingMatchesTheClosedForm) {
  // x'' = -(k/m) x - (c/m) x' decays at c / (2m). The spring row evaluates
  // the force at the end of the step (force k e_{n+1} - c v_{n+1}), which
  // adds the known numerical damping k h / (2m): expected (c + k h) / (2m).
  const double c = 0.5, h = 1e-3;
  double period = 0, decay = 0;
  oscillate(c, h, &period, &decay);
  RecordProperty("decay_per_s", std::to_string(decay));
  const double expected = (c + 100 * h) / 2;
  EXPECT_NEAR(decay, expected, 0.03 * expected);
  const double wd = std::sqrt(100 - 0.25 * c * c);
  EXPECT_NEAR(period, 2 * M_PI / wd, 0.01 * 2 * M_PI / wd);
}

TEST(Spring, RodKeepsItsLengthAsAPendulum) {
  // A rod of length 1 released horizontally: swings for 10 s.
  World w;
  MdtWorldSetGravity(w, 0, -(MeReal)kG, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID b = makeBody(w, 1, 0, 0);
  MdtSpringID s = MdtSpringCreate(w);
  MdtSpringSetBodies(s, b, nullptr);
  MdtSpringSetPosition(s, 1, 0, 0, 0);
  MdtSpringSetStiffness(s, MEINFINITY);
  MdtSpringEnable(s);
  double worst = 0, lowest = 0;
  for (int i = 0; i < 1000; ++i) {
    MdtWorldStep(w, (MeReal)0.01);
    worst = std::max(worst, std::fabs((double)MdtSpringGetLength(s) - 1));
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    lowest = std::min(lowest, (double)x[1]);
  }
  RecordProperty("rod_length_error_m", std::to_string(worst));
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(lowest, -0.99);  // it does swing through the bottom
}

TEST(Spring, VeryStiffSpringStaysStableFor60Seconds) {
  // k = 1e7 on m = 1 (omega h = 31.6 at h = 0.01), released 1 cm stretched:
  // energy 500 J. It must stay finite and never gain energy.
  Hanging s(1.01, 0);
  MdtSpringSetNaturalLength(s.s, 1);
  MdtSpringSetStiffness(s.s, (MeReal)1e7);
  MdtSpringSetDamping(s.s, 0);
  MdtSpringEnable(s.s);
  const double e0 = 0.5 * 1e7 * 0.01 * 0.01;
  double worst = 0;
  for (int i = 0; i < 6000; ++i) {
    MdtWorldStep(s.w, (MeReal)0.01);
    ASSERT_TRUE(bodyFinite(s.b)) << "step " << i;
    MeVector3 v;
    MdtBodyGetLinearVelocity(s.b, v);
    const double x = MdtSpringGetLength(s.s) - 1;
    const double e = 0.5 * MeVector3Dot(v, v) + 0.5 * 1e7 * x * x;
    worst = std::max(worst, e);
  }
  RecordProperty("stiff_spring_max_energy_J", std::to_string(worst));
  EXPECT_LE(worst, e0 * 1.001);
  EXPECT_NEAR(MdtSpringGetLength(s.s), 1, 1e-4);
}

TEST(Spring, BadInputIsRejectedWithAWarning) {
  WarningCapture warnings;
  Hanging h(1, 0);
  MdtSpringSetStiffness(h.s, -1);
  EXPECT_NE(warnings.last().find("MdtSpringSetStiffness"), std::string::npos);
  EXPECT_EQ(MdtSpringGetStiffness(h.s), 10);
  MdtSpringSetDamping(h.s, NAN);
  EXPECT_NE(warnings.last().find("MdtSpringSetDamping"), std::string::npos);
  MdtSpringSetNaturalLength(h.s, -2);
  EXPECT_NE(warnings.last().find("MdtSpringSetNaturalLength"), std::string::npos);
  EXPECT_NEAR(MdtSpringGetNaturalLength(h.s), 1, 1e-6);
  MdtSpringSetPosition(h.s, 2, 0, 0, 0);
  EXPECT_NE(warnings.last().find("body index 2"), std::string::npos);
  MdtSpringSetPosition(h.s, 0, NAN, 0, 0);
  EXPECT_NE(warnings.last().find("not finite"), std::string::npos);
  MdtSpringSetLimit(h.s, nullptr);
  EXPECT_NE(warnings.last().find("MdtSpringSetLimit"), std::string::npos);
  EXPECT_EQ(MdtSpringGetLimit(nullptr), nullptr);
  // Coincident attachment points: no direction, no crash, finite result.
  MdtSpringSetPosition(h.s, 1, 0, -1, 0);
  MdtSpringEnable(h.s);
  for (int i = 0; i < 10; ++i) MdtWorldStep(h.w, (MeReal)0.01);
  EXPECT_TRUE(bodyFinite(h.b));
}
