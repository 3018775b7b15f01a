// vector_test.cpp: MeVector3 / MeVector4 against hand-computed values.
#include <cmath>
#include <limits>

#include "math_test_util.h"

using namespace mathtest;

TEST(MeVector3, AddSubtractScale) {
  MeVector3 a = {1, 2, 3}, b = {mr(0.5), -4, 10}, out;
  MeVector3Add(out, a, b);
  expectVec3(out, 1.5, -2, 13);
  MeVector3Subtract(out, a, b);
  expectVec3(out, 0.5, 6, -7);
  MeVector3MultiplyScalar(out, a, -2);
  expectVec3(out, -2, -4, -6);
  MeVector3Scale(b, mr(0.5));  // in place, as the guide's MeVector3Scale(vel, 0.5)
  expectVec3(b, 0.25, -2, 5);
  MeVector3Negate(b);
  expectVec3(b, -0.25, 2, -5);
  MeVector3MultiplyAdd(b, 2, a);  // b += 2a
  expectVec3(b, 1.75, 6, 1);
}

TEST(MeVector3, OutputsMayAliasInputs) {
  MeVector3 a = {1, 2, 3};
  MeVector3Add(a, a, a);
  expectVec3(a, 2, 4, 6);
  MeVector3Subtract(a, a, a);
  expectVec3(a, 0, 0, 0);
  MeVector3 x = {1, 0, 0}, y = {0, 1, 0};
  MeVector3Cross(x, x, y);  // x <- x cross y
  expectVec3(x, 0, 0, 1);
  MeVector3 v = {3, 4, 5};
  MeVector3MultiplyAdd(v, -1, v);
  expectVec3(v, 0, 0, 0);
}

TEST(MeVector3, DotMagnitudeDistance) {
  MeVector3 a = {1, 2, 3}, b = {4, -5, 6};
  EXPECT_NEAR(MeVector3Dot(a, b), 4 - 10 + 18, kTol);
  MeVector3 c = {3, 4, 12};
  EXPECT_NEAR(MeVector3MagnitudeSqr(c), 169, kTol * 169);
  EXPECT_NEAR(MeVector3Magnitude(c), 13, kTol * 13);
  MeVector3 p = {1, 1, 1}, q = {4, 5, 1};
  EXPECT_NEAR(MeVector3Distance(p, q), 5, kTol * 5);
  EXPECT_NEAR(MeVector3DistanceSqr(p, q), 25, kTol * 25);
}

TEST(MeVector3, CrossIsRightHanded) {
  MeVector3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1}, out;
  MeVector3Cross(out, x, y);
  expectVec3(out, 0, 0, 1);
  MeVector3Cross(out, y, z);
  expectVec3(out, 1, 0, 0);
  MeVector3Cross(out, z, x);
  expectVec3(out, 0, 1, 0);
  MeVector3Cross(out, y, x);
  expectVec3(out, 0, 0, -1);
  // (1,2,3) x (4,5,6) = (2*6-3*5, 3*4-1*6, 1*5-2*4) = (-3, 6, -3)
  MeVector3 a = {1, 2, 3}, b = {4, 5, 6};
  MeVector3Cross(out, a, b);
  expectVec3(out, -3, 6, -3);
  EXPECT_NEAR(MeVector3Dot(out, a), 0, kTol);
  EXPECT_NEAR(MeVector3Dot(out, b), 0, kTol);
}

TEST(MeVector3, NormalizeReturnsLengthAndLeavesZeroAlone) {
  MeVector3 v = {0, -3, 4};
  EXPECT_NEAR(MeVector3Normalize(v), 5, kTol * 5);
  expectVec3(v, 0, -0.6, 0.8);
  EXPECT_NEAR(MeVector3Magnitude(v), 1, kTol);
  MeVector3 z = {0, 0, 0};
  EXPECT_EQ(MeVector3Normalize(z), 0);
  EXPECT_EQ(z[0], 0);
  EXPECT_EQ(z[1], 0);
  EXPECT_EQ(z[2], 0);
  EXPECT_TRUE(MeVector3IsZero(z));
  EXPECT_FALSE(MeVector3IsZero(v));
}

TEST(MeVector3, SetCopyFinite) {
  MeVector3 v, w;
  MeVector3Set(v, 7, 8, 9);
  MeVector3Copy(w, v);
  expectVec3(w, 7, 8, 9);
  EXPECT_TRUE(MeVector3AllFinite(w));
  w[1] = std::numeric_limits<MeReal>::quiet_NaN();
  EXPECT_FALSE(MeVector3AllFinite(w));
  w[1] = std::numeric_limits<MeReal>::infinity();
  EXPECT_FALSE(MeVector3AllFinite(w));
  w[1] = MEINFINITY;  // the largest finite value is finite
  EXPECT_TRUE(MeVector3AllFinite(w));
}

TEST(MeVector3, PlaneSpaceIsRightHandedOrthonormal) {
  const double normals[][3] = {{0, 0, 1}, {0, 0, -2}, {1, 0, 0}, {0, 5, 0}, {1, 2, 3}, {-0.3, 0.2, -0.9}, {0, 0, 0}};
  for (const auto &nn : normals) {
    MeVector3 n = {mr(nn[0]), mr(nn[1]), mr(nn[2])}, p, q, pxq;
    MeVector3PlaneSpace(n, p, q);
    EXPECT_NEAR(MeVector3Magnitude(p), 1, kTol);
    EXPECT_NEAR(MeVector3Magnitude(q), 1, kTol);
    EXPECT_NEAR(MeVector3Dot(p, q), 0, kTol);
    if (MeVector3Normalize(n) == 0) MeVector3Set(n, 0, 0, 1);
    MeVector3Cross(pxq, p, q);
    expectVec3(pxq, n[0], n[1], n[2]);
  }
}

TEST(MeVector3, PlaneSpaceCompletesATM) {
  // Fill the rotation rows of a TM from its z row, aliasing n with a row.
  MeMatrix4 tm;
  MeMatrix4TMMakeIdentity(tm);
  MeVector3Set(tm[2], mr(0.6), 0, mr(0.8));
  MeVector3PlaneSpace(tm[2], tm[0], tm[1]);
  EXPECT_TRUE(MeMatrix4IsTM(tm, mr(kTol)));
  expectVec3(tm[2], 0.6, 0, 0.8);  // n itself is untouched
  // n may even be one of the outputs.
  MeVector3 n = {0, 3, 4}, other;
  MeVector3PlaneSpace(n, other, n);
  EXPECT_NEAR(MeVector3Magnitude(n), 1, kTol);
  EXPECT_NEAR(n[1] * 3 + n[2] * 4, 0, kTol * 5);
}

TEST(MeVector4, Basics) {
  MeVector4 v, w;
  MeVector4Set(v, 1, 2, 2, 4);
  MeVector4Copy(w, v);
  expectVec4(w, 1, 2, 2, 4);
  EXPECT_NEAR(MeVector4Dot(v, w), 25, kTol * 25);
  EXPECT_NEAR(MeVector4Magnitude(v), 5, kTol * 5);
  EXPECT_NEAR(MeVector4Normalize(v), 5, kTol * 5);
  expectVec4(v, 0.2, 0.4, 0.4, 0.8);
  MeVector4 z = {0, 0, 0, 0};
  EXPECT_EQ(MeVector4Normalize(z), 0);
  expectVec4(z, 0, 0, 0, 0, 0);
}
