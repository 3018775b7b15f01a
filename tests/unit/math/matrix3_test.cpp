// matrix3_test.cpp: MeMatrix3 algebra and rotations against hand-computed values.
#include "math_test_util.h"

using namespace mathtest;

namespace {

// det A = 1, and its inverse has small integer entries.
const MeMatrix3 kA = {{1, 2, 3}, {0, 1, 4}, {5, 6, 0}};
const MeMatrix3 kAInv = {{-24, 18, 5}, {20, -15, -4}, {-5, 4, 1}};
const MeMatrix3 kB = {{2, 0, 1}, {1, 3, 0}, {0, -1, 2}};

}  // namespace

TEST(MeMatrix3, IdentityAndCopy) {
  MeMatrix3 m, c;
  MeMatrix3MakeIdentity(m);
  expectIdentity3(m, 0);
  MeMatrix3Copy(c, kA);
  expectMat<3>(c, kA, 0);
}

TEST(MeMatrix3, MultiplyHandComputed) {
  const MeMatrix3 ab = {{4, 3, 7}, {1, -1, 8}, {16, 18, 5}};
  MeMatrix3 out;
  MeMatrix3Multiply(out, kA, kB);
  expectMat<3>(out, ab);
  // Aliasing: out is the first, then the second operand.
  MeMatrix3 a;
  MeMatrix3Copy(a, kA);
  MeMatrix3Multiply(a, a, kB);
  expectMat<3>(a, ab);
  MeMatrix3 b;
  MeMatrix3Copy(b, kB);
  MeMatrix3Multiply(b, kA, b);
  expectMat<3>(b, ab);
  MeMatrix3Copy(a, kA);
  MeMatrix3Multiply(a, a, a);  // A^2 row 0 = 1*(1,2,3) + 2*(0,1,4) + 3*(5,6,0)
  expectVec3(a[0], 16, 22, 11);
}

TEST(MeMatrix3, TransposeDeterminantInverse) {
  MeMatrix3 t;
  MeMatrix3Transpose(t, kA);
  const MeMatrix3 at = {{1, 0, 5}, {2, 1, 6}, {3, 4, 0}};
  expectMat<3>(t, at, 0);
  MeMatrix3Transpose(t, t);  // in place
  expectMat<3>(t, kA, 0);

  EXPECT_NEAR(MeMatrix3Determinant(kA), 1, kTol * 30);
  EXPECT_NEAR(MeMatrix3Determinant(kB), 2 * 6 - 0 + 1 * (-1), kTol * 30);

  MeMatrix3 inv;
  ASSERT_TRUE(MeMatrix3Inverse(inv, kA));
  expectMat<3>(inv, kAInv, kTol * 100);
  MeMatrix3 prod;
  MeMatrix3Multiply(prod, kA, inv);
  expectIdentity3(prod, kTol * 100);

  MeMatrix3 self;
  MeMatrix3Copy(self, kB);
  ASSERT_TRUE(MeMatrix3Inverse(self, self));  // in place
  MeMatrix3Multiply(prod, self, kB);
  expectIdentity3(prod, kTol * 10);

  // A scaled matrix is still invertible: the singularity test is scale-free.
  MeMatrix3 tiny = {{mr(1e-6), 0, 0}, {0, mr(2e-6), 0}, {0, 0, mr(4e-6)}};
  ASSERT_TRUE(MeMatrix3Inverse(inv, tiny));
  EXPECT_NEAR(inv[2][2], 2.5e5, 2.5e5 * kTol);
}

TEST(MeMatrix3, InverseOfSingularFailsAndLeavesOutputUnchanged) {
  const MeMatrix3 singular = {{1, 2, 3}, {2, 4, 6}, {0, 1, 1}};  // row1 = 2 row0
  MeMatrix3 out = {{9, 9, 9}, {9, 9, 9}, {9, 9, 9}};
  EXPECT_FALSE(MeMatrix3Inverse(out, singular));
  for (auto &row : out)
    for (MeReal e : row) EXPECT_EQ(e, 9);
  const MeMatrix3 zero = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(MeMatrix3Inverse(out, zero));
  EXPECT_EQ(out[0][0], 9);
}

TEST(MeMatrix3, MultiplyVectorVersusTranspose) {
  const MeVector3 v = {1, -1, 2};
  MeVector3 out;
  MeMatrix3MultiplyVector(out, kA, v);  // A v: rows dotted with v
  expectVec3(out, 5, 7, -1);
  MeMatrix3TransposeMultiplyVector(out, kA, v);  // v A: combination of rows
  expectVec3(out, 11, 13, -1);
  MeVector3 w = {1, -1, 2};
  MeMatrix3MultiplyVector(w, kA, w);  // aliasing
  expectVec3(w, 5, 7, -1);
  MeVector3Set(w, 1, -1, 2);
  MeMatrix3TransposeMultiplyVector(w, kA, w);
  expectVec3(w, 11, 13, -1);
}

