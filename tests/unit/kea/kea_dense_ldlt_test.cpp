// The dense LDL^T (kea_dense_ldlt.h): it solves symmetric positive definite
// systems of every size it takes to the rounding of a backward-stable
// factorisation, agrees with the envelope LDL^T, leaves the padding of its
// rows zero, reports a breakdown on a singular or indefinite block, refuses
// a block larger than kMaxRows, and gives the same bits on every run and
// the bits of its documented order taken one scalar at a time, also when
// it is told which entries may be nonzero (a tree's pattern).
#include "kea_dense_ldlt.h"
#include "kea_envelope_ldlt.h"

#include <gtest/gtest.h>

#include "kea_hash_unit.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

using karma::kea::detail::DenseLdlt;
using karma::kea::detail::EnvelopeSystem;

namespace {

using kea_test::Unit;

// A = G G^T + m I / 4 (G: m x m random), positive definite with a
// condition number of a few hundred; `band` > 0 keeps only |i - j| < band.
std::vector<double> Spd(int m, std::uint32_t seed, int band = 0) {
  std::vector<double> g((size_t)m * m), a((size_t)m * m, 0.0);
  for (size_t k = 0; k < g.size(); ++k) g[k] = Unit(seed, (std::uint32_t)k);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      double s = i == j ? m / 4.0 : 0.0;
      for (int k = 0; k < m; ++k) s += g[(size_t)i * m + k] * g[(size_t)j * m + k];
      if (band == 0 || std::abs(i - j) < band) a[(size_t)i * m + j] = s;
    }
  if (band > 0)  // a band of a positive definite matrix need not be one: add to the diagonal
    for (int i = 0; i < m; ++i) a[(size_t)i * m + i] += m;
  return a;
}

void Fill(DenseLdlt &d, const std::vector<double> &a, int m) {
  d.begin(m);
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) d.at(i, j) = (MeReal)a[(size_t)i * m + j];
}

// max_i |A x - b|_i / (|A| |x| + |b|)_i: the componentwise backward error.
double BackwardError(const std::vector<double> &a, int m, const std::vector<MeReal> &x, const std::vector<MeReal> &b) {
  double worst = 0;
  for (int i = 0; i < m; ++i) {
    double r = -(double)b[(size_t)i], scale = std::fabs((double)b[(size_t)i]);
    for (int j = 0; j < m; ++j) {
      const double aij = (double)(MeReal)a[(size_t)i * m + j];
      r += aij * (double)x[(size_t)j];
      scale += std::fabs(aij * (double)x[(size_t)j]);
    }
    worst = std::max(worst, std::fabs(r) / scale);
  }
  return worst;
}

}  // namespace

TEST(DenseLdlt, SolvesPositiveDefiniteSystemsOfEverySize) {
  DenseLdlt d;
  d.reserve(DenseLdlt::kMaxRows);
  for (int m = 1; m <= DenseLdlt::kMaxRows; ++m) {
    const std::vector<double> a = Spd(m, (std::uint32_t)m);
    Fill(d, a, m);
    ASSERT_TRUE(d.factor()) << "m = " << m;
    std::vector<MeReal> b((size_t)m), x((size_t)m);
    for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(99, (std::uint32_t)i);
    d.solve(b, x);
    // Backward stable: a small multiple of m times the unit roundoff.
    EXPECT_LT(BackwardError(a, m, x, b), 4.0 * m * ME_REAL_EPSILON) << "m = " << m;
    // The padding of each row stays zero.
    for (int i = 0; i < m; ++i)
      for (int c = m; c < d.stride; ++c) EXPECT_EQ(d.upper[(size_t)i * d.stride + c], MeReal(0));
    // In place (x aliasing rhs) gives the same bits.
    std::vector<MeReal> y = b;
    d.solve(y, y);
    EXPECT_TRUE(y == x) << "m = " << m;
  }
}

