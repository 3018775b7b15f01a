// The pass over a constraint's rows before they are kept (row_scan.h):
// against the plain scalar scan it replaces, on random rows and on every
// value that is not finite in every position a row scans.
#include "row_scan.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using karma::mdt::Row;
using karma::mdt::RowScan;
using karma::mdt::scanRowValues;

// The scan written value by value with fabs and isfinite.
RowScan scalarScan(const std::vector<Row> &rows) {
  RowScan s;
  for (const Row &row : rows) {
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) {
        s.finite = s.finite && std::isfinite(row.J[k][c]);
        s.largestJ = std::max(s.largestJ, std::fabs(row.J[k][c]));
      }
    s.finite = s.finite && std::isfinite(row.speed) && std::isfinite(row.softness);
    s.largestSoftness = std::max(s.largestSoftness, std::fabs(row.softness));
    s.asking += row.bounceAfter > 0 ? 1 : 0;
  }
  return s;
}

// Values of every kind a finite row may hold: zeros of both signs,
// subnormals, the extremes, and ordinary values of both signs.
MeReal finiteValue(std::mt19937 &rng, bool extremes) {
  const MeReal special[] = {0,
                            -(MeReal)0,
                            std::numeric_limits<MeReal>::denorm_min(),
                            -std::numeric_limits<MeReal>::denorm_min(),
                            std::numeric_limits<MeReal>::min(),
                            ME_REAL_MAX,
                            -ME_REAL_MAX,
                            1,
                            -1};
  std::uniform_int_distribution<int> pick(0, 19);
  const int k = pick(rng);
  if (k < 9 && (extremes || (k != 5 && k != 6))) return special[k];
  std::uniform_real_distribution<MeReal> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-40, 40);
  return std::ldexp(mantissa(rng), exponent(rng));
}

std::vector<Row> randomRows(std::mt19937 &rng, int n, bool extremes = true) {
  std::vector<Row> rows((size_t)n);
  std::bernoulli_distribution bounce(0.3);
  for (Row &row : rows) {
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) row.J[k][c] = finiteValue(rng, extremes);
    row.speed = finiteValue(rng, extremes);
    row.softness = finiteValue(rng, extremes);
    row.bounceAfter = bounce(rng) ? 1 : 0;
  }
  return rows;
}

void expectSameBits(MeReal a, MeReal b) {
  EXPECT_EQ(std::bit_cast<karma::mdt::row_scan_detail::MagnitudeBits>(a),
            std::bit_cast<karma::mdt::row_scan_detail::MagnitudeBits>(b))
      << a << " vs " << b;
}

// With the extremes (+-ME_REAL_MAX) among the values and, in every other
// trial, without them, so that the order among ordinary values decides.
TEST(RowScan, FiniteRowsGiveTheBitsOfTheScalarScan) {
  std::mt19937 rng(20261205);
  for (int trial = 0; trial < 800; ++trial) {
    const std::vector<Row> rows = randomRows(rng, trial % 13, trial % 2 == 0);
    const RowScan fast = scanRowValues(rows.data(), (int)rows.size());
    const RowScan plain = scalarScan(rows);
    ASSERT_TRUE(plain.finite);
    EXPECT_TRUE(fast.finite);
    expectSameBits(fast.largestJ, plain.largestJ);
    expectSameBits(fast.largestSoftness, plain.largestSoftness);
    EXPECT_EQ(fast.asking, plain.asking);
  }
}

// Rows whose largest magnitude is a zero of either sign, a subnormal of
// either sign, or a value beside its negation.
TEST(RowScan, TheLargestIsFoundAmongZerosSubnormalsAndOpposites) {
  const MeReal tiny = std::numeric_limits<MeReal>::denorm_min();
  const MeReal cases[][2] = {{0, -(MeReal)0}, {-(MeReal)0, 0}, {-tiny, 0}, {0, -2 * tiny}, {(MeReal)1.5, -(MeReal)1.5},
                             {-(MeReal)1.5, (MeReal)1.5}, {-(MeReal)3, (MeReal)2.5}};
  for (const auto &c : cases) {
    std::vector<Row> rows(2);
    for (int r = 0; r < 2; ++r) {
      for (int k = 0; k < 4; ++k)
        for (int e = 0; e < 3; ++e) rows[(size_t)r].J[k][e] = 0;
      rows[(size_t)r].J[r + 1][r] = c[r];
      rows[(size_t)r].softness = c[1 - r];
    }
    const RowScan fast = scanRowValues(rows.data(), 2);
    const RowScan plain = scalarScan(rows);
    EXPECT_TRUE(fast.finite);
    expectSameBits(fast.largestJ, plain.largestJ);
    expectSameBits(fast.largestSoftness, plain.largestSoftness);
  }
}

TEST(RowScan, NoRowsAreFiniteWithNothingLarge) {
  const RowScan s = scanRowValues(nullptr, 0);
  EXPECT_TRUE(s.finite);
  EXPECT_EQ(s.largestJ, 0);
  EXPECT_EQ(s.largestSoftness, 0);
  EXPECT_EQ(s.asking, 0);
}

// Each of the 14 scanned values of any row, in turn, set to each value that
// is not finite: the scan says so. The value next to them (lo) is not
// scanned, so an infinity there changes nothing.
TEST(RowScan, AnyValueNotFiniteInAnyScannedPlaceIsFound) {
  const MeReal inf = std::numeric_limits<MeReal>::infinity();
  const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
  const MeReal bad[] = {inf, -inf, nan, -nan};
  std::mt19937 rng(7);
  std::vector<Row> rows = randomRows(rng, 5);
  for (size_t r = 0; r < rows.size(); ++r)
    for (int place = 0; place < 14; ++place)
      for (MeReal v : bad) {
        std::vector<Row> broken = rows;
        MeReal *value = place < 12 ? &broken[r].J[place / 3][place % 3]
                                   : place == 12 ? &broken[r].speed : &broken[r].softness;
        *value = v;
        EXPECT_FALSE(scanRowValues(broken.data(), (int)broken.size()).finite)
            << "row " << r << ", place " << place << ", value " << v;
      }
  std::vector<Row> unbounded = rows;
  unbounded[2].lo = -inf;
  EXPECT_TRUE(scanRowValues(unbounded.data(), (int)unbounded.size()).finite);
}

}  // namespace
