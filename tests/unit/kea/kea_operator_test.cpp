// A problem with an operator (SparseLcpProblem::op, kea_lcp.h): Kea applies
// A through it and reads A's entries only after assemble(), to factorise.
// The test operator holds a problem of the step's structure
// (kea_contact_problems.h), sums each row's products in the reverse order
// of the CSR (so its rounding differs from the stored rows'), and keeps
// NaN in the values until assemble() copies them in: an entry read too
// early poisons the answer. Checked: a solve without a kept factor
// assembles first and gives the stored matrix's bits; one that starts on
// the kept factor agrees with the stored matrix's answer to the tolerance
// and, when it ends on that factor, assembles nothing; a far problem
// assembles once; PGS assembles first; an operator that does not vouch for
// its values is assembled and checked. A warm start checked on the kept
// factor (KeaOptions::acceptWarmStart) is scored through the operator: kept,
// it reads no entry; not kept, it is multiplied once however the solve ends.
#include "kea_tolerance.h"
#include "kea_contact_problems.h"
#include "kea_lcp.h"
#include "kea_activeset_core.h"
#include "kea_sparse_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

using namespace karma::kea;
using kea_test::ContactProblem;

namespace {

using kea_test::kTol;

class ReversedRows final : public SparseLcpOperator {
 public:
  explicit ReversedRows(const ContactProblem &p, bool bounded = true)
      : p_(p), values_(p.val.size(), std::numeric_limits<MeReal>::quiet_NaN()), entriesFinite_(bounded) {}

  SparseLcpProblem problem() const {
    SparseLcpProblem s = p_.sparse();
    s.val = values_;
    s.op = this;
    return s;
  }
  int assembled() const { return assembled_; }
  // Counts from now on the products of every row with `x` (bit for bit).
  void watch(std::span<const MeReal> x) {
    watched_.assign(x.begin(), x.end());
    watchedProducts_ = 0;
  }
  int watchedProducts() const { return watchedProducts_; }

  // Products with A (times, and the timesAndAbsTimesMax that calls it).
  int products() const { return products_; }
  void times(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const override {
    ++products_;
    if (!rows && count == watched_.size() && std::equal(watched_.begin(), watched_.end(), x)) ++watchedProducts_;
    for (std::size_t a = 0; a < count; ++a) y[a] = rowSum(rows ? rows[a] : (int)a, x, false);
  }
  MeReal absTimesMax(const int *rows, std::size_t count, const MeReal *x) const override {
    MeReal largest = 0;
    for (std::size_t a = 0; a < count; ++a) largest = std::max(largest, rowSum(rows ? rows[a] : (int)a, x, true));
    return largest;
  }
  bool entriesFinite() const override { return entriesFinite_; }
  void assemble() const override {
    if (values_[0] == values_[0]) return;  // already filled
    values_ = p_.val;
    ++assembled_;
  }

 private:
  MeReal rowSum(int i, const MeReal *x, bool absolute) const {
    MeReal sum = 0;
    for (int k = p_.rowStart[(size_t)i + 1] - 1; k >= p_.rowStart[(size_t)i]; --k) {
      const MeReal term = p_.val[(size_t)k] * x[p_.col[(size_t)k]];
      sum += absolute ? std::fabs(term) : term;
    }
    return sum;
  }

  const ContactProblem &p_;
  mutable std::vector<MeReal> values_;
  mutable int assembled_ = 0;
  bool entriesFinite_;
  std::vector<MeReal> watched_;
  mutable int watchedProducts_ = 0;
  mutable int products_ = 0;
};

std::vector<std::pair<std::string, ContactProblem>> Problems() {
  std::vector<std::pair<std::string, ContactProblem>> all;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    all.push_back({"stack6 seed " + std::to_string(seed), kea_test::Stack(6, seed)});
    all.push_back({"stack20 seed " + std::to_string(seed), kea_test::Stack(20, seed)});
    all.push_back({"car seed " + std::to_string(seed), kea_test::Car(seed)});
    all.push_back({"chain100 seed " + std::to_string(seed), kea_test::Chain(100, seed)});
  }
  all.push_back({"pile64 (sparse LDL^T)", kea_test::Pile(64, 40, 2)});
  return all;
}

// The problem with every entry of A and of b moved by a relative `size`
// (symmetrically, so A stays symmetric positive definite).
ContactProblem Perturbed(const ContactProblem &p, double size) {
  ContactProblem q = p;
  auto scale = [&](int i) { return 1 + size * kea_test::Jitter(11, (unsigned)i); };
  for (int i = 0; i < p.n; ++i)
    for (int k = p.rowStart[(size_t)i]; k < p.rowStart[(size_t)i + 1]; ++k)
      q.val[(size_t)k] = (MeReal)(p.val[(size_t)k] * scale(i) * scale(p.col[(size_t)k]));
  for (std::size_t i = 0; i < q.b.size(); ++i) q.b[i] = (MeReal)(q.b[i] * scale(p.n + (int)i));
  return q;
}

void ExpectAgree(const KeaResult &a, const KeaResult &b, const std::string &name) {
  const double scale = 1 + kea_test::MaxAbs(b.lambda);
  for (std::size_t i = 0; i < b.lambda.size(); ++i)
    EXPECT_NEAR(a.lambda[i], b.lambda[i], 10 * kTol * scale) << name << " row " << i;
}

}  // namespace

