// transform_test.cpp: MeMatrix4 and rigid transforms (TMs), by hand.
#include <cstdlib>

#include "math_test_util.h"

using namespace mathtest;

namespace {

// Turn +90 degrees about z, then translate by (1, 2, 3).
void makeTurnZThenShift(MeMatrix4 tm) {
  MeMatrix3 R;
  MeMatrix3MakeRotationZ(R, kPi / 2);
  MeMatrix4TMMakeFromRotationAndPosition(tm, R, 1, 2, 3);
}

}  // namespace

TEST(MeMatrix4, IdentityCopyMultiplyTranspose) {
  MeMatrix4 I, c;
  MeMatrix4MakeIdentity(I);
  expectIdentity4(I, 0);
  // The guide's terrain TM: a plane rotated by pi/2 about x.
  MeALIGNDATA(MeMatrix4, tm, 16) = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MeMatrix4Copy(c, tm);
  expectMat<4>(c, tm, 0);
  MeMatrix4Copy(c, c);
  expectMat<4>(c, tm, 0);

  const MeMatrix4 a = {{1, 2, 0, 0}, {0, 1, 0, 3}, {0, 0, 2, 0}, {1, 0, 0, 1}};
  const MeMatrix4 b = {{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 1}, {0, 2, 0, 1}};
  // Row i of a*b = sum_k a[i][k] b[k].
  const MeMatrix4 ab = {{2, 1, 0, 0}, {1, 6, 0, 3}, {0, 0, 2, 2}, {0, 3, 0, 1}};
  MeMatrix4 out;
  MeMatrix4Multiply(out, a, b);
  expectMat<4>(out, ab, 0);
  MeMatrix4Copy(out, a);
  MeMatrix4Multiply(out, out, b);
  expectMat<4>(out, ab, 0);

  MeMatrix4Transpose(out, ab);
  EXPECT_EQ(out[3][2], 2);  // ab[2][3]
  EXPECT_EQ(out[2][3], 0);  // ab[3][2]
  MeMatrix4Transpose(out, out);
  expectMat<4>(out, ab, 0);
}

TEST(MeMatrix4TM, SetAndGetParts) {
  MeMatrix4Ptr tm = static_cast<MeMatrix4Ptr>(std::malloc(sizeof(MeMatrix4)));  // as the guide does
  ASSERT_NE(tm, nullptr);
  MeMatrix4TMMakeIdentity(tm);
  MeMatrix4TMSetPosition(tm, 0, 0, 1);
  expectVec4(tm[3], 0, 0, 1, 1, 0);
  expectVec4(tm[0], 1, 0, 0, 0, 0);
  const MeVector3 p = {-1, 1, 0};
  MeMatrix4TMSetPositionVector(tm, p);
  MeVector3 got;
  MeMatrix4TMGetPosition(got, tm);
  expectVec3(got, -1, 1, 0, 0);

  MeMatrix3 R, back;
  MeMatrix3MakeRotationX(R, mr(0.4));
  MeMatrix4TMSetRotation(tm, R);
  MeMatrix4TMGetRotation(back, tm);
  expectMat<3>(back, R, 0);
  MeMatrix4TMGetPosition(got, tm);  // rotation change keeps the position
  expectVec3(got, -1, 1, 0, 0);
  EXPECT_EQ(tm[0][3], 0);
  EXPECT_EQ(tm[3][3], 1);
  EXPECT_TRUE(MeMatrix4IsTM(tm, mr(kTol)));
  std::free(tm);
}

TEST(MeMatrix4TM, TransformVersusRotateByHand) {
  MeMatrix4 tm;
  makeTurnZThenShift(tm);
  const MeVector3 ex = {1, 0, 0}, p = {2, 3, 4};
  MeVector3 out;
  MeMatrix4TMTransform(out, tm, ex);  // (0,1,0) + (1,2,3)
  expectVec3(out, 1, 3, 3);
  // p R = 2 (0,1,0) + 3 (-1,0,0) + 4 (0,0,1) = (-3, 2, 4)
  MeMatrix4TMRotate(out, tm, p);
  expectVec3(out, -3, 2, 4);
  MeMatrix4TMTransform(out, tm, p);
  expectVec3(out, -2, 4, 7);
  // And back.
  const MeVector3 wp = {-2, 4, 7}, wv = {-3, 2, 4};
  MeMatrix4TMInverseTransform(out, tm, wp);
  expectVec3(out, 2, 3, 4);
  MeMatrix4TMInverseRotate(out, tm, wv);
  expectVec3(out, 2, 3, 4);
  // Aliasing.
  MeVector3 q = {2, 3, 4};
  MeMatrix4TMTransform(q, tm, q);
  expectVec3(q, -2, 4, 7);
  MeMatrix4TMInverseTransform(q, tm, q);
  expectVec3(q, 2, 3, 4);
}

