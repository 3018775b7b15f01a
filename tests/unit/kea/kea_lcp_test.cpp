// Tests of the Kea boxed-LCP contract (engine/kea/kea_lcp.h).
#include "kea_tolerance.h"
#include "kea_lcp.h"
#include "kea_internal.h"
#include "kea_enumerate.h"
#include "support/warning_capture.h"

#include "MeMessage.h"

#include <Eigen/Dense>
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

// A problem owning its arrays; problem() gives the spans.
struct Owned {
  int n = 0;
  std::vector<MeReal> A, b, lo, hi, mu;
  std::vector<int> findex;
  LcpProblem problem() const { return {n, A, b, lo, hi, findex, mu}; }
};

using karma_test::WarningCapture;

// A = M M^T + 0.1 I with M uniform in [-1, 1]; b uniform in [-1, 1]; each
// row's bounds drawn from: unbounded, contact [0, inf), a finite box,
// (-inf, hi], [lo, inf).
Owned RandomBoxed(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = u(rng);
  const Eigen::MatrixXd A = M * M.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
  Owned o;
  o.n = n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) o.A.push_back(static_cast<MeReal>(A(i, j)));
  std::uniform_int_distribution<int> kind(0, 4);
  for (int i = 0; i < n; ++i) {
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
  return o;
}

double MaxAbs(const std::vector<double> &v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

}  // namespace

TEST(KeaLcp, UnboundedSpdSystemIsTheLinearSolve) {
  Owned o;
  o.n = 4;
  o.A = {4, 1, 0, 0.5f, 1, 3, 0.25f, 0, 0, 0.25f, 2, 0.1f, 0.5f, 0, 0.1f, 5};
  o.b = {1, -2, 0.5f, 3};
  o.lo.assign(4, -kInf);
  o.hi.assign(4, kInf);
  Eigen::MatrixXd A(4, 4);
  Eigen::VectorXd b(4);
  for (int i = 0; i < 4; ++i) {
    b(i) = o.b[static_cast<std::size_t>(i)];
    for (int j = 0; j < 4; ++j) A(i, j) = o.A[static_cast<std::size_t>(i * 4 + j)];
  }
  const Eigen::VectorXd x = A.ldlt().solve(b);
  for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
    KeaOptions opt;
    opt.method = method;
    opt.maxIterations = method == KeaMethod::PGS ? 500 : 0;
    const KeaResult r = KeaSolve(o.problem(), opt);
    EXPECT_EQ(r.status, KeaStatus::Solved) << KeaStatusName(r.status);
    ASSERT_EQ(r.lambda.size(), 4u);
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(r.lambda[static_cast<std::size_t>(i)], x(i), kTol * (1 + x.cwiseAbs().maxCoeff()));
    if (method == KeaMethod::ActiveSet) {
      EXPECT_EQ(r.iterations, 1);
    }
  }
}

TEST(KeaLcp, ActiveSetMatchesExhaustiveEnumeration) {
  int checked = 0;
  for (int n = 1; n <= 6; ++n) {
    for (unsigned seed = 1; seed <= 25; ++seed) {
      const Owned o = RandomBoxed(n, 1000u * static_cast<unsigned>(n) + seed);
      int found = 0;
      const std::vector<double> expected = kea_test::EnumerateLcp(o.problem(), &found);
      ASSERT_EQ(found, 1) << "n=" << n << " seed=" << seed;
      const KeaResult r = KeaSolveActiveSet(o.problem(), KeaOptions{});
      ASSERT_EQ(r.status, KeaStatus::Solved) << "n=" << n << " seed=" << seed << " " << KeaStatusName(r.status);
      EXPECT_LE(r.residual, KeaDefaultTolerance() * 2);
      const double scale = 1 + MaxAbs(expected);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(r.lambda[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)], kTol * scale)
            << "n=" << n << " seed=" << seed << " row " << i;
      // Warm-started from its own answer, one linear solve suffices.
      KeaOptions warm;
      warm.warmStart = r.lambda;
      const KeaResult again = KeaSolveActiveSet(o.problem(), warm);
      EXPECT_EQ(again.status, KeaStatus::Solved);
      EXPECT_EQ(again.iterations, 1) << "n=" << n << " seed=" << seed;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 150);
}

