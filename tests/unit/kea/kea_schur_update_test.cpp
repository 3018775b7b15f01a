// The Schur-complement update (kea_schur_update.h): a free block that
// differs from a factorised one by up to kMaxRows rows, freed and clamped,
// is solved through the old factor and a capacitance matrix as accurately
// as a fresh factorisation solves it; it orders the rows as documented,
// refuses what it does not take, and gives the same bits on every run. In
// the sparse solver (KeaOptions::factorUpdateRows) it serves the pivots of
// solves that would have refactorised, and the answers agree with
// refactorising ones.
#include "kea_schur_update.h"

#include <gtest/gtest.h>

#include "kea_contact_problems.h"
#include "kea_dense_ldlt.h"
#include "kea_hash_unit.h"
#include "kea_lcp.h"
#include "kea_tolerance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

using karma::kea::KeaOptions;
using karma::kea::KeaResult;
using karma::kea::KeaSolveSparse;
using karma::kea::KeaStatus;
using karma::kea::detail::DenseLdlt;
using karma::kea::detail::SchurUpdate;

namespace {

using kea_test::Unit;

// A = G G^T + n I / 4 (G: n x n random): symmetric positive definite with
// a condition number of a few hundred, row-major, rounded to MeReal.
std::vector<MeReal> Spd(int n, std::uint32_t seed) {
  std::vector<double> g((size_t)n * n);
  for (size_t k = 0; k < g.size(); ++k) g[k] = Unit(seed, (std::uint32_t)k);
  std::vector<MeReal> a((size_t)n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double s = i == j ? n / 4.0 : 0.0;
      for (int k = 0; k < n; ++k) s += g[(size_t)i * n + k] * g[(size_t)j * n + k];
      a[(size_t)i * n + j] = (MeReal)s;
    }
  return a;
}

// The dense factor of A's rows `rows`, in that order.
void Factor(DenseLdlt &d, const std::vector<MeReal> &a, int n, const std::vector<int> &rows) {
  const int m = (int)rows.size();
  d.reserve((size_t)m);
  d.begin(m);
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) d.at(i, j) = a[(size_t)rows[(size_t)i] * n + rows[(size_t)j]];
  ASSERT_TRUE(d.factor());
}

// max_i |A_FF x - b|_i / (|A_FF| |x| + |b|)_i over the rows `rows` (x and b
// in that order): the componentwise backward error, in double.
double BackwardError(const std::vector<MeReal> &a, int n, const std::vector<int> &rows, std::span<const MeReal> x,
                     std::span<const MeReal> b) {
  double worst = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    double r = -(double)b[i], scale = std::fabs((double)b[i]);
    for (size_t j = 0; j < rows.size(); ++j) {
      const double aij = (double)a[(size_t)rows[i] * n + rows[j]];
      r += aij * (double)x[j];
      scale += std::fabs(aij * (double)x[j]);
    }
    worst = std::max(worst, std::fabs(r) / scale);
  }
  return worst;
}

struct Case {
  std::vector<int> base;  // the factor's rows, in its order
  std::vector<int> free;  // the new free rows, ascending
};

// Rows 0..n-1; the base takes every row but the last `spare`, in a
// shuffled order (the update must not assume ascending rows); the free set
// drops `removed` base rows and adds `added` of the spare ones.
Case MakeCase(int n, int spare, int removed, int added, std::uint32_t seed) {
  Case c;
  for (int i = 0; i < n - spare; ++i) c.base.push_back(i);
  for (size_t i = c.base.size(); i > 1; --i) {  // Fisher-Yates with the hash's values in [0, 1)
    const auto j = (size_t)((Unit(seed, (std::uint32_t)i) + 1) / 2 * (double)i);
    std::swap(c.base[i - 1], c.base[std::min(j, i - 1)]);
  }
  std::vector<int> free = c.base;
  for (int r = 0; r < removed; ++r) free.erase(free.begin() + (r * 7 + 3) % (int)free.size());
  for (int s = 0; s < added; ++s) free.push_back(n - spare + s);
  std::sort(free.begin(), free.end());
  c.free = free;
  return c;
}

auto ColumnOf(const std::vector<MeReal> &a, int n) {
  return [&a, n](int row, std::span<const int> position, std::span<MeReal> out) {
    for (int c = 0; c < n; ++c)
      if (position[(size_t)c] >= 0) out[(size_t)position[(size_t)c]] = a[(size_t)row * n + c];
  };
}

auto SolveWith(const DenseLdlt &d) {
  return [&d](std::span<const MeReal> in, std::span<MeReal> out) { d.solve(in, out); };
}

}  // namespace

