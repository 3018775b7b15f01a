// quaternion_test.cpp: quaternions (w, x, y, z) against matrices and by hand.
#include <cmath>

#include "math_test_util.h"

using namespace mathtest;

namespace {

// q and -q are one rotation: compare up to sign.
void expectSameRotation(const MeReal *a, const MeReal *b, double tol) {
  const double d = MeVector4Dot(a, b);
  EXPECT_NEAR(std::fabs(d), 1, tol) << "q1 = (" << a[0] << ", " << a[1] << ", " << a[2] << ", " << a[3] << "), q2 = ("
                                    << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3] << ")";
}

}  // namespace

TEST(MeQuaternion, MakeByHand) {
  MeVector4 q;
  const MeVector3 z = {0, 0, 3};  // need not be unit
  MeQuaternionMake(q, z, kPi / 2);
  const double h = std::sqrt(0.5);
  expectVec4(q, h, 0, 0, h);
  MeMatrix3 R;
  MeQuaternionToR(R, q);  // body x -> world y, so R[0] = (0, 1, 0)
  expectVec3(R[0], 0, 1, 0);
  expectVec3(R[1], -1, 0, 0);
  expectVec3(R[2], 0, 0, 1);

  const MeVector3 zero = {0, 0, 0};
  MeQuaternionMake(q, zero, 1);
  expectVec4(q, 1, 0, 0, 0, 0);
  MeQuaternionMakeIdentity(q);
  MeQuaternionToR(R, q);
  expectIdentity3(R, 0);
}

TEST(MeQuaternion, ToRMatchesAxisAngleMatrix) {
  for (const auto &aa : testRotations()) {
    MeVector4 q;
    MeMatrix3 Rq, Ra;
    MeQuaternionMake(q, aa.axis, aa.angle);
    EXPECT_TRUE(MeQuaternionIsUnit(q, mr(kTol)));
    MeQuaternionToR(Rq, q);
    MeMatrix3FromAxisAngle(Ra, aa.axis, aa.angle);
    expectMat<3>(Rq, Ra, kTol * 10);
    // A non-unit quaternion gives the same rotation (ToR divides by |q|^2).
    MeVector4 big = {3 * q[0], 3 * q[1], 3 * q[2], 3 * q[3]};
    MeQuaternionToR(Rq, big);
    expectMat<3>(Rq, Ra, kTol * 10);
  }
}

TEST(MeQuaternion, RoundTripsThroughMatrixIncludingHalfTurns) {
  for (const auto &aa : testRotations()) {
    MeVector4 q, back;
    MeMatrix3 R, R2;
    MeQuaternionMake(q, aa.axis, aa.angle);
    MeQuaternionToR(R, q);
    MeQuaternionFromR(back, R);
    EXPECT_GE(back[0], 0);
    EXPECT_TRUE(MeQuaternionIsUnit(back, mr(kTol)));
    expectSameRotation(q, back, kTol * 10);
    // Componentwise agreement after fixing q's sign to w >= 0, unless w ~ 0
    // where both signs are legitimate.
    if (std::fabs(q[0]) > 1e-2) {
      const MeReal sgn = q[0] < 0 ? mr(-1) : mr(1);
      expectVec4(back, sgn * q[0], sgn * q[1], sgn * q[2], sgn * q[3], kTol * 10);
    }
    MeQuaternionToR(R2, back);
    expectMat<3>(R2, R, kTol * 10);
  }
}