TEST(MeMatrix4TM, ComposeByHand) {
  // Child: 1 unit along the parent's x. Parent: turnZThenShift.
  MeMatrix4 child, parent, world;
  MeMatrix4TMMakeIdentity(child);
  MeMatrix4TMSetPosition(child, 1, 0, 0);
  makeTurnZThenShift(parent);
  MeMatrix4TMCompose(world, child, parent);
  expectVec3(world[3], 1, 3, 3);
  expectVec3(world[0], 0, 1, 0);
  EXPECT_TRUE(MeMatrix4IsTM(world, mr(kTol)));

  // a = +90 about x and shift (0,0,1); b = +90 about z and shift (10,0,0).
  MeMatrix3 rx, rz;
  MeMatrix3MakeRotationX(rx, kPi / 2);
  MeMatrix3MakeRotationZ(rz, kPi / 2);
  const MeVector3 ta = {0, 0, 1}, tb = {10, 0, 0};
  MeMatrix4 a, b, ab;
  MeMatrix4TMMakeFromRotationAndPosition(a, rx, ta[0], ta[1], ta[2]);
  MeMatrix4TMMakeFromRotationAndPosition(b, rz, tb[0], tb[1], tb[2]);
  MeMatrix4TMCompose(ab, a, b);
  expectVec3(ab[0], 0, 1, 0);
  expectVec3(ab[1], 0, 0, 1);
  expectVec3(ab[2], 1, 0, 0);
  expectVec3(ab[3], 10, 0, 1);
  // Transforming by the composition = transforming by a, then by b.
  const MeVector3 p = {1, 0, 0};
  MeVector3 viaA, twoStep, oneStep;
  MeMatrix4TMTransform(viaA, a, p);
  MeMatrix4TMTransform(twoStep, b, viaA);
  MeMatrix4TMTransform(oneStep, ab, p);
  expectVec3(twoStep, 10, 1, 1);
  expectVec3(oneStep, 10, 1, 1);
  // Compose agrees with the general product for TMs.
  MeMatrix4 general;
  MeMatrix4Multiply(general, a, b);
  expectMat<4>(general, ab);
  // Aliasing: out = a, and out = b.
  MeMatrix4TMCompose(a, a, b);
  expectMat<4>(a, ab);
  MeMatrix4TMMakeFromRotationAndPosition(a, rx, ta[0], ta[1], ta[2]);
  MeMatrix4TMCompose(b, a, b);
  expectMat<4>(b, ab);
}

TEST(MeMatrix4TM, InverseByHandAndRoundTrips) {
  MeMatrix4 tm, inv;
  makeTurnZThenShift(tm);
  MeMatrix4TMInverse(inv, tm);
  // R^T: rows (0,-1,0), (1,0,0), (0,0,1); t' = -t R^T = -(R[i] . t) = (-2, 1, -3).
  expectVec3(inv[0], 0, -1, 0);
  expectVec3(inv[1], 1, 0, 0);
  expectVec3(inv[3], -2, 1, -3);
  EXPECT_EQ(inv[3][3], 1);

  int n = 0;
  for (const auto &aa : testRotations()) {
    MeMatrix3 R;
    MeMatrix3FromAxisAngle(R, aa.axis, aa.angle);
    const MeVector3 t = {mr(0.5 * n - 3), mr(1.0 - 0.25 * n), mr(0.1 * n)};
    ++n;
    MeMatrix4TMMakeFromRotationAndPosition(tm, R, t[0], t[1], t[2]);
    MeMatrix4TMInverse(inv, tm);
    MeMatrix4 prod;
    MeMatrix4TMCompose(prod, tm, inv);
    expectIdentity4(prod, kTol * 50);
    MeMatrix4TMCompose(prod, inv, tm);
    expectIdentity4(prod, kTol * 50);
    MeMatrix4Multiply(prod, tm, inv);
    expectIdentity4(prod, kTol * 50);
    // In place inverse twice gives back tm.
    MeMatrix4Copy(prod, tm);
    MeMatrix4TMInverse(prod, prod);
    MeMatrix4TMInverse(prod, prod);
    expectMat<4>(prod, tm, kTol * 50);
    // InverseTransform undoes Transform.
    const MeVector3 p = {mr(0.3), mr(-2), mr(5)};
    MeVector3 w, b;
    MeMatrix4TMTransform(w, tm, p);
    MeMatrix4TMInverseTransform(b, tm, w);
    expectVec3(b, p[0], p[1], p[2], kTol * 50);
    MeMatrix4TMTransform(b, inv, w);
    expectVec3(b, p[0], p[1], p[2], kTol * 50);
  }
}

TEST(MeMatrix4TM, IsTM) {
  MeMatrix4 tm;
  makeTurnZThenShift(tm);
  EXPECT_TRUE(MeMatrix4IsTM(tm, mr(kTol)));
  tm[1][3] = mr(0.5);  // not affine
  EXPECT_FALSE(MeMatrix4IsTM(tm, mr(kTol)));
  makeTurnZThenShift(tm);
  tm[2][2] = -1;  // a reflection
  EXPECT_FALSE(MeMatrix4IsTM(tm, mr(kTol)));
  makeTurnZThenShift(tm);
  tm[0][0] = mr(0.2);  // not orthonormal
  EXPECT_FALSE(MeMatrix4IsTM(tm, mr(kTol)));
}