TEST(KeaLcp, PgsConvergesWithManySweepsAndIsWorseWithFew) {
  for (int n = 2; n <= 6; ++n) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
      const Owned o = RandomBoxed(n, 7000u * static_cast<unsigned>(n) + seed);
      int found = 0;
      const std::vector<double> expected = kea_test::EnumerateLcp(o.problem(), &found);
      ASSERT_EQ(found, 1);
      KeaOptions many;
      many.method = KeaMethod::PGS;
      many.maxIterations = 20000;
      many.warnings = false;
      const KeaResult r = KeaSolvePGS(o.problem(), many);
      const double scale = 1 + MaxAbs(expected);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(r.lambda[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)], 5 * kTol * scale)
            << "n=" << n << " seed=" << seed << " row " << i;

      KeaOptions few = many;
      few.maxIterations = 1;
      const KeaResult rough = KeaSolvePGS(o.problem(), few);
      EXPECT_LE(rough.iterations, 1);
      EXPECT_GE(rough.residual, r.residual) << "n=" << n << " seed=" << seed;
    }
  }
  // Strongly coupled rows (Gauss-Seidel contracts by about 0.98 per sweep):
  // the sweep budget visibly trades cost for accuracy.
  Owned o;
  o.n = 2;
  o.A = {1, 0.99f, 0.99f, 1};
  o.b = {1, 0.5f};
  o.lo.assign(2, -kInf);
  o.hi.assign(2, kInf);
  KeaOptions opt;
  opt.method = KeaMethod::PGS;
  opt.warnings = false;
  opt.maxIterations = 3;
  const KeaResult rough = KeaSolvePGS(o.problem(), opt);
  opt.maxIterations = 2000;
  const KeaResult fine = KeaSolvePGS(o.problem(), opt);
  EXPECT_EQ(rough.status, KeaStatus::IterationLimit);
  EXPECT_EQ(fine.status, KeaStatus::Solved);
  EXPECT_GT(rough.residual, 10 * fine.residual);
}

TEST(KeaLcp, RedundantRowsAreSolvedWithEpsilon) {
  // Two identical contact rows (J = [1; 1] on a unit mass): A = [[1,1],[1,1]]
  // is singular. With eps > 0 the answer is unique and splits evenly.
  Owned o;
  o.n = 2;
  o.A = {1, 1, 1, 1};
  o.b = {1, 1};
  o.lo = {0, 0};
  o.hi = {kInf, kInf};
  for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
    KeaOptions opt;
    opt.method = method;
    opt.epsilon = MeReal(0.01);
    opt.maxIterations = method == KeaMethod::PGS ? 5000 : 0;
    const KeaResult r = KeaSolve(o.problem(), opt);
    EXPECT_EQ(r.status, KeaStatus::Solved) << KeaStatusName(r.status);
    const double expected = 1.0 / 2.01;
    EXPECT_NEAR(r.lambda[0], expected, 10 * kTol);
    EXPECT_NEAR(r.lambda[1], expected, 10 * kTol);
  }
  // Inconsistent bilateral rows (b = [1, 2]) have no exact solution at
  // eps = 0; eps > 0 makes them solvable: lambda = (A + eps I)^-1 b.
  o.b = {1, 2};
  o.lo = {-kInf, -kInf};
  KeaOptions opt;
  opt.epsilon = MeReal(0.1);
  const KeaResult r = KeaSolveActiveSet(o.problem(), opt);
  EXPECT_EQ(r.status, KeaStatus::Solved);
  // (A + 0.1 I)^-1 = 1/(1.1^2 - 1) [[1.1, -1], [-1, 1.1]]
  const double det = 1.1 * 1.1 - 1.0;
  EXPECT_NEAR(r.lambda[0], (1.1 * 1 - 2) / det, 10 * kTol * 10);
  EXPECT_NEAR(r.lambda[1], (-1 + 1.1 * 2) / det, 10 * kTol * 10);
}