TEST(MeQuaternion, FromRExactHalfTurns) {
  MeVector4 q;
  const MeMatrix3 aboutX = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  MeQuaternionFromR(q, aboutX);
  const MeVector4 qx = {0, 1, 0, 0}, qy = {0, 0, 1, 0}, qz = {0, 0, 0, 1};
  expectSameRotation(q, qx, kTol);
  const MeMatrix3 aboutY = {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  MeQuaternionFromR(q, aboutY);
  expectSameRotation(q, qy, kTol);
  const MeMatrix3 aboutZ = {{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
  MeQuaternionFromR(q, aboutZ);
  expectSameRotation(q, qz, kTol);
  // Half turn about (1,1,0)/sqrt2: x <-> y, z -> -z.
  const MeMatrix3 aboutXY = {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
  MeQuaternionFromR(q, aboutXY);
  const double h = std::sqrt(0.5);
  const MeVector4 qxy = {0, mr(h), mr(h), 0};
  expectSameRotation(q, qxy, kTol);
  // The identity gives exactly (1, 0, 0, 0).
  const MeMatrix3 I = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  MeQuaternionFromR(q, I);
  expectVec4(q, 1, 0, 0, 0, 0);
}

TEST(MeQuaternion, MultiplyIsAThenB) {
  const MeVector3 zAxis = {0, 0, 1}, xAxis = {1, 0, 0};
  MeVector4 a, b, ab, ba;
  MeQuaternionMake(a, zAxis, kPi / 2);  // x -> y
  MeQuaternionMake(b, xAxis, kPi / 2);  // y -> z
  MeQuaternionMultiply(ab, a, b);
  MeQuaternionMultiply(ba, b, a);
  const MeVector3 ex = {1, 0, 0};
  MeVector3 w;
  MeQuaternionRotateVector(w, ab, ex);  // x -a-> y -b-> z
  expectVec3(w, 0, 0, 1);
  MeQuaternionRotateVector(w, ba, ex);  // x -b-> x -a-> y
  expectVec3(w, 0, 1, 0);
  // Hand product (Hamilton b a): a 120 degree turn about (1,-1,1)/sqrt3,
  // which cycles x -> z -> -y -> x... : (1/2)(1, 1, -1, 1).
  expectVec4(ab, 0.5, 0.5, -0.5, 0.5);
  // Aliasing.
  MeVector4 t;
  MeVector4Copy(t, a);
  MeQuaternionMultiply(t, t, b);
  expectVec4(t, ab[0], ab[1], ab[2], ab[3]);
  MeVector4Copy(t, b);
  MeQuaternionMultiply(t, a, t);
  expectVec4(t, ab[0], ab[1], ab[2], ab[3]);
}

TEST(MeQuaternion, MultiplyAgreesWithMatrixMultiply) {
  const auto rots = testRotations();
  for (size_t i = 0; i < rots.size(); i += 7) {
    for (size_t j = 3; j < rots.size(); j += 11) {
      MeVector4 a, b, ab;
      MeQuaternionMake(a, rots[i].axis, rots[i].angle);
      MeQuaternionMake(b, rots[j].axis, rots[j].angle);
      MeQuaternionMultiply(ab, a, b);
      MeMatrix3 Ra, Rb, RaRb, Rab;
      MeQuaternionToR(Ra, a);
      MeQuaternionToR(Rb, b);
      MeMatrix3Multiply(RaRb, Ra, Rb);
      MeQuaternionToR(Rab, ab);
      expectMat<3>(Rab, RaRb, kTol * 10);
    }
  }
}

TEST(MeQuaternion, RotateVectorAgreesWithMatrix) {
  const MeVector3 v = {mr(0.3), -2, mr(1.7)};
  for (const auto &aa : testRotations()) {
    MeVector4 q;
    MeMatrix3 R;
    MeQuaternionMake(q, aa.axis, aa.angle);
    MeQuaternionToR(R, q);
    MeVector3 byQ, byR;
    MeQuaternionRotateVector(byQ, q, v);
    MeMatrix3TransposeMultiplyVector(byR, R, v);  // body -> world
    expectVec3(byQ, byR[0], byR[1], byR[2], kTol * 20);
    MeQuaternionInverseRotateVector(byQ, q, v);
    MeMatrix3MultiplyVector(byR, R, v);  // world -> body
    expectVec3(byQ, byR[0], byR[1], byR[2], kTol * 20);
    MeVector3 same = {v[0], v[1], v[2]};
    MeQuaternionRotateVector(same, q, same);  // aliasing
    MeQuaternionInverseRotateVector(same, q, same);
    expectVec3(same, v[0], v[1], v[2], kTol * 20);
  }
}

TEST(MeQuaternion, ConjugateInvertNormalize) {
  const MeVector3 axis = {1, 2, -2};
  MeVector4 q, c, p;
  MeQuaternionMake(q, axis, mr(1.1));
  MeQuaternionConjugate(c, q);
  expectVec4(c, q[0], -q[1], -q[2], -q[3], 0);
  MeQuaternionMultiply(p, q, c);
  expectVec4(p, 1, 0, 0, 0);

  MeVector4 big = {2, -4, 0, 4}, inv;  // |big|^2 = 36
  ASSERT_TRUE(MeQuaternionInvert(inv, big));
  expectVec4(inv, 2.0 / 36, 4.0 / 36, 0, -4.0 / 36);
  MeQuaternionMultiply(p, big, inv);
  expectVec4(p, 1, 0, 0, 0);
  MeVector4 zero = {0, 0, 0, 0};
  inv[0] = 7;
  EXPECT_FALSE(MeQuaternionInvert(inv, zero));
  EXPECT_EQ(inv[0], 7);

  EXPECT_NEAR(MeQuaternionNormalize(big), 6, kTol * 6);
  expectVec4(big, 1.0 / 3, -2.0 / 3, 0, 2.0 / 3);
  EXPECT_TRUE(MeQuaternionIsUnit(big, mr(kTol)));
  EXPECT_EQ(MeQuaternionNormalize(zero), 0);
  expectVec4(zero, 1, 0, 0, 0, 0);
  const MeVector4 off = {1, 0, mr(0.1), 0};
  EXPECT_FALSE(MeQuaternionIsUnit(off, mr(1e-3)));
}

TEST(MeQuaternion, ToTM) {
  const MeVector3 zAxis = {0, 0, 1}, pos = {1, 2, 3};
  MeVector4 q;
  MeQuaternionMake(q, zAxis, kPi / 2);
  MeMatrix4 tm;
  MeQuaternionToTM(tm, q, pos);
  EXPECT_TRUE(MeMatrix4IsTM(tm, mr(kTol)));
  expectVec4(tm[0], 0, 1, 0, 0);
  expectVec4(tm[1], -1, 0, 0, 0);
  expectVec4(tm[2], 0, 0, 1, 0);
  expectVec4(tm[3], 1, 2, 3, 1, 0);
}

TEST(MeQuaternion, FiniteRotationConstantOmegaAboutZ) {
  const MeVector3 omega = {0, 0, mr(2.5)}, zAxis = {0, 0, 1};
  const MeReal h = mr(0.01);
  const int steps = 100;  // t = 1: total angle 2.5 rad
  MeVector4 q;
  MeQuaternionMakeIdentity(q);
  for (int i = 0; i < steps; ++i) MeQuaternionFiniteRotation(q, omega, h);
  MeVector4 expect;
  MeQuaternionMake(expect, zAxis, mr(2.5));
  expectVec4(q, expect[0], expect[1], expect[2], expect[3], kTol * 20);
  // The angle is |omega| t, whatever the step: one step of t = 1.
  MeQuaternionMakeIdentity(q);
  MeQuaternionFiniteRotation(q, omega, 1);
  expectVec4(q, expect[0], expect[1], expect[2], expect[3], kTol);
  // Body x now points at angle 2.5 in the world xy plane.
  MeVector3 w;
  const MeVector3 ex = {1, 0, 0};
  MeQuaternionRotateVector(w, q, ex);
  expectVec3(w, std::cos(2.5), std::sin(2.5), 0, kTol * 10);
  // Negative h undoes it.
  MeQuaternionFiniteRotation(q, omega, -1);
  expectVec4(q, 1, 0, 0, 0, kTol * 10);
}

TEST(MeQuaternion, FiniteRotationOmegaIsInWorldFrame) {
  // Start turned +90 about x (body y = world z). Spin about WORLD z, which
  // is the body's y axis: body x must sweep the world xy plane.
  const MeVector3 xAxis = {1, 0, 0}, zAxis = {0, 0, 1};
  MeVector4 q0, q, turn, expect;
  MeQuaternionMake(q0, xAxis, kPi / 2);
  MeVector4Copy(q, q0);
  const MeVector3 omega = {0, 0, mr(0.8)};
  MeQuaternionFiniteRotation(q, omega, mr(1.5));
  MeQuaternionMake(turn, zAxis, mr(1.2));
  MeQuaternionMultiply(expect, q0, turn);  // q0, then the world turn
  expectSameRotation(q, expect, kTol * 10);
  const MeVector3 ex = {1, 0, 0};
  MeVector3 w;
  MeQuaternionRotateVector(w, q, ex);
  expectVec3(w, std::cos(1.2), std::sin(1.2), 0, kTol * 10);
}

TEST(MeQuaternion, FiniteRotationTinyAndZeroOmega) {
  const MeVector3 axis = {1, -1, 2};
  MeVector4 q, q0;
  MeQuaternionMake(q0, axis, mr(0.9));
  MeVector4Copy(q, q0);
  const MeVector3 zero = {0, 0, 0};
  MeQuaternionFiniteRotation(q, zero, mr(0.01));
  expectVec4(q, q0[0], q0[1], q0[2], q0[3], kTol);
  // A tiny spin about x for h: angle 1e-7 rad, no 0/0.
  const MeVector3 tiny = {mr(1e-5), 0, 0};
  MeQuaternionMakeIdentity(q);
  MeQuaternionFiniteRotation(q, tiny, mr(0.01));
  EXPECT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]));
  EXPECT_NEAR(q[1], 0.5e-7, 1e-12);
  EXPECT_TRUE(MeQuaternionIsUnit(q, mr(kTol)));
}