TEST(DenseLdlt, AgreesWithTheEnvelopeLdltAndSkipsRowsThatDoNotMeet) {
  // A band: most pairs of rows do not meet (their multiplier is exactly
  // zero and the update is skipped), which must not change the answer.
  for (int band : {0, 2, 5}) {
    const int m = 40;
    const std::vector<double> a = Spd(m, 7, band);
    DenseLdlt d;
    Fill(d, a, m);
    ASSERT_TRUE(d.factor());
    EnvelopeSystem e;
    e.begin(m);
    e.layout();
    for (int i = 0; i < m; ++i)
      for (int j = 0; j <= i; ++j) e.value[e.at(i, j)] = (MeReal)a[(size_t)i * m + j];
    e.factor();
    std::vector<MeReal> b((size_t)m), xd((size_t)m), xe((size_t)m);
    for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(5, (std::uint32_t)i);
    d.solve(b, xd);
    e.solve(b, xe);
    double big = 0;
    for (MeReal v : xe) big = std::max(big, std::fabs((double)v));
    for (int i = 0; i < m; ++i)
      EXPECT_NEAR(xd[(size_t)i], xe[(size_t)i], 64 * m * ME_REAL_EPSILON * big) << "band " << band << " row " << i;
  }
}

TEST(DenseLdlt, ReportsABreakdownOnASingularOrIndefiniteBlock) {
  DenseLdlt d;
  // Rows 0 and 1 equal: singular.
  Fill(d, {1, 1, 0, 1, 1, 0, 0, 0, 1}, 3);
  EXPECT_FALSE(d.factor());
  // Indefinite: a 2 x 2 block with a negative determinant.
  Fill(d, {1, 2, 2, 1}, 2);
  EXPECT_FALSE(d.factor());
  // A non-positive diagonal entry.
  Fill(d, {0, 0, 0, 1}, 2);
  EXPECT_FALSE(d.factor());
  // Too large for it.
  d.begin(DenseLdlt::kMaxRows + 1);
  for (int i = 0; i <= DenseLdlt::kMaxRows; ++i) d.at(i, i) = 1;
  EXPECT_FALSE(d.factor());
}

TEST(DenseLdlt, TheSameBitsOnEveryRun) {
  const int m = 33;
  const std::vector<double> a = Spd(m, 3);
  std::vector<MeReal> b((size_t)m), first((size_t)m), again((size_t)m);
  for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(8, (std::uint32_t)i);
  DenseLdlt d;
  Fill(d, a, m);
  ASSERT_TRUE(d.factor());
  d.solve(b, first);
  const std::vector<MeReal> factor = d.upper;
  for (int run = 0; run < 3; ++run) {
    DenseLdlt e;
    Fill(e, a, m);
    ASSERT_TRUE(e.factor());
    e.solve(b, again);
    EXPECT_TRUE(again == first);
    EXPECT_TRUE(e.upper == factor);
  }
}

// begin() zeroes only what factor() and solve() read, and the caller
// writes only the nonzeros (as Kea's sparse backend does), so a factor
// reused for a smaller block still holds the larger block's values in
// places: none of them may reach the answer.
TEST(DenseLdlt, AReusedFactorGivesAFreshOnesBits) {
  auto fillNonzeros = [](DenseLdlt &d, const std::vector<double> &a, int m) {
    d.begin(m);
    for (int i = 0; i < m; ++i)
      for (int j = i; j < m; ++j)
        if (a[(size_t)i * m + j] != 0) d.at(i, j) = (MeReal)a[(size_t)i * m + j];
  };
  DenseLdlt reused;
  reused.reserve(DenseLdlt::kMaxRows);
  std::vector<MeReal> fresh, again;
  for (int m : {DenseLdlt::kMaxRows, 41, 17, 8, 33, 1, 64}) {
    Fill(reused, Spd(DenseLdlt::kMaxRows, 7), DenseLdlt::kMaxRows);  // every entry written
    ASSERT_TRUE(reused.factor());
    const std::vector<double> a = Spd(m, (std::uint32_t)(100 + m), 3);
    std::vector<MeReal> b((size_t)m);
    for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(5, (std::uint32_t)i);
    fresh.assign((size_t)m, 0);
    again.assign((size_t)m, 0);
    DenseLdlt d;
    fillNonzeros(d, a, m);
    ASSERT_TRUE(d.factor());
    d.solve(b, fresh);
    fillNonzeros(reused, a, m);
    ASSERT_TRUE(reused.factor());
    reused.solve(b, again);
    EXPECT_TRUE(again == fresh) << "m = " << m;
  }
}