TEST(KeaLcp, FrictionRowIsBoundedByMuTimesNormal) {
  // One contact: normal row 0 and two friction rows tied to it; the
  // right-hand side pushes the friction rows hard, so they saturate.
  Owned o;
  o.n = 3;
  o.A = {2, 0.3f, 0.1f, 0.3f, 1, 0.2f, 0.1f, 0.2f, 1.5f};
  o.b = {1, 5, -4};
  o.lo = {0, 0, 0};
  o.hi = {kInf, 0, 0};
  o.findex = {-1, 0, 0};
  o.mu = {0, 0.5f, 0.25f};
  for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
    KeaOptions opt;
    opt.method = method;
    opt.maxIterations = method == KeaMethod::PGS ? 2000 : 0;
    const KeaResult r = KeaSolve(o.problem(), opt);
    EXPECT_EQ(r.status, KeaStatus::Solved) << KeaStatusName(r.status);
    const double ln = r.lambda[0];
    EXPECT_GT(ln, 0);
    EXPECT_LE(std::fabs(r.lambda[1]), 0.5 * ln + 1e-6);
    EXPECT_LE(std::fabs(r.lambda[2]), 0.25 * ln + 1e-6);
    // Saturated: at the bounds, with w of the matching sign.
    EXPECT_NEAR(r.lambda[1], 0.5 * ln, 10 * kTol);
    EXPECT_NEAR(r.lambda[2], -0.25 * ln, 10 * kTol);
    EXPECT_LE(r.w[1], 10 * kTol);
    EXPECT_GE(r.w[2], -10 * kTol);
  }

  // Random multi-contact problems: every friction row within its cone box.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int contacts = 1 + static_cast<int>(seed % 3), n = 3 * contacts;
    Eigen::MatrixXd M(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = u(rng);
    const Eigen::MatrixXd A = M * M.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
    Owned f;
    f.n = n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) f.A.push_back(static_cast<MeReal>(A(i, j)));
    for (int c = 0; c < contacts; ++c) {
      for (int k = 0; k < 3; ++k) {
        f.b.push_back(static_cast<MeReal>(k == 0 ? std::fabs(u(rng)) : 3 * u(rng)));
        f.lo.push_back(0);
        f.hi.push_back(k == 0 ? kInf : 0);
        f.findex.push_back(k == 0 ? -1 : 3 * c);
        f.mu.push_back(static_cast<MeReal>(k == 0 ? 0 : 0.6));
      }
    }
    const KeaResult r = KeaSolveActiveSet(f.problem(), KeaOptions{});
    EXPECT_EQ(r.status, KeaStatus::Solved) << "seed " << seed;
    for (int i = 0; i < n; ++i) {
      const int j = f.findex[static_cast<std::size_t>(i)];
      if (j < 0) {
        EXPECT_GE(r.lambda[static_cast<std::size_t>(i)], -1e-6);
        continue;
      }
      const double limit = 0.6 * std::max(0.0, double(r.lambda[static_cast<std::size_t>(j)]));
      EXPECT_LE(std::fabs(r.lambda[static_cast<std::size_t>(i)]), limit + kTol * 0.05 * (1 + limit)) << "seed " << seed;
    }
  }
}

TEST(KeaLcp, IterationCapReportsIterationLimitAndWarns) {
  // Three pushed contacts: the first guess (all at lo) is wrong, so one
  // linear solve cannot finish.
  Owned o;
  o.n = 3;
  o.A = {2, 0.5f, 0.2f, 0.5f, 2, 0.5f, 0.2f, 0.5f, 2};
  o.b = {1, 1, 1};
  o.lo.assign(3, 0);
  o.hi.assign(3, kInf);
  {
    WarningCapture capture;
    KeaOptions opt;
    opt.maxIterations = 1;
    const KeaResult r = KeaSolveActiveSet(o.problem(), opt);
    EXPECT_EQ(r.status, KeaStatus::IterationLimit);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_GT(r.residual, 0);
    ASSERT_EQ(r.lambda.size(), 3u);
    EXPECT_TRUE(capture.saw("maximum number of iterations exceeded"));
  }
  {
    WarningCapture capture;
    KeaOptions opt;
    opt.method = KeaMethod::PGS;
    opt.maxIterations = 1;
    const KeaResult r = KeaSolve(o.problem(), opt);
    EXPECT_EQ(r.status, KeaStatus::IterationLimit);
    EXPECT_TRUE(capture.saw("maximum number of iterations exceeded"));
    // The best iterate is returned: never worse than the starting point.
    const std::vector<MeReal> zero(3, 0);
    EXPECT_LE(r.residual, KeaResidual(o.problem(), 0, zero));
  }
  {
    WarningCapture capture;
    KeaOptions opt;
    opt.maxIterations = 1;
    opt.warnings = false;
    EXPECT_EQ(KeaSolveActiveSet(o.problem(), opt).status, KeaStatus::IterationLimit);
    EXPECT_EQ(capture.count(), 0u);
  }
  {
    WarningCapture capture;
    const KeaResult r = KeaSolveActiveSet(o.problem(), KeaOptions{});
    EXPECT_EQ(r.status, KeaStatus::Solved);
    EXPECT_EQ(capture.count(), 0u);
  }
}