TEST(KeaOperator, WithoutAKeptFactorTheStoredValuesAreUsed) {
  for (const auto &[name, problem] : Problems()) {
    const ReversedRows op(problem);
    const KeaResult stored = KeaSolveSparse(problem.sparse(), KeaOptions{});
    const KeaResult applied = KeaSolveSparse(op.problem(), KeaOptions{});
    ASSERT_EQ(stored.status, KeaStatus::Solved) << name;
    ASSERT_EQ(applied.status, KeaStatus::Solved) << name;
    EXPECT_EQ(op.assembled(), 1) << name;  // no kept factor: assembled first
    EXPECT_EQ(applied.lambda, stored.lambda) << name;
  }
}

TEST(KeaOperator, ASolveOnTheKeptFactorAssemblesNothing) {
  int stale = 0;
  for (const auto &[name, problem] : Problems()) {
    const ContactProblem near = Perturbed(problem, 1e-5), far = Perturbed(problem, 0.3);
    const ReversedRows first(problem), nearOp(near), farOp(far);
    kea_test::Workspace workspace(KeaWorkspaceCreate());
    KeaOptions o;
    o.factorMemory = KeaFactorMemory::Always;
    // Without updates the kept factor is the answer's set's, which the near
    // problem's warm start begins from (kea_factor_memory_test.cpp).
    o.factorUpdateRows = 0;
    KeaResult r1, r2, r3;
    KeaSolveSparse(first.problem(), o, *workspace, r1);
    ASSERT_EQ(r1.status, KeaStatus::Solved) << name;
    o.warmStart = r1.lambda;
    KeaSolveSparse(nearOp.problem(), o, *workspace, r2);
    ASSERT_EQ(r2.status, KeaStatus::Solved) << name;
    // Every solve of the near problem on the kept factor: nothing read.
    if (r2.factorizations == 0) {
      ++stale;
      EXPECT_GE(r2.staleSolves, 1) << name;
      EXPECT_EQ(nearOp.assembled(), 0) << name;
    } else {
      EXPECT_EQ(nearOp.assembled(), 1) << name;
    }
    ExpectAgree(r2, KeaSolveSparse(near.sparse(), KeaOptions{}), name + " near");
    KeaSolveSparse(farOp.problem(), o, *workspace, r3);
    ASSERT_EQ(r3.status, KeaStatus::Solved) << name;
    EXPECT_EQ(farOp.assembled(), r3.factorizations > 0 ? 1 : 0) << name;
    ExpectAgree(r3, KeaSolveSparse(far.sparse(), KeaOptions{}), name + " far");
  }
  EXPECT_GE(stale, 10);  // the resting problems (all but the pile) keep their factor
}

