// Tests of the sparse Kea solvers (KeaSolveSparse, engine/kea/kea_sparse.cpp):
// agreement with the dense solvers on random body-structured problems, with
// and without friction; small problems against exhaustive enumeration of the
// active sets; a 3000-row chain; bad CSR input; the iteration cap; cycles.
#include "kea_tolerance.h"
#include "kea_lcp.h"
#include "kea_enumerate.h"
#include "support/warning_capture.h"

#include "MeMessage.h"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace karma::kea;

namespace {

using kea_test::kTol;

const MeReal kInf = MEINFINITY;

using karma_test::WarningCapture;

// A sparse problem owning its arrays, with its dense twin.
struct Owned {
  int n = 0;
  std::vector<int> rowStart, col, findex;
  std::vector<MeReal> val, b, lo, hi, mu, dense;
  SparseLcpProblem sparse() const { return {n, rowStart, col, val, b, lo, hi, findex, mu}; }
  LcpProblem problem() const { return {n, dense, b, lo, hi, findex, mu}; }
};

// A = J M^-1 J^T (+ diag) in CSR and dense, from a row -> (body0, body1)
// structure: each row has random 6-vectors on its bodies (body -1 is the
// world), each body a random diagonal inverse mass in [0.5, 2].
void Assemble(Owned &o, const std::vector<std::pair<int, int>> &rowBodies, int bodies, std::mt19937 &rng,
              double diagonal) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), m(0.5, 2.0);
  const int n = static_cast<int>(rowBodies.size());
  Eigen::SparseMatrix<double, Eigen::RowMajor> J(n, 6 * bodies), Minv(6 * bodies, 6 * bodies);
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < n; ++r)
    for (int body : {rowBodies[static_cast<std::size_t>(r)].first, rowBodies[static_cast<std::size_t>(r)].second})
      if (body >= 0)
        for (int d = 0; d < 6; ++d) t.emplace_back(r, 6 * body + d, u(rng));
  J.setFromTriplets(t.begin(), t.end());
  t.clear();
  for (int d = 0; d < 6 * bodies; ++d) t.emplace_back(d, d, m(rng));
  Minv.setFromTriplets(t.begin(), t.end());
  Eigen::SparseMatrix<double, Eigen::RowMajor> A =
      J * Minv * Eigen::SparseMatrix<double, Eigen::RowMajor>(J.transpose());
  for (int i = 0; i < n; ++i) A.coeffRef(i, i) += diagonal;
  A.makeCompressed();
  o.n = n;
  o.rowStart.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
  o.col.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  o.val.clear();
  for (Eigen::Index k = 0; k < A.nonZeros(); ++k) o.val.push_back(static_cast<MeReal>(A.valuePtr()[k]));
  o.dense.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i)
    for (int k = o.rowStart[static_cast<std::size_t>(i)]; k < o.rowStart[static_cast<std::size_t>(i) + 1]; ++k)
      o.dense[static_cast<std::size_t>(i) * static_cast<std::size_t>(n) +
              static_cast<std::size_t>(o.col[static_cast<std::size_t>(k)])] = o.val[static_cast<std::size_t>(k)];
}

// Random bounds as in kea_lcp_test.cpp: unbounded, contact, box, one-sided.
void RandomBounds(Owned &o, std::mt19937 &rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 4);
  o.b.clear();
  o.lo.clear();
  o.hi.clear();
  for (int i = 0; i < o.n; ++i) {
    o.b.push_back(static_cast<MeReal>(u(rng)));
    const double l = -std::fabs(u(rng)) * 0.5, h = std::fabs(u(rng)) * 0.5;
    switch (kind(rng)) {
      case 0:
        o.lo.push_back(-kInf);
        o.hi.push_back(kInf);
        break;
      case 1:
        o.lo.push_back(0);
        o.hi.push_back(kInf);
        break;
      case 2:
        o.lo.push_back(static_cast<MeReal>(l));
        o.hi.push_back(static_cast<MeReal>(h));
        break;
      case 3:
        o.lo.push_back(-kInf);
        o.hi.push_back(static_cast<MeReal>(h));
        break;
      default:
        o.lo.push_back(static_cast<MeReal>(l));
        o.hi.push_back(kInf);
        break;
    }
  }
}