namespace {

using Bits = std::conditional_t<sizeof(MeReal) == 4, std::uint32_t, std::uint64_t>;

// The factorisation and the solves exactly as kea_dense_ldlt.h orders them,
// one scalar at a time: row by row, each entry's updates in ascending k (a
// row k whose multiplier is exactly zero skipped); forward in ascending k,
// backward in descending c.
std::vector<MeReal> ScalarLdltSolve(const std::vector<double> &a, int m, const std::vector<MeReal> &b) {
  std::vector<MeReal> u((size_t)m * m, 0), l((size_t)m * m, 0), r((size_t)m, 0);
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) u[(size_t)i * m + j] = (MeReal)a[(size_t)i * m + j];
  for (int j = 0; j < m; ++j) {
    for (int k = 0; k < j; ++k) {
      const MeReal lj = u[(size_t)k * m + j] * r[(size_t)k];
      l[(size_t)j * m + k] = lj;
      if (lj == 0) continue;
      for (int c = j; c < m; ++c) u[(size_t)j * m + c] = u[(size_t)j * m + c] - lj * u[(size_t)k * m + c];
    }
    r[(size_t)j] = MeReal(1) / u[(size_t)j * m + j];
  }
  std::vector<MeReal> y = b, x((size_t)m);
  for (int k = 0; k < m; ++k) {
    x[(size_t)k] = y[(size_t)k] * r[(size_t)k];
    for (int c = k + 1; c < m; ++c) y[(size_t)c] = y[(size_t)c] - x[(size_t)k] * u[(size_t)k * m + c];
  }
  for (int c = m - 1; c > 0; --c)
    for (int k = 0; k < c; ++k) x[(size_t)k] = x[(size_t)k] - x[(size_t)c] * l[(size_t)c * m + k];
  return x;
}

}  // namespace

// The vector lanes and the blocks of the solves change no rounding: every
// size, full and banded (rows that do not meet), gives the scalar order's
// bits.
TEST(DenseLdlt, GivesTheBitsOfTheScalarOrder) {
  DenseLdlt d;
  for (int band : {0, 3})
    for (int m = 1; m <= DenseLdlt::kMaxRows; ++m) {
      const std::vector<double> a = Spd(m, 7u + (std::uint32_t)m, band);
      std::vector<MeReal> b((size_t)m), x((size_t)m);
      for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(99u, (std::uint32_t)i);
      Fill(d, a, m);
      ASSERT_TRUE(d.factor()) << "m = " << m;
      d.solve(b, x);
      const std::vector<MeReal> expected = ScalarLdltSolve(a, m, b);
      for (int i = 0; i < m; ++i)
        ASSERT_EQ(std::bit_cast<Bits>(x[(size_t)i]), std::bit_cast<Bits>(expected[(size_t)i]))
            << "m = " << m << ", band = " << band << ", x[" << i << "]";
    }
}

namespace {

// A = J J^T + I of rows on a tree of bodies, as a rag doll's: `bodies`
// bodies, body b > 0 joined to a random earlier one by three rows on both,
// and two to four rows on each body alone (its contacts); six random J
// entries per row and body. Rows share a nonzero exactly when they share a
// body. The rows are shuffled, so that no band follows the tree. `values`
// seeds J alone: two seeds give two matrices of one pattern.
std::vector<double> TreeSpd(int bodies, std::uint32_t shape, std::uint32_t values, int &m) {
  std::vector<std::vector<int>> rowBodies;
  for (int b = 1; b < bodies; ++b) {
    const int parent = (int)((Unit(shape, (std::uint32_t)b) + 1) / 2 * b) % b;
    for (int r = 0; r < 3; ++r) rowBodies.push_back({parent, b});
  }
  for (int b = 0; b < bodies; ++b) {
    const int contacts = 2 + (int)((Unit(shape + 1, (std::uint32_t)b) + 1) * 1.5) % 3;
    for (int r = 0; r < contacts; ++r) rowBodies.push_back({b});
  }
  for (size_t i = rowBodies.size(); i > 1; --i) {
    const auto j = (size_t)((Unit(shape + 2, (std::uint32_t)i) + 1) / 2 * (double)i);
    std::swap(rowBodies[i - 1], rowBodies[std::min(j, i - 1)]);
  }
  m = (int)rowBodies.size();
  const int cols = 6 * bodies;
  std::vector<double> jac((size_t)m * cols, 0.0), a((size_t)m * m, 0.0);
  for (int i = 0; i < m; ++i)
    for (int b : rowBodies[(size_t)i])
      for (int k = 0; k < 6; ++k)
        jac[(size_t)i * cols + 6 * b + k] = Unit(values, (std::uint32_t)(i * cols + 6 * b + k));
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      double s = i == j ? 1.0 : 0.0;
      for (int k = 0; k < cols; ++k) s += jac[(size_t)i * cols + k] * jac[(size_t)j * cols + k];
      a[(size_t)i * m + j] = s;
    }
  return a;
}