// The default, factor updates on: the same sequence of solves through the
// operator (the updates' refinement then measures its rounding through
// absTimesMax) agrees with plain solves, and only a factorisation
// assembles A.
TEST(KeaOperator, WithUpdatesTheOperatorsAnswersAgree) {
  for (const auto &[name, problem] : Problems()) {
    const ContactProblem near = Perturbed(problem, 1e-5), far = Perturbed(problem, 0.3);
    const ReversedRows first(problem), nearOp(near), farOp(far);
    kea_test::Workspace workspace(KeaWorkspaceCreate());
    KeaOptions o;
    o.factorMemory = KeaFactorMemory::Always;
    ASSERT_GT(o.factorUpdateRows, 0);
    KeaResult r1, r2, r3;
    KeaSolveSparse(first.problem(), o, *workspace, r1);
    ASSERT_EQ(r1.status, KeaStatus::Solved) << name;
    o.warmStart = r1.lambda;
    KeaSolveSparse(nearOp.problem(), o, *workspace, r2);
    ASSERT_EQ(r2.status, KeaStatus::Solved) << name;
    EXPECT_EQ(nearOp.assembled(), r2.factorizations > 0 ? 1 : 0) << name;
    ExpectAgree(r2, KeaSolveSparse(near.sparse(), KeaOptions{}), name + " near");
    KeaSolveSparse(farOp.problem(), o, *workspace, r3);
    ASSERT_EQ(r3.status, KeaStatus::Solved) << name;
    EXPECT_EQ(farOp.assembled(), r3.factorizations > 0 ? 1 : 0) << name;
    ExpectAgree(r3, KeaSolveSparse(far.sparse(), KeaOptions{}), name + " far");
  }
}

TEST(KeaOperator, ProjectedGaussSeidelAssemblesFirst) {
  const ContactProblem problem = kea_test::Stack(6, 1);
  const ReversedRows op(problem);
  KeaOptions o;
  o.method = KeaMethod::PGS;
  o.maxIterations = 500;
  const KeaResult applied = KeaSolveSparse(op.problem(), o);
  EXPECT_EQ(op.assembled(), 1);
  EXPECT_TRUE(std::isfinite(applied.residual));
  const KeaResult stored = KeaSolveSparse(problem.sparse(), o);
  EXPECT_EQ(applied.iterations, stored.iterations);
}

TEST(KeaOperator, AnUnboundedOperatorIsAssembledAndChecked) {
  ContactProblem problem = kea_test::Stack(6, 1);
  kea_test::Workspace workspace(KeaWorkspaceCreate());
  KeaOptions o;
  o.factorMemory = KeaFactorMemory::Always;
  KeaResult r1, r2;
  KeaSolveSparse(problem.sparse(), o, *workspace, r1);
  ASSERT_EQ(r1.status, KeaStatus::Solved);
  o.warmStart = r1.lambda;
  problem.val[0] = std::numeric_limits<MeReal>::infinity();
  const ReversedRows op(problem, false);
  KeaSolveSparse(op.problem(), o, *workspace, r2);
  EXPECT_EQ(op.assembled(), 1);
  EXPECT_EQ(r2.status, KeaStatus::BadInput);
}

namespace {

// A workspace that has solved `problem` with KeaFactorMemory::Always, so
// that its next solve of that sparsity starts on the kept factor and
// applies the operator; `answer` is that solve's result.
kea_test::Workspace SolvedOnce(const ContactProblem &problem, KeaResult &answer) {
  kea_test::Workspace workspace(KeaWorkspaceCreate());
  KeaOptions o;
  o.factorMemory = KeaFactorMemory::Always;
  KeaSolveSparse(problem.sparse(), o, *workspace, answer);
  return workspace;
}

}  // namespace