// n rows between random pairs of `bodies` bodies (or a body and the world).
Owned RandomSparse(int n, int bodies, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(-1, bodies - 1);
  std::vector<std::pair<int, int>> rows;
  for (int r = 0; r < n; ++r) {
    int a = pick(rng), c = pick(rng);
    if (a < 0) a = 0;
    if (c == a) c = -1;
    rows.emplace_back(a, c);
  }
  Owned o;
  Assemble(o, rows, bodies, rng, 0.1);
  RandomBounds(o, rng);
  return o;
}

// Contacts between random body pairs: a normal row [0, inf) and two
// friction rows tied to it (mu in [0.2, 1]).
Owned RandomFriction(int contacts, int bodies, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(-1, bodies - 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0), mu(0.2, 1.0);
  std::vector<std::pair<int, int>> rows;
  for (int c = 0; c < contacts; ++c) {
    int a = pick(rng), d = pick(rng);
    if (a < 0) a = 0;
    if (d == a) d = -1;
    for (int k = 0; k < 3; ++k) rows.emplace_back(a, d);
  }
  Owned o;
  Assemble(o, rows, bodies, rng, 0.1);
  for (int c = 0; c < contacts; ++c) {
    const MeReal m = static_cast<MeReal>(mu(rng));
    for (int k = 0; k < 3; ++k) {
      o.b.push_back(static_cast<MeReal>(k == 0 ? std::fabs(u(rng)) : 3 * u(rng)));
      o.lo.push_back(0);
      o.hi.push_back(k == 0 ? kInf : 0);
      o.findex.push_back(k == 0 ? -1 : 3 * c);
      o.mu.push_back(k == 0 ? 0 : m);
    }
  }
  return o;
}

// A chain: joint k ties body k-1 (the world for k = 0) to body k with three
// rows; every `contactEvery`-th row is a contact [0, inf), the rest are
// bilateral.
Owned Chain(int joints, unsigned seed, int contactEvery) {
  std::mt19937 rng(seed);
  std::vector<std::pair<int, int>> rows;
  for (int k = 0; k < joints; ++k)
    for (int r = 0; r < 3; ++r) rows.emplace_back(k, k - 1);
  Owned o;
  Assemble(o, rows, joints, rng, 0.01);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < o.n; ++i) {
    o.b.push_back(static_cast<MeReal>(u(rng)));
    const bool contact = contactEvery > 0 && i % contactEvery == 0;
    o.lo.push_back(contact ? 0 : -kInf);
    o.hi.push_back(kInf);
  }
  return o;
}

double MaxAbs(const std::vector<MeReal> &v) {
  double m = 0;
  for (MeReal x : v) m = std::max(m, std::fabs(double(x)));
  return m;
}

}  // namespace

TEST(KeaSparse, SmallProblemsMatchExhaustiveEnumeration) {
  int checked = 0;
  for (int n = 1; n <= 6; ++n) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
      const Owned o = RandomSparse(n, 1 + n / 2, 500u * static_cast<unsigned>(n) + seed);
      int found = 0;
      const std::vector<double> expected = kea_test::EnumerateLcp(o.problem(), &found);
      ASSERT_EQ(found, 1) << "n=" << n << " seed=" << seed;
      const KeaResult r = KeaSolveSparse(o.sparse(), KeaOptions{});
      ASSERT_EQ(r.status, KeaStatus::Solved) << "n=" << n << " seed=" << seed << " " << KeaStatusName(r.status);
      double scale = 1;
      for (double x : expected) scale = std::max(scale, 1 + std::fabs(x));
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(r.lambda[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)], kTol * scale)
            << "n=" << n << " seed=" << seed << " row " << i;
      KeaOptions warm;
      warm.warmStart = r.lambda;
      const KeaResult again = KeaSolveSparse(o.sparse(), warm);
      EXPECT_EQ(again.status, KeaStatus::Solved);
      EXPECT_EQ(again.iterations, 1);

      KeaOptions pgs;
      pgs.method = KeaMethod::PGS;
      pgs.maxIterations = 20000;
      pgs.warnings = false;
      const KeaResult g = KeaSolveSparse(o.sparse(), pgs);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(g.lambda[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)], 5 * kTol * scale)
            << "PGS n=" << n << " seed=" << seed << " row " << i;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 120);
}