// Fills the nonzeros of a's upper triangle, noting each off-diagonal one
// (and, with `extra`, also every entry (i, i + 2) whether or not it is
// zero: a pattern may hold more than the nonzeros).
void FillNoting(DenseLdlt &d, const std::vector<double> &a, int m, DenseLdlt::Pattern known, bool extra = false) {
  d.begin(m, known);
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) {
      const bool nonzero = a[(size_t)i * m + j] != 0;
      if (nonzero) d.at(i, j) = (MeReal)a[(size_t)i * m + j];
      if (known == DenseLdlt::Pattern::Noted && j > i && (nonzero || (extra && j == i + 2))) d.notePattern(i, j);
    }
}

void ExpectScalarBits(const DenseLdlt &d, const std::vector<double> &a, int m, const char *what) {
  std::vector<MeReal> b((size_t)m), x((size_t)m);
  for (int i = 0; i < m; ++i) b[(size_t)i] = (MeReal)Unit(41u, (std::uint32_t)i);
  d.solve(b, x);
  const std::vector<MeReal> expected = ScalarLdltSolve(a, m, b);
  for (int i = 0; i < m; ++i)
    ASSERT_EQ(std::bit_cast<Bits>(x[(size_t)i]), std::bit_cast<Bits>(expected[(size_t)i]))
        << what << ", m = " << m << ", x[" << i << "]";
}

}  // namespace

// A factor told which entries it fills visits only the rows the symbolic
// elimination says can meet, and one told that the pattern is the last
// one's reuses that: both give the bits of the full test, on trees whose
// rows are shuffled (fill reaches across the block), in one word of
// columns and in two. (A kept pattern that fell back to testing every pair
// would give the same bits: this checks the answers, not which path ran.)
TEST(DenseLdlt, ANotedOrKeptPatternGivesTheBitsOfTheFullTest) {
  DenseLdlt d;
  d.reserve(DenseLdlt::kMaxRows);
  int tested = 0, pastOneWord = 0;
  for (int bodies : {3, 6, 10, 13, 16})
    for (std::uint32_t shape = 1; shape <= 3; ++shape) {
      int m = 0;
      const std::vector<double> a = TreeSpd(bodies, shape * 17, 5, m);
      if (m > DenseLdlt::kMaxRows) continue;
      FillNoting(d, a, m, DenseLdlt::Pattern::Noted);
      ASSERT_TRUE(d.factor());
      ExpectScalarBits(d, a, m, "noted");
      int again = 0;
      const std::vector<double> next = TreeSpd(bodies, shape * 17, 6, again);  // the same pattern, new values
      ASSERT_EQ(again, m);
      FillNoting(d, next, m, DenseLdlt::Pattern::Kept);
      ASSERT_TRUE(d.factor());
      ExpectScalarBits(d, next, m, "kept");
      FillNoting(d, a, m, DenseLdlt::Pattern::Noted, true);
      ASSERT_TRUE(d.factor());
      ExpectScalarBits(d, a, m, "noted with extra entries");
      ++tested;
      if (m > 64) ++pastOneWord;
    }
  EXPECT_EQ(tested, 15);      // every tree fits in a block
  EXPECT_GE(pastOneWord, 1);  // and some need the second word of columns
}

// A pivot so small that its reciprocal overflows (possible with eps = 0)
// is a breakdown whether or not the pattern is known: with r_k infinite the
// rows after it could only be infinite or NaN.
TEST(DenseLdlt, APivotWhoseReciprocalOverflowsIsABreakdown) {
  for (DenseLdlt::Pattern known : {DenseLdlt::Pattern::Unknown, DenseLdlt::Pattern::Noted}) {
    DenseLdlt d;
    d.reserve(2);
    d.begin(2, known);
    d.at(0, 0) = std::numeric_limits<MeReal>::denorm_min() * 4;
    d.at(1, 1) = 1;
    EXPECT_FALSE(d.factor());
  }
}