TEST(MeMatrix3, RotationsCarryBodyAxesToWorld) {
  MeMatrix3 R;
  const MeVector3 bx = {1, 0, 0}, by = {0, 1, 0}, bz = {0, 0, 1};
  MeVector3 w;
  // +90 degrees about z: body x -> world y, body y -> world -x.
  MeMatrix3MakeRotationZ(R, kPi / 2);
  expectVec3(R[0], 0, 1, 0);
  MeMatrix3TransposeMultiplyVector(w, R, bx);
  expectVec3(w, 0, 1, 0);
  MeMatrix3TransposeMultiplyVector(w, R, by);
  expectVec3(w, -1, 0, 0);
  MeMatrix3MultiplyVector(w, R, by);  // world y is body x
  expectVec3(w, 1, 0, 0);
  // +90 degrees about x: y -> z, z -> -y.
  MeMatrix3MakeRotationX(R, kPi / 2);
  MeMatrix3TransposeMultiplyVector(w, R, by);
  expectVec3(w, 0, 0, 1);
  MeMatrix3TransposeMultiplyVector(w, R, bz);
  expectVec3(w, 0, -1, 0);
  // +90 degrees about y: z -> x, x -> -z.
  MeMatrix3MakeRotationY(R, kPi / 2);
  MeMatrix3TransposeMultiplyVector(w, R, bz);
  expectVec3(w, 1, 0, 0);
  MeMatrix3TransposeMultiplyVector(w, R, bx);
  expectVec3(w, 0, 0, -1);
  // A general angle: 30 degrees about z.
  MeMatrix3MakeRotationZ(R, kPi / 6);
  expectVec3(R[0], std::sqrt(3.0) / 2, 0.5, 0);
  expectVec3(R[1], -0.5, std::sqrt(3.0) / 2, 0);
}

TEST(MeMatrix3, FromAxisAngleMatchesCoordinateRotations) {
  const MeReal angles[] = {mr(0.3), mr(-1.2), mr(2.9), kPi};
  for (MeReal a : angles) {
    MeMatrix3 R1, R2;
    const MeVector3 x = {2, 0, 0}, y = {0, mr(0.5), 0}, z = {0, 0, -1};
    MeMatrix3FromAxisAngle(R1, x, a);
    MeMatrix3MakeRotationX(R2, a);
    expectMat<3>(R1, R2);
    MeMatrix3FromAxisAngle(R1, y, a);
    MeMatrix3MakeRotationY(R2, a);
    expectMat<3>(R1, R2);
    MeMatrix3FromAxisAngle(R1, z, a);  // -z axis: the opposite turn about z
    MeMatrix3MakeRotationZ(R2, -a);
    expectMat<3>(R1, R2);
  }
  MeMatrix3 R;
  const MeVector3 zero = {0, 0, 0};
  MeMatrix3FromAxisAngle(R, zero, 1);
  expectIdentity3(R, 0);
}

TEST(MeMatrix3, FromAxisAngleKeepsAxisAndTurnsRightHanded) {
  for (const auto &aa : testRotations()) {
    MeMatrix3 R;
    MeMatrix3FromAxisAngle(R, aa.axis, aa.angle);
    EXPECT_TRUE(MeMatrix3IsRotation(R, mr(kTol * 10)));
    EXPECT_NEAR(MeMatrix3Determinant(R), 1, kTol * 10);
    MeVector3 n = {aa.axis[0], aa.axis[1], aa.axis[2]}, w;
    MeVector3Normalize(n);
    MeMatrix3TransposeMultiplyVector(w, R, n);  // the axis is fixed
    expectVec3(w, n[0], n[1], n[2], kTol * 10);
    // A unit vector u normal to n goes to cos(a) u + sin(a) (n x u).
    MeVector3 u, v, expect;
    MeVector3PlaneSpace(n, u, v);
    MeVector3Cross(v, n, u);
    MeMatrix3TransposeMultiplyVector(w, R, u);
    MeVector3MultiplyScalar(expect, u, MeCos(aa.angle));
    MeVector3MultiplyAdd(expect, MeSin(aa.angle), v);
    expectVec3(w, expect[0], expect[1], expect[2], kTol * 10);
  }
}

TEST(MeMatrix3, IsOrthonormalAndIsRotation) {
  MeMatrix3 R;
  MeMatrix3MakeRotationY(R, mr(0.7));
  EXPECT_TRUE(MeMatrix3IsOrthonormal(R, mr(kTol)));
  EXPECT_TRUE(MeMatrix3IsRotation(R, mr(kTol)));
  MeMatrix3 reflect = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  EXPECT_TRUE(MeMatrix3IsOrthonormal(reflect, mr(kTol)));
  EXPECT_FALSE(MeMatrix3IsRotation(reflect, mr(kTol)));
  R[0][0] *= mr(1.01);
  EXPECT_FALSE(MeMatrix3IsOrthonormal(R, mr(1e-3)));
  EXPECT_TRUE(MeMatrix3IsOrthonormal(R, mr(0.1)));
  EXPECT_FALSE(MeMatrix3IsOrthonormal(kA, mr(0.1)));
}