TEST(KeaSparse, AgreesWithDenseOnRandomBoxedProblems) {
  // Sizes on both sides of the dense-block threshold, so that the sparse
  // LDL^T is exercised.
  for (int n : {8, 25, 60, 120}) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const Owned o = RandomSparse(n, std::max(2, n / 3), 9000u * static_cast<unsigned>(n) + seed);
      const KeaResult dense = KeaSolveActiveSet(o.problem(), KeaOptions{});
      const KeaResult sparse = KeaSolveSparse(o.sparse(), KeaOptions{});
      ASSERT_EQ(dense.status, KeaStatus::Solved) << "n=" << n << " seed=" << seed;
      ASSERT_EQ(sparse.status, KeaStatus::Solved) << "n=" << n << " seed=" << seed;
      const double scale = 1 + MaxAbs(dense.lambda);
      for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(sparse.lambda[static_cast<std::size_t>(i)], dense.lambda[static_cast<std::size_t>(i)], kTol * scale)
            << "n=" << n << " seed=" << seed << " row " << i;
        EXPECT_NEAR(sparse.w[static_cast<std::size_t>(i)], dense.w[static_cast<std::size_t>(i)], kTol * scale);
      }
      // With eps: both add it to the diagonal.
      KeaOptions soft;
      soft.epsilon = MeReal(0.05);
      const KeaResult ds = KeaSolveActiveSet(o.problem(), soft), ss = KeaSolveSparse(o.sparse(), soft);
      ASSERT_EQ(ss.status, KeaStatus::Solved);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(ss.lambda[static_cast<std::size_t>(i)], ds.lambda[static_cast<std::size_t>(i)], kTol * scale);
      // PGS: the same sweeps, so the same iterates up to rounding.
      KeaOptions pgs;
      pgs.method = KeaMethod::PGS;
      pgs.maxIterations = 30;
      pgs.warnings = false;
      const KeaResult dp = KeaSolvePGS(o.problem(), pgs), sp = KeaSolveSparse(o.sparse(), pgs);
      EXPECT_EQ(dp.iterations, sp.iterations);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(sp.lambda[static_cast<std::size_t>(i)], dp.lambda[static_cast<std::size_t>(i)], 10 * kTol * scale);
    }
  }
}

TEST(KeaSparse, AgreesWithDenseWithFriction) {
  // The friction fixed point does not converge on every random problem (the
  // contract allows that: IterationLimit); both solvers must then agree on
  // the status, and most problems must be solved.
  int solved = 0, total = 0;
  for (int contacts : {2, 10, 30}) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const Owned o =
          RandomFriction(contacts, std::max(2, contacts / 2), 300u * static_cast<unsigned>(contacts) + seed);
      const int n = o.n;
      KeaOptions opt;
      opt.warnings = false;
      const KeaResult dense = KeaSolveActiveSet(o.problem(), opt);
      const KeaResult sparse = KeaSolveSparse(o.sparse(), opt);
      ++total;
      EXPECT_EQ(sparse.status, dense.status) << "contacts=" << contacts << " seed=" << seed;
      if (dense.status != KeaStatus::Solved || sparse.status != KeaStatus::Solved) continue;
      ++solved;
      const double scale = 1 + MaxAbs(dense.lambda);
      for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(sparse.lambda[static_cast<std::size_t>(i)], dense.lambda[static_cast<std::size_t>(i)],
                    10 * kTol * scale)
            << "contacts=" << contacts << " seed=" << seed << " row " << i;
        const int j = o.findex[static_cast<std::size_t>(i)];
        if (j < 0) {
          EXPECT_GE(sparse.lambda[static_cast<std::size_t>(i)], -kTol);
        } else {
          const double limit =
              o.mu[static_cast<std::size_t>(i)] * std::max(0.0, double(sparse.lambda[static_cast<std::size_t>(j)]));
          EXPECT_LE(std::fabs(sparse.lambda[static_cast<std::size_t>(i)]), limit + kTol * (1 + limit));
        }
      }
      KeaOptions pgs;
      pgs.method = KeaMethod::PGS;
      pgs.maxIterations = 25;
      pgs.warnings = false;
      const KeaResult dp = KeaSolvePGS(o.problem(), pgs), sp = KeaSolveSparse(o.sparse(), pgs);
      EXPECT_EQ(dp.iterations, sp.iterations);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(sp.lambda[static_cast<std::size_t>(i)], dp.lambda[static_cast<std::size_t>(i)], 10 * kTol * scale);
    }
  }
  EXPECT_GE(solved * 5, total * 4) << solved << " of " << total << " solved";
}