TEST(KeaOperator, AWarmStartKeptOnTheKeptFactorReadsNoEntry) {
  // The warm-start check on the kept factor takes its residual through the
  // operator (the values are NaN until assembled): an answer given back is
  // kept exactly when that residual is within the solved threshold over
  // kWarmAcceptDivisor, and then nothing is assembled or solved.
  int kept = 0;
  for (const auto &[name, problem] : Problems()) {
    KeaResult answer, r;
    kea_test::Workspace workspace = SolvedOnce(problem, answer);
    ASSERT_EQ(answer.status, KeaStatus::Solved) << name;
    const ReversedRows reference(problem), op(problem);
    std::vector<MeReal> w(answer.lambda.size());
    const MeReal residual = karma::kea::detail::SparseMultiplyResidual(karma::platform::DefaultKernels(),
                                                                       reference.problem(), 0, answer.lambda, w);
    const MeReal threshold = KeaDefaultTolerance() * (1 + static_cast<MeReal>(kea_test::MaxAbs(problem.b)));
    const bool keep = residual <= threshold / karma::kea::detail::kWarmAcceptDivisor;
    KeaOptions o;
    o.factorMemory = KeaFactorMemory::Always;
    o.warmStart = answer.lambda;
    o.acceptWarmStart = true;
    KeaSolveSparse(op.problem(), o, *workspace, r);
    EXPECT_EQ(reference.assembled(), 0) << name;
    ASSERT_EQ(r.status, KeaStatus::Solved) << name;
    EXPECT_EQ(r.warmStartAccepted, keep) << name << ": residual " << residual << ", threshold " << threshold;
    if (!keep) continue;
    ++kept;
    EXPECT_EQ(op.assembled(), 0) << name;
    EXPECT_EQ(r.iterations, 0) << name;
    EXPECT_EQ(r.factorizations, 0) << name;
    EXPECT_EQ(r.staleSolves, 0) << name;
    EXPECT_TRUE(r.lambda == answer.lambda) << name;
    EXPECT_EQ(r.residual, residual) << name;  // the operator's own residual and w
    EXPECT_TRUE(r.w == w) << name;
  }
  // 10 of the 13: a friction fixed point may stop anywhere within half the
  // threshold, above its sixteenth.
  EXPECT_GE(kept, 8);
}

TEST(KeaOperator, AWarmStartThatFailsItsCheckIsMultipliedOnce) {
  // A warm start far from the answer fails its check; the solve, capped at
  // one linear solve, then ends short of the threshold, where the starting
  // point competes for the best iterate: its residual from the check is
  // used, not computed again (only its w is, when it is returned).
  int capped = 0;
  for (const auto &[name, problem] : Problems()) {
    KeaResult answer, r;
    kea_test::Workspace workspace = SolvedOnce(problem, answer);
    ASSERT_EQ(answer.status, KeaStatus::Solved) << name;
    const ContactProblem far = Perturbed(problem, 0.3);
    ReversedRows op(far);
    KeaOptions o;
    o.factorMemory = KeaFactorMemory::Always;
    o.warmStart = answer.lambda;
    o.acceptWarmStart = true;
    o.maxIterations = 1;
    o.warnings = false;
    op.watch(answer.lambda);
    KeaSolveSparse(op.problem(), o, *workspace, r);
    EXPECT_FALSE(r.warmStartAccepted) << name;
    if (r.status == KeaStatus::Solved) continue;
    ++capped;
    // The check's product, and the one that gives w when the start is the
    // answer returned.
    EXPECT_EQ(op.watchedProducts(), r.lambda == answer.lambda ? 2 : 1) << name;
  }
  EXPECT_GE(capped, 5);  // 7 of the 13 end short of the threshold after one solve
}