TEST(KeaLcp, BadInputIsReportedWithoutCrashing) {
  const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
  Owned good;
  good.n = 2;
  good.A = {2, 0, 0, 2};
  good.b = {1, 1};
  good.lo = {0, 0};
  good.hi = {kInf, kInf};

  auto expectBad = [](const Owned &o, const KeaOptions &opt, const char *what) {
    for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
      WarningCapture capture;
      KeaOptions m = opt;
      m.method = method;
      const KeaResult r = KeaSolve(o.problem(), m);
      EXPECT_EQ(r.status, KeaStatus::BadInput) << what;
      EXPECT_EQ(r.lambda.size(), static_cast<std::size_t>(std::max(o.n, 0))) << what;
      for (MeReal l : r.lambda) EXPECT_EQ(l, 0) << what;
      EXPECT_TRUE(capture.saw("bad input")) << what;
    }
  };
  Owned o = good;
  o.A[1] = nan;
  expectBad(o, {}, "NaN in A");
  o = good;
  o.b[0] = nan;
  expectBad(o, {}, "NaN in b");
  o = good;
  o.A.pop_back();
  expectBad(o, {}, "A too short");
  o = good;
  o.lo.pop_back();
  expectBad(o, {}, "lo too short");
  o = good;
  o.lo[0] = 1;
  o.hi[0] = 0;
  expectBad(o, {}, "lo > hi");
  o = good;
  o.lo[1] = kInf;
  expectBad(o, {}, "lo = +inf");
  o = good;
  o.findex = {-1, 5};
  o.mu = {0, 1};
  expectBad(o, {}, "findex out of range");
  o = good;
  o.findex = {-1, 0};
  o.mu = {0, -1};
  expectBad(o, {}, "negative mu");
  o = good;
  o.findex = {1, 0};
  o.mu = {1, 1};
  expectBad(o, {}, "friction row tied to a friction row");
  o = good;
  o.n = -1;
  expectBad(o, {}, "negative n");
  KeaOptions opt;
  opt.epsilon = -1;
  expectBad(good, opt, "negative epsilon");
  opt = {};
  const std::vector<MeReal> shortWarm = {1};
  opt.warmStart = shortWarm;
  expectBad(good, opt, "warm start of the wrong size");

  // An empty problem is trivially solved.
  Owned empty;
  EXPECT_EQ(KeaSolveActiveSet(empty.problem(), {}).status, KeaStatus::Solved);
  EXPECT_EQ(KeaSolvePGS(empty.problem(), {}).status, KeaStatus::Solved);
}

TEST(KeaLcp, CycleInTheActiveSetIsDetected) {
  // A negative "mass" row breaks the contract's semi-definiteness (as
  // rounding can in near-singular systems): at lo, w < 0 asks to free the
  // row; free, lambda < lo sends it back. The method notices the repeat.
  Owned o;
  o.n = 1;
  o.A = {-1};
  o.b = {1};
  o.lo = {0};
  o.hi = {kInf};
  WarningCapture capture;
  const KeaResult r = KeaSolveActiveSet(o.problem(), KeaOptions{});
  EXPECT_EQ(r.status, KeaStatus::CycleDetected) << KeaStatusName(r.status);
  EXPECT_LT(r.iterations, 20);
  EXPECT_TRUE(capture.saw("cycle has been detected"));
  ASSERT_EQ(r.lambda.size(), 1u);
  EXPECT_TRUE(std::isfinite(r.lambda[0]));
}

// The size of a residual (kea_internal.h): the largest |value|, exactly the
// scalar loop's, or infinity once a value is NaN or infinite, at every
// length (whole vector lanes and the rest).
TEST(LargestOrInfinite, IsTheLargestMagnitudeOrInfinityWhenOneIsNotFinite) {
  using karma::kea::detail::LargestOrInfinite;
  const MeReal inf = std::numeric_limits<MeReal>::infinity();
  const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
  EXPECT_EQ(LargestOrInfinite({}), MeReal(0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int n = 1; n <= 19; ++n) {
    std::vector<MeReal> v((size_t)n);
    for (MeReal &e : v) e = (MeReal)u(rng);
    MeReal expected = 0;
    for (MeReal e : v) expected = std::max(expected, std::fabs(e));
    EXPECT_EQ(LargestOrInfinite(v), expected) << n;
    for (int at = 0; at < n; ++at) {
      for (MeReal bad : {nan, inf, -inf}) {
        std::vector<MeReal> w = v;
        w[(size_t)at] = bad;
        EXPECT_EQ(LargestOrInfinite(w), inf) << n << " at " << at;
      }
      std::vector<MeReal> w = v;  // the largest magnitude, negative, at any place
      w[(size_t)at] = -std::numeric_limits<MeReal>::max();
      EXPECT_EQ(LargestOrInfinite(w), std::numeric_limits<MeReal>::max()) << n << " at " << at;
    }
    const std::vector<MeReal> zeros((size_t)n, -MeReal(0));  // -0 gives +0, as fabs does
    const MeReal zero = LargestOrInfinite(zeros);
    EXPECT_EQ(zero, MeReal(0));
    EXPECT_FALSE(std::signbit(zero)) << n;
  }
}