TEST(KeaSparse, LongChainIsSolved) {
  const Owned o = Chain(1000, 7, 7);  // 3000 rows
  ASSERT_EQ(o.n, 3000);
  // Banded: a handful of entries per row.
  EXPECT_LE(o.col.size(), static_cast<std::size_t>(o.n) * 12);
  const KeaResult r = KeaSolveSparse(o.sparse(), KeaOptions{});
  EXPECT_EQ(r.status, KeaStatus::Solved) << KeaStatusName(r.status) << " residual " << r.residual;
  ASSERT_EQ(r.lambda.size(), 3000u);
  for (MeReal l : r.lambda) EXPECT_TRUE(std::isfinite(l));
  for (int i = 0; i < o.n; i += 7) EXPECT_GE(r.lambda[static_cast<std::size_t>(i)], 0);
  // Warm-started from its answer: one solve.
  KeaOptions warm;
  warm.warmStart = r.lambda;
  const KeaResult again = KeaSolveSparse(o.sparse(), warm);
  EXPECT_EQ(again.status, KeaStatus::Solved);
  EXPECT_EQ(again.iterations, 1);
}

// trustedStructure skips the CSR checks (the caller built the structure),
// never the checks of the values: the same answer bit for bit on a good
// problem, and BadInput for a NaN in A or an infinite b.
TEST(KeaSparse, ATrustedStructureStillHasItsValuesChecked) {
  const Owned good = RandomSparse(12, 3, 5);
  KeaOptions trusted;
  trusted.trustedStructure = true;
  const KeaResult checked = KeaSolveSparse(good.sparse(), KeaOptions{});
  const KeaResult skipped = KeaSolveSparse(good.sparse(), trusted);
  ASSERT_EQ(checked.status, KeaStatus::Solved);
  EXPECT_EQ(skipped.status, KeaStatus::Solved);
  EXPECT_EQ(skipped.lambda, checked.lambda);
  Owned o = good;
  o.val[3] = std::numeric_limits<MeReal>::quiet_NaN();
  {
    WarningCapture capture;
    EXPECT_EQ(KeaSolveSparse(o.sparse(), trusted).status, KeaStatus::BadInput);
    EXPECT_TRUE(capture.saw("bad input"));
  }
  o = good;
  o.b[2] = std::numeric_limits<MeReal>::infinity();
  {
    WarningCapture capture;
    EXPECT_EQ(KeaSolveSparse(o.sparse(), trusted).status, KeaStatus::BadInput);
    EXPECT_TRUE(capture.saw("bad input"));
  }
}