// A dense factor is kept, with an operator, while the workspace's stale
// solves average at most kDenseStaleIterations; a stale solve far from its
// factor teaches it to refactorise, and each factor not kept moves the
// expectation back to its prior (kStaleIterationsPrior, the same value).
// The expectation must land on the prior, not stop a few ulps above it: a
// resting car's problems are solved stale again after a few hundred
// factorisations (about 205 in single precision and 515 in double, within
// the 1000 solves allowed).
TEST(KeaOperator, ADenseWorkspaceThatLearntToRefactoriseTriesItsFactorAgain) {
  const ContactProblem car = kea_test::Car(1), near = Perturbed(car, 1e-5), far = Perturbed(car, 0.3);
  const ReversedRows carOp(car), nearOp(near), farOp(far);
  kea_test::Workspace workspace(KeaWorkspaceCreate());
  KeaOptions o;
  o.factorMemory = KeaFactorMemory::WhenCheaper;  // as Mdt asks: a dense factor kept only with an operator
  KeaResult r;
  KeaSolveSparse(carOp.problem(), o, *workspace, r);
  ASSERT_EQ(r.status, KeaStatus::Solved);
  o.warmStart = r.lambda;
  KeaSolveSparse(farOp.problem(), o, *workspace, r);
  ASSERT_EQ(r.status, KeaStatus::Solved);
  ASSERT_EQ(r.staleSolves, 1);  // the kept factor was tried, and failed
  ASSERT_GE(r.factorizations, 1);
  int firstStale = -1;
  for (int solve = 0; solve < 1000 && firstStale < 0; ++solve) {
    o.warmStart = r.lambda;
    KeaSolveSparse(nearOp.problem(), o, *workspace, r);
    ASSERT_EQ(r.status, KeaStatus::Solved);
    if (r.staleSolves > 0 && r.factorizations == 0) firstStale = solve;
  }
  ASSERT_GE(firstStale, 0) << "the dense factor was never kept again";
  EXPECT_GE(firstStale, 16);  // it learnt to refactorise first
}

// A stale solve on a problem whose rows are all free (a chain's joints)
// takes its accepted residual from the conjugate-gradient recursion instead
// of a product of its own (SparseBackend::acceptRecursive): the solve makes
// one product for its start and one an iteration, and none to check its
// answer, which the active set's residual reuses. The answer's residual and
// w, recomputed from the stored rows, still meet the solved threshold and
// agree with the reported ones within an eighth of it, with and without
// eps on the diagonal, and the answer agrees with a fresh solve.
TEST(KeaOperator, AStaleSolveAcceptedOnItsRecursionMeetsTheThreshold) {
  int recursive = 0;
  for (const MeReal eps : {MeReal(0), MeReal(1e-4)}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const std::string name = "chain100 seed " + std::to_string(seed) + " eps " + std::to_string(eps);
      const ContactProblem chain = kea_test::Chain(100, seed), next = Perturbed(chain, 1e-3);
      const ReversedRows first(chain), nextOp(next);
      kea_test::Workspace workspace(KeaWorkspaceCreate());
      KeaOptions o;
      o.factorMemory = KeaFactorMemory::Always;
      o.epsilon = eps;
      KeaResult r;
      KeaSolveSparse(first.problem(), o, *workspace, r);
      ASSERT_EQ(r.status, KeaStatus::Solved) << name;
      o.warmStart = r.lambda;
      KeaSolveSparse(nextOp.problem(), o, *workspace, r);
      ASSERT_EQ(r.status, KeaStatus::Solved) << name;
      if (r.factorizations == 0 && r.staleSolves == 1 && r.staleIterations > 0) {
        ++recursive;
        EXPECT_EQ(nextOp.products(), 1 + r.staleIterations) << name;
      }
      const std::size_t n = (std::size_t)next.n;
      std::vector<MeReal> w(n);
      const MeReal truth = karma::kea::detail::SparseMultiplyResidual(karma::platform::DefaultKernels(),
                                                                      next.sparse(), o.epsilon, r.lambda, w);
      const MeReal threshold = KeaDefaultTolerance() * (1 + (MeReal)kea_test::MaxAbs(next.b));
      EXPECT_LE(truth, threshold) << name;
      EXPECT_NEAR(r.residual, truth, threshold / 8) << name;
      ASSERT_EQ(r.w.size(), n) << name;
      for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(r.w[i], w[i], threshold / 8) << name << " row " << i;
      KeaOptions fresh;
      fresh.epsilon = eps;
      ExpectAgree(r, KeaSolveSparse(next.sparse(), fresh), name);
    }
  }
  EXPECT_GE(recursive, 4);  // the stale solves iterated and ended on the recursion
}