TEST(SchurUpdate, SolvesTheChangedBlockAsWellAsAFreshFactorisation) {
  constexpr int n = 48, spare = 8;
  const std::vector<MeReal> a = Spd(n, 5);
  for (int removed = 0; removed <= SchurUpdate::kMaxRows; ++removed)
    for (int added = 0; added + removed <= SchurUpdate::kMaxRows && added <= spare; ++added) {
      if (added + removed == 0) continue;
      const std::string name = "removed " + std::to_string(removed) + ", added " + std::to_string(added);
      const Case c = MakeCase(n, spare, removed, added, (std::uint32_t)(removed * 16 + added));
      DenseLdlt base;
      Factor(base, a, n, c.base);
      SchurUpdate u;
      ASSERT_TRUE(u.prepare(c.base, c.free, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base))) << name;
      const std::vector<int> &order = u.order();
      // The kept rows in the base's order, then the added ones ascending.
      std::vector<int> expected;
      for (int r : c.base)
        if (std::binary_search(c.free.begin(), c.free.end(), r)) expected.push_back(r);
      for (int s = 0; s < added; ++s) expected.push_back(n - spare + s);
      ASSERT_EQ(order, expected) << name;
      const size_t m = order.size();
      std::vector<MeReal> b(m), x(m), fresh(m);
      for (size_t i = 0; i < m; ++i) b[i] = (MeReal)Unit(77, (std::uint32_t)i);
      u.solve(b, x, SolveWith(base));
      DenseLdlt direct;
      Factor(direct, a, n, order);
      direct.solve(b, fresh);
      // As backward stable as the fresh factorisation, to a small factor
      // (measured: at most 1.6 times it, in both precisions).
      const double updated = BackwardError(a, n, order, x, b), refactorised = BackwardError(a, n, order, fresh, b);
      EXPECT_LT(updated, 4 * refactorised + 4 * ME_REAL_EPSILON) << name;
      // Twice gives the same bits.
      std::vector<MeReal> again(m);
      u.solve(b, again, SolveWith(base));
      EXPECT_TRUE(again == x) << name;
    }
}

