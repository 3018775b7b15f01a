// The small exact LCP of the PGS contact blocks (small_lcp.h): its answer
// meets the LCP's conditions, and the solve with the full set's elimination
// made beforehand gives the same bits as the plain solve, whichever set
// the answer has free.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "small_lcp.h"

namespace {

using karma::mdt::EliminateSmallLcpFullSet;
using karma::mdt::kSmallLcpMax;
using karma::mdt::SmallLcpFullSet;
using karma::mdt::SolveSmallLcp;
using karma::mdt::SolveSmallLcpAfterFull;

constexpr int kStride = kSmallLcpMax;

// A = B B^T + 0.1 I: symmetric positive definite.
void RandomSpd(std::mt19937 &rng, int k, MeReal *A) {
  std::uniform_real_distribution<double> u(-1, 1);
  double B[kSmallLcpMax][kSmallLcpMax];
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) B[i][j] = u(rng);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      double a = i == j ? 0.1 : 0;
      for (int l = 0; l < k; ++l) a += B[i][l] * B[j][l];
      A[i * kStride + j] = (MeReal)a;
    }
}

TEST(SmallLcp, AnswersMeetTheConditionsAndThePreEliminatedSolveGivesTheSameBits) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const double tol = sizeof(MeReal) == 4 ? 1e-3 : 1e-9;
  int someClamped = 0, allFree = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int k = 1 + trial % kSmallLcpMax;
    MeReal A[kSmallLcpMax * kSmallLcpMax] = {}, q[kSmallLcpMax] = {}, lo[kSmallLcpMax] = {};
    RandomSpd(rng, k, A);
    for (int i = 0; i < k; ++i) {
      q[i] = (MeReal)u(rng);
      lo[i] = trial % 3 == 0 ? (MeReal)(-0.5 * std::fabs(u(rng))) : 0;
    }
    MeReal x[kSmallLcpMax] = {}, y[kSmallLcpMax] = {};
    const bool plain = SolveSmallLcp(A, q, lo, k, x);
    SmallLcpFullSet full;
    EliminateSmallLcpFullSet(A, k, full);
    ASSERT_TRUE(full.ok);
    const bool eliminated = SolveSmallLcp(A, full, q, lo, k, y);
    ASSERT_TRUE(plain) << "trial " << trial;
    ASSERT_EQ(eliminated, plain);
    bool clamped = false;
    for (int i = 0; i < k; ++i) {
      EXPECT_EQ(x[i], y[i]) << "trial " << trial << " row " << i;  // bit-identical
      double w = -q[i];
      for (int j = 0; j < k; ++j) w += A[i * kStride + j] * x[j];
      EXPECT_GE(x[i], lo[i]);
      EXPECT_GE(w, -tol) << "trial " << trial;
      if (x[i] > lo[i] + tol) {
        EXPECT_NEAR(w, 0, tol) << "trial " << trial;
      }
      clamped = clamped || x[i] == lo[i];
    }
    (clamped ? someClamped : allFree)++;
  }
  // Both kinds of answer were exercised.
  EXPECT_GT(someClamped, 200);
  EXPECT_GT(allFree, 200);
}

TEST(SmallLcp, TheKeptInverseIsTheInverse) {
  // A^-1 A = I to a few hundred units of rounding (A = B B^T + 0.1 I:
  // the largest entry of the difference seen is 1.4e-6 in single and
  // 3.6e-15 in double precision).
  std::mt19937 rng(11);
  const double tol = sizeof(MeReal) == 4 ? 2e-5 : 5e-14;
  double worst = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = 1 + trial % kSmallLcpMax;
    MeReal A[kSmallLcpMax * kSmallLcpMax] = {};
    RandomSpd(rng, k, A);
    SmallLcpFullSet full;
    EliminateSmallLcpFullSet(A, k, full);
    ASSERT_TRUE(full.ok);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        double e = 0;
        for (int l = 0; l < k; ++l) e += (double)full.inverse[i][l] * (double)A[l * kStride + j];
        EXPECT_NEAR(e, i == j ? 1.0 : 0.0, tol) << "trial " << trial << " (" << i << ", " << j << ")";
        worst = std::max(worst, std::fabs(e - (i == j ? 1.0 : 0.0)));
      }
  }
  std::printf("largest |A^-1 A - I| entry: %.3g\n", worst);
}

TEST(SmallLcp, AGuessedFreeSetChangesNoBitOfTheAnswer) {
  // The answer is unique, so whichever set is tried first, the one that
  // fits is the same and gives the same bits; every guess is tried on
  // problems whose answer clamps some row (the all-free set does not fit).
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int k = 1 + trial % kSmallLcpMax;
    MeReal A[kSmallLcpMax * kSmallLcpMax] = {}, q[kSmallLcpMax] = {}, lo[kSmallLcpMax] = {};
    RandomSpd(rng, k, A);
    for (int i = 0; i < k; ++i) q[i] = (MeReal)u(rng);
    MeReal x[kSmallLcpMax] = {};
    ASSERT_TRUE(SolveSmallLcp(A, q, lo, k, x));
    bool clamped = false;
    for (int i = 0; i < k; ++i) clamped = clamped || x[i] == lo[i];
    if (!clamped) continue;
    ++checked;
    for (unsigned guess = 0; guess < (1u << k); ++guess) {
      MeReal y[kSmallLcpMax] = {};
      ASSERT_TRUE(SolveSmallLcpAfterFull(A, q, lo, k, guess, y));
      for (int i = 0; i < k; ++i) EXPECT_EQ(y[i], x[i]) << "trial " << trial << " guess " << guess << " row " << i;
    }
  }
  EXPECT_GT(checked, 300);
}

TEST(SmallLcp, AMatrixWithANonPositivePivotIsNotPreEliminated) {
  const MeReal A[kSmallLcpMax * kSmallLcpMax] = {1, 2, 0, 0, 2, 1};  // 2 x 2, indefinite
  SmallLcpFullSet full;
  EliminateSmallLcpFullSet(A, 2, full);
  EXPECT_FALSE(full.ok);
}

}  // namespace
