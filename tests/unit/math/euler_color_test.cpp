// euler_color_test.cpp: MeMatrix3FromEulerAngles against the glossary's
// matrix, and MeHSVtoRGB against the primary and secondary colours.
#include <cmath>

#include "math_test_util.h"

using namespace mathtest;

namespace {

// The glossary's entries, evaluated in double from the three angles.
void glossaryMatrix(double psi, double theta, double phi, double M[3][3]) {
  const double cps = std::cos(psi), sps = std::sin(psi);
  const double cth = std::cos(theta), sth = std::sin(theta);
  const double cph = std::cos(phi), sph = std::sin(phi);
  M[0][0] = cps * cph - cth * sph * sps;
  M[0][1] = cps * sph + cth * cph * sps;
  M[0][2] = sps * sth;
  M[1][0] = -sps * cph - cth * sph * cps;
  M[1][1] = -sps * sph + cth * cph * cps;
  M[1][2] = cps * sth;
  M[2][0] = sth * sph;
  M[2][1] = -sth * cph;
  M[2][2] = cth;
}

void expectRgb(MeReal h, MeReal s, MeReal v, double r, double g, double b) {
  float rgb[4] = {-1, -1, -1, 0.25f};
  MeHSVtoRGB(h, s, v, rgb);
  EXPECT_NEAR(rgb[0], r, 1e-6) << "h=" << h << " s=" << s << " v=" << v;
  EXPECT_NEAR(rgb[1], g, 1e-6) << "h=" << h << " s=" << s << " v=" << v;
  EXPECT_NEAR(rgb[2], b, 1e-6) << "h=" << h << " s=" << s << " v=" << v;
  EXPECT_EQ(rgb[3], 0.25f);  // only three floats are written
}

}  // namespace

TEST(MeEuler, SingleAnglesByHand) {
  MeMatrix3 R, want;
  MeMatrix3FromEulerAngles(R, kPi / 2, 0, 0);  // yaw alone: +90 about z
  const MeMatrix3 yaw = {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}};
  expectMat<3>(R, yaw);
  MeMatrix3FromEulerAngles(R, 0, kPi / 2, 0);  // pitch alone: +90 about x
  const MeMatrix3 pitch = {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  expectMat<3>(R, pitch);
  MeMatrix3FromEulerAngles(R, 0, 0, mr(0.3));  // roll alone: about z too
  MeMatrix3MakeRotationZ(want, mr(0.3));
  expectMat<3>(R, want);
  MeMatrix3FromEulerAngles(R, 0, 0, 0);
  expectIdentity3(R, 0);
}

TEST(MeEuler, MatchesGlossaryEntriesAndIsProperRotation) {
  const double triples[][3] = {{0.1, 0.2, 0.3},   {-0.7, 1.1, 2.5},  {3.0, -0.4, -1.9}, {1.5707963, 0.5, 0},
                               {0.25, 3.1, -3.1}, {-2.2, -2.9, 0.6}, {5.0, 0.01, 4.0}};
  for (const auto &t : triples) {
    MeMatrix3 R;
    MeMatrix3FromEulerAngles(R, mr(t[0]), mr(t[1]), mr(t[2]));
    double M[3][3];
    glossaryMatrix(mr(t[0]), mr(t[1]), mr(t[2]), M);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(R[i][j], M[i][j], kTol * 5) << "[" << i << "][" << j << "]";
    EXPECT_TRUE(MeMatrix3IsOrthonormal(R, mr(kTol * 10)));
    EXPECT_NEAR(MeMatrix3Determinant(R), 1, kTol * 10);
    // The factorisation stated in euler.cpp: Rz(psi) Rx(theta) Rz(phi).
    MeMatrix3 a, b, c, ab, abc;
    MeMatrix3MakeRotationZ(a, mr(t[0]));
    MeMatrix3MakeRotationX(b, mr(t[1]));
    MeMatrix3MakeRotationZ(c, mr(t[2]));
    MeMatrix3Multiply(ab, a, b);
    MeMatrix3Multiply(abc, ab, c);
    expectMat<3>(R, abc, kTol * 10);
  }
}

TEST(MeHSV, PrimaryAndSecondaryColours) {
  expectRgb(0, 1, 1, 1, 0, 0);      // red
  expectRgb(60, 1, 1, 1, 1, 0);     // yellow
  expectRgb(120, 1, 1, 0, 1, 0);    // green
  expectRgb(180, 1, 1, 0, 1, 1);    // cyan
  expectRgb(240, 1, 1, 0, 0, 1);    // blue
  expectRgb(300, 1, 1, 1, 0, 1);    // magenta
  expectRgb(30, 1, 1, 1, 0.5, 0);   // orange, halfway red -> yellow
  expectRgb(210, 1, 1, 0, 0.5, 1);  // halfway cyan -> blue
  expectRgb(120, 1, mr(0.5), 0, 0.5, 0);
  expectRgb(0, mr(0.5), 1, 1, 0.5, 0.5);  // pink: p = v(1-s)
}

TEST(MeHSV, GreyWrapAndClamp) {
  expectRgb(0, 0, mr(0.4), 0.4, 0.4, 0.4);  // s = 0: grey of value v
  expectRgb(200, 0, mr(0.7), 0.7, 0.7, 0.7);
  expectRgb(360, 1, 1, 1, 0, 0);  // 360 wraps to red
  expectRgb(720, 1, 1, 1, 0, 0);
  expectRgb(480, 1, 1, 0, 1, 0);   // 480 = 120: green
  expectRgb(-120, 1, 1, 0, 0, 1);  // -120 = 240: blue
  expectRgb(-mr(1e-9), 1, 1, 1, 0, 0);
  expectRgb(60, 2, 3, 1, 1, 0);            // s, v clamped to 1
  expectRgb(60, -1, -1, 0, 0, 0);          // s, v clamped to 0
  expectRgb(std::nan(""), 1, 1, 1, 0, 0);  // NaN hue counts as 0
}

TEST(MeHSV, RainbowChainHuesAreDistinctAndSaturated) {
  // RainbowChain: MeHSVtoRGB((i / NBALLS) * 360, 1, 1, color) into float[4].
  const int nballs = 10;
  for (int i = 0; i < nballs; ++i) {
    float color[4] = {0, 0, 0, 0};
    MeHSVtoRGB((mr(i) / mr(nballs)) * 360, 1, 1, color);
    const float mx = std::fmax(color[0], std::fmax(color[1], color[2]));
    const float mn = std::fmin(color[0], std::fmin(color[1], color[2]));
    EXPECT_FLOAT_EQ(mx, 1.0f);
    EXPECT_FLOAT_EQ(mn, 0.0f);
  }
}