TEST(SchurUpdate, RefusesTheBaseItselfAChangeBeyondItsLimitAndALostBase) {
  constexpr int n = 24, spare = 10;
  const std::vector<MeReal> a = Spd(n, 9);
  const Case same = MakeCase(n, spare, 0, 0, 1);
  DenseLdlt base;
  Factor(base, a, n, same.base);
  SchurUpdate u;
  std::vector<int> free = same.base;
  std::sort(free.begin(), free.end());
  EXPECT_FALSE(u.prepare(same.base, free, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
  // The cases below share the base's rows and order (seed 1).
  const Case far = MakeCase(n, spare, 3, 6, 1);  // 9 rows change
  EXPECT_FALSE(u.prepare(far.base, far.free, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
  EXPECT_FALSE(u.prepare(far.base, far.free, n, 0, 9, ColumnOf(a, n), SolveWith(base)));  // kMaxRows at most
  const Case near = MakeCase(n, spare, 3, 4, 1);                                          // 7 rows change
  ASSERT_EQ(near.base, same.base);
  EXPECT_TRUE(u.prepare(near.base, near.free, n, 0, 7, ColumnOf(a, n), SolveWith(base)));
  EXPECT_FALSE(u.prepare(near.base, near.free, n, 0, 6, ColumnOf(a, n), SolveWith(base)));
  EXPECT_FALSE(u.prepare(near.base, near.free, n, 0, 0, ColumnOf(a, n), SolveWith(base)));
  EXPECT_FALSE(u.prepare(near.base, near.free, n, 0, -1, ColumnOf(a, n), SolveWith(base)));
  // Every base row clamped, within the limit: nothing of the factor is kept.
  const std::vector<int> small = {0, 1, 2, 3}, others = {n - spare, n - spare + 1};
  DenseLdlt smallBase;
  Factor(smallBase, a, n, small);
  EXPECT_FALSE(u.prepare(small, others, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(smallBase)));
  // The refusals left nothing behind: an update prepared now is exact.
  ASSERT_TRUE(u.prepare(near.base, near.free, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
  const size_t m = u.order().size();
  std::vector<MeReal> b(m, 1), x(m);
  u.solve(b, x, SolveWith(base));
  EXPECT_LT(BackwardError(a, n, u.order(), x, b), 64.0 * (double)m * ME_REAL_EPSILON);
}

// A freed row that repeats a free one (eps = 0: redundant contacts) makes
// the new block singular. A fresh factorisation breaks down on it
// (DenseLdlt's pivot floor); the update refuses it by the same rule, on
// its scaled capacitance matrix, rather than divide by rounding.
TEST(SchurUpdate, RefusesASingularChangeAsAFactorisationDoes) {
  constexpr int n = 12;
  // Diagonally dominant (well conditioned), with row 11 a copy of row 4.
  std::vector<MeReal> a((size_t)n * n, 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      a[(size_t)i * n + j] = i == j ? MeReal(4) : MeReal(0.1 * Unit(3, (std::uint32_t)(i * n + j)));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j) a[(size_t)j * n + i] = a[(size_t)i * n + j];  // symmetric
  for (int j = 0; j < n; ++j) a[(size_t)11 * n + j] = a[(size_t)4 * n + j];
  for (int i = 0; i < n; ++i) a[(size_t)i * n + 11] = a[(size_t)i * n + 4];
  a[(size_t)11 * n + 11] = a[(size_t)4 * n + 4];
  std::vector<int> baseRows;
  for (int i = 0; i < 10; ++i) baseRows.push_back(i);
  DenseLdlt base;
  Factor(base, a, n, baseRows);
  std::vector<int> withCopy = baseRows;
  withCopy.push_back(11);
  DenseLdlt fresh;
  fresh.reserve(withCopy.size());
  fresh.begin((int)withCopy.size());
  for (size_t i = 0; i < withCopy.size(); ++i)
    for (size_t j = i; j < withCopy.size(); ++j) fresh.at((int)i, (int)j) = a[(size_t)withCopy[i] * n + withCopy[j]];
  EXPECT_FALSE(fresh.factor());
  SchurUpdate u;
  EXPECT_FALSE(u.prepare(baseRows, withCopy, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
  // The row that is not a copy is taken.
  std::vector<int> withOther = baseRows;
  withOther.push_back(10);
  EXPECT_TRUE(u.prepare(baseRows, withOther, n, 0, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
}

TEST(SchurUpdate, AddsEpsilonToTheAddedRowsDiagonal) {
  constexpr int n = 20, spare = 4;
  const std::vector<MeReal> a = Spd(n, 13);
  const MeReal eps = (MeReal)0.5;
  std::vector<MeReal> shifted = a;
  for (int i = 0; i < n; ++i) shifted[(size_t)i * n + i] += eps;
  const Case c = MakeCase(n, spare, 1, 3, 3);
  DenseLdlt base;
  Factor(base, shifted, n, c.base);  // the base factor holds A + eps I
  SchurUpdate u;
  ASSERT_TRUE(u.prepare(c.base, c.free, n, eps, SchurUpdate::kMaxRows, ColumnOf(a, n), SolveWith(base)));
  const size_t m = u.order().size();
  std::vector<MeReal> b(m, 1), x(m);
  u.solve(b, x, SolveWith(base));
  EXPECT_LT(BackwardError(shifted, n, u.order(), x, b), 64.0 * (double)m * ME_REAL_EPSILON);
}

namespace {

struct Named {
  std::string name;
  kea_test::ContactProblem problem;
};

// Problems whose free blocks take the dense path (a stack of six, a car).
std::vector<Named> DenseProblems() {
  std::vector<Named> all;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    all.push_back({"stack6 seed " + std::to_string(seed), kea_test::Stack(6, seed)});
    all.push_back({"stack3 seed " + std::to_string(seed), kea_test::Stack(3, seed)});
    all.push_back({"car seed " + std::to_string(seed), kea_test::Car(seed)});
  }
  return all;
}

}  // namespace

TEST(SchurUpdate, ServesPivotsOfTheSparseSolverAndAgreesWithRefactorising) {
  int updates = 0, factorisationsWith = 0, factorisationsWithout = 0;
  for (const Named &t : DenseProblems()) {
    KeaOptions with, without;
    without.factorUpdateRows = 0;
    const KeaResult u = KeaSolveSparse(t.problem.sparse(), with);
    const KeaResult r = KeaSolveSparse(t.problem.sparse(), without);
    ASSERT_EQ(u.status, KeaStatus::Solved) << t.name;
    ASSERT_EQ(r.status, KeaStatus::Solved) << t.name;
    EXPECT_EQ(r.factorUpdates, 0) << t.name;
    updates += u.factorUpdates;
    factorisationsWith += u.factorizations;
    factorisationsWithout += r.factorizations;
    const double scale = 1 + kea_test::MaxAbs(r.lambda);
    for (size_t i = 0; i < r.lambda.size(); ++i)
      EXPECT_NEAR(u.lambda[i], r.lambda[i], 10 * kea_test::kTol * scale) << t.name << " row " << i;
  }
  // Cold solves pivot: some pivots are served by updates, and each spares a
  // factorisation.
  EXPECT_GT(updates, 0);
  EXPECT_LT(factorisationsWith, factorisationsWithout);
}