TEST(KeaSparse, BadCsrInputIsReportedWithoutCrashing) {
  const Owned good = RandomSparse(4, 2, 11);
  ASSERT_EQ(KeaSolveSparse(good.sparse(), KeaOptions{}).status, KeaStatus::Solved);
  auto expectBad = [](const Owned &o, const char *what) {
    for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
      WarningCapture capture;
      KeaOptions opt;
      opt.method = method;
      const KeaResult r = KeaSolveSparse(o.sparse(), opt);
      EXPECT_EQ(r.status, KeaStatus::BadInput) << what;
      EXPECT_EQ(r.lambda.size(), static_cast<std::size_t>(std::max(o.n, 0))) << what;
      for (MeReal l : r.lambda) EXPECT_EQ(l, 0) << what;
      EXPECT_TRUE(capture.saw("bad input")) << what;
    }
  };
  Owned o = good;
  o.rowStart.pop_back();
  expectBad(o, "row starts too short");
  o = good;
  o.rowStart[0] = 1;
  expectBad(o, "row starts not from 0");
  o = good;
  std::swap(o.rowStart[1], o.rowStart[2]);
  expectBad(o, "row starts descending");
  o = good;
  o.col.pop_back();
  expectBad(o, "columns too short");
  o = good;
  o.val.pop_back();
  expectBad(o, "values too short");
  o = good;
  o.col[0] = 7;
  expectBad(o, "column out of range");
  o = good;
  o.col[0] = -1;
  expectBad(o, "negative column");
  o = good;
  std::swap(o.col[0], o.col[1]);
  expectBad(o, "columns not ascending");
  o = good;
  o.val[2] = std::numeric_limits<MeReal>::quiet_NaN();
  expectBad(o, "NaN in A");
  o = good;
  o.b[1] = std::numeric_limits<MeReal>::infinity();
  expectBad(o, "infinite b");
  o = good;
  o.lo[0] = 1;
  o.hi[0] = 0;
  expectBad(o, "lo > hi");
  o = good;
  o.findex = {-1, 0, 1, -1};
  o.mu = {0, 1, 1, 0};
  expectBad(o, "friction row tied to a friction row");
  // A row without its diagonal: a 2x2 with only the off-diagonal entries.
  Owned off;
  off.n = 2;
  off.rowStart = {0, 1, 2};
  off.col = {1, 0};
  off.val = {1, 1};
  off.b = {1, 1};
  off.lo = {0, 0};
  off.hi = {kInf, kInf};
  expectBad(off, "missing diagonal");
  o = good;
  o.n = -1;
  expectBad(o, "negative n");
  // The empty problem is solved.
  Owned empty;
  empty.rowStart = {0};
  EXPECT_EQ(KeaSolveSparse(empty.sparse(), KeaOptions{}).status, KeaStatus::Solved);
}

TEST(KeaSparse, IterationCapIsReported) {
  // The chain with contacts: starting with every contact at lo, one linear
  // solve does not finish.
  const Owned o = Chain(20, 3, 2);
  for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
    WarningCapture capture;
    KeaOptions opt;
    opt.method = method;
    opt.maxIterations = 1;
    const KeaResult r = KeaSolveSparse(o.sparse(), opt);
    EXPECT_EQ(r.status, KeaStatus::IterationLimit) << KeaStatusName(r.status);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_GT(r.residual, 0);
    EXPECT_TRUE(capture.saw("maximum number of iterations exceeded"));
    EXPECT_TRUE(capture.saw("KeaSolveSparse"));
  }
  WarningCapture capture;
  KeaOptions quiet;
  quiet.maxIterations = 1;
  quiet.warnings = false;
  EXPECT_EQ(KeaSolveSparse(o.sparse(), quiet).status, KeaStatus::IterationLimit);
  EXPECT_EQ(capture.count(), 0u);
}

TEST(KeaSparse, CycleIsDetected) {
  Owned o;
  o.n = 1;
  o.rowStart = {0, 1};
  o.col = {0};
  o.val = {-1};
  o.b = {1};
  o.lo = {0};
  o.hi = {kInf};
  WarningCapture capture;
  const KeaResult r = KeaSolveSparse(o.sparse(), KeaOptions{});
  EXPECT_EQ(r.status, KeaStatus::CycleDetected) << KeaStatusName(r.status);
  EXPECT_TRUE(capture.saw("cycle has been detected"));
}
