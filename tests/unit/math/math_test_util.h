// math_test_util.h: tolerances and comparison helpers for the MeMath tests.
#ifndef KARMA_TESTS_MATH_TEST_UTIL_H
#define KARMA_TESTS_MATH_TEST_UTIL_H

#include <gtest/gtest.h>

#include <vector>

#include "MeMath.h"

namespace mathtest {

// A few ulps of an O(1) result in the configured precision.
inline constexpr double kTol = sizeof(MeReal) == 4 ? 1e-5 : 1e-12;
inline constexpr MeReal kPi = ME_PI;

inline MeReal mr(double x) { return static_cast<MeReal>(x); }

inline void expectVec3(const MeReal *got, double x, double y, double z, double tol = kTol) {
  EXPECT_NEAR(got[0], x, tol);
  EXPECT_NEAR(got[1], y, tol);
  EXPECT_NEAR(got[2], z, tol);
}

inline void expectVec4(const MeReal *got, double a, double b, double c, double d, double tol = kTol) {
  EXPECT_NEAR(got[0], a, tol);
  EXPECT_NEAR(got[1], b, tol);
  EXPECT_NEAR(got[2], c, tol);
  EXPECT_NEAR(got[3], d, tol);
}

template <int N>
void expectMat(const MeReal (*got)[N], const MeReal (*want)[N], double tol = kTol) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) EXPECT_NEAR(got[i][j], want[i][j], tol) << "entry [" << i << "][" << j << "]";
}

inline void expectIdentity3(const MeReal (*got)[3], double tol = kTol) {
  MeMatrix3 I;
  MeMatrix3MakeIdentity(I);
  expectMat<3>(got, I, tol);
}

inline void expectIdentity4(const MeReal (*got)[4], double tol = kTol) {
  MeMatrix4 I;
  MeMatrix4MakeIdentity(I);
  expectMat<4>(got, I, tol);
}

// Deterministic test rotations: axes in several directions and angles over
// (-2pi, 2pi), including half turns (w = 0) and near-half turns.
struct AxisAngle {
  MeReal axis[3];
  MeReal angle;
};

inline std::vector<AxisAngle> testRotations() {
  const double axes[][3] = {{1, 0, 0},  {0, 1, 0},      {0, 0, 1}, {1, 1, 0},     {1, -2, 3},
                            {-3, 1, 2}, {0.2, 0.1, -1}, {1, 1, 1}, {-1, 0.01, 0}, {0.3, -0.7, 0.05}};
  const double angles[] = {
      0.0,     0.1, -0.4, 1.0, 1.5707963267948966, 2.5, -2.9, 3.0, 3.14, 3.1415926535897932, -3.1415926535897932,
      3.14159, 4.0, -5.5, 6.2};
  std::vector<AxisAngle> out;
  for (const auto &a : axes)
    for (double ang : angles) out.push_back({{mr(a[0]), mr(a[1]), mr(a[2])}, mr(ang)});
  return out;
}

}  // namespace mathtest

#endif  // KARMA_TESTS_MATH_TEST_UTIL_H
