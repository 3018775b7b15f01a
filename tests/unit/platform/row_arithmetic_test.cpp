// Tests of the reference per-row arithmetic (reference_inline.h) the step's
// assembly calls inline: against hand-computed values, and bit-identity with
// the MeMath operations the step used before.
#include "reference_inline.h"

#include "MeMath.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace ref = karma::platform::reference;

TEST(PlatformKernels, BodyMinvJtByHand) {
  // invMass 0.5; I^-1 = [[1, 2, 0], [0, 3, -1], [4, 0, 0.5]];
  // jl = (2, -4, 6) -> (1, -2, 3); ja = (1, 2, 4) -> (1+4+0, 0+6-4, 4+0+2) = (5, 2, 6).
  const MeReal inv[3][3] = {{1, 2, 0}, {0, 3, -1}, {4, 0, MeReal(0.5)}};
  const MeReal jl[3] = {2, -4, 6}, ja[3] = {1, 2, 4};
  MeReal lin[3] = {9, 9, 9}, ang[3] = {9, 9, 9};
  ref::BodyMinvJt(MeReal(0.5), inv, jl, ja, lin, ang);
  EXPECT_EQ(lin[0], 1);
  EXPECT_EQ(lin[1], -2);
  EXPECT_EQ(lin[2], 3);
  EXPECT_EQ(ang[0], 5);
  EXPECT_EQ(ang[1], 2);
  EXPECT_EQ(ang[2], 6);
}

TEST(PlatformKernels, BodyMinvJtOfAStaticBodyIsZero) {
  const MeReal inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  const MeReal jl[3] = {1, 2, 3}, ja[3] = {-1, 5, 7};
  MeReal lin[3], ang[3];
  ref::BodyMinvJt(0, inv, jl, ja, lin, ang);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(lin[k], 0);
    EXPECT_EQ(ang[k], 0);
  }
}

TEST(PlatformKernels, RowPairEntryByHand) {
  // (1, 2, 3).(4, -5, 6) + (-1, 0, 2).(0.5, 7, 0.25) = (4 - 10 + 18) + (-0.5 + 0 + 0.5) = 12.
  const MeReal jl[3] = {1, 2, 3}, ja[3] = {-1, 0, 2};
  const MeReal lin[3] = {4, -5, 6}, ang[3] = {MeReal(0.5), 7, MeReal(0.25)};
  EXPECT_EQ(ref::RowPairEntry(jl, ja, lin, ang), 12);
  // A unit point mass on a row along x: J M^-1 J^T = 1 / mass.
  const MeReal ex[3] = {1, 0, 0}, zero[3] = {0, 0, 0};
  const MeReal inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  MeReal ml[3], ma[3];
  ref::BodyMinvJt(MeReal(0.25), inv, ex, zero, ml, ma);
  EXPECT_EQ(ref::RowPairEntry(ex, zero, ml, ma), MeReal(0.25));
}

TEST(PlatformKernels, BitIdenticalToTheMeMathOperations) {
  // The step's determinism hash was taken with MeVector3MultiplyScalar,
  // MeMatrix3MultiplyVector and MeVector3Dot; the reference must reproduce
  // it bit for bit.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  auto r = [&] { return static_cast<MeReal>(u(rng)); };
  for (int t = 0; t < 1000; ++t) {
    MeMatrix3 inv;
    for (auto &row : inv)
      for (MeReal &x : row) x = r();
    const MeReal invMass = r();
    const MeVector3 jl = {r(), r(), r()}, ja = {r(), r(), r()};
    MeVector3 lin, ang, refLin, refAng;
    ref::BodyMinvJt(invMass, inv, jl, ja, lin, ang);
    MeVector3MultiplyScalar(refLin, jl, invMass);
    MeMatrix3MultiplyVector(refAng, inv, ja);
    EXPECT_EQ(std::memcmp(lin, refLin, sizeof lin), 0);
    EXPECT_EQ(std::memcmp(ang, refAng, sizeof ang), 0);
    const MeVector3 ki = {r(), r(), r()}, kj = {r(), r(), r()};
    const MeReal got = ref::RowPairEntry(ki, kj, lin, ang);
    const MeReal want = MeVector3Dot(ki, lin) + MeVector3Dot(kj, ang);
    EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0);
  }
}
