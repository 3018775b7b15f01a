// Warm starts of the sparse active-set solver on problems with the step's
// structure (kea_contact_problems.h): a problem warm-started from its own
// solution is confirmed by one linear solve and one factorisation with the
// same answer; a slightly changed problem (b perturbed, as from one step to
// the next of a resting scene) converges in a few solves; the workspace
// entry point gives bit-identical answers to the allocating one; the two
// factorisations of the free blocks (sparse, envelope) give the same answers.
#include "kea_tolerance.h"
#include "kea_contact_problems.h"
#include "kea_lcp.h"
#include "kea_activeset_core.h"
#include "kea_sparse_backend.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace karma::kea;
using kea_test::ContactProblem;

namespace {

using kea_test::kTol;

struct Named {
  std::string name;
  ContactProblem problem;
};

std::vector<Named> Problems() {
  std::vector<Named> all;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    all.push_back({"stack3 seed " + std::to_string(seed), kea_test::Stack(3, seed)});
    all.push_back({"stack6 seed " + std::to_string(seed), kea_test::Stack(6, seed)});
    all.push_back({"stack6 frictionless seed " + std::to_string(seed), kea_test::Stack(6, seed, false)});
    all.push_back({"car seed " + std::to_string(seed), kea_test::Car(seed)});
    all.push_back({"chain100 seed " + std::to_string(seed), kea_test::Chain(100, seed)});
  }
  return all;
}

using kea_test::MaxAbs;

using kea_test::Workspace;

}  // namespace

TEST(KeaWarmStart, OwnSolutionIsConfirmedByOneSolve) {
  for (const Named &t : Problems()) {
    const KeaResult cold = KeaSolveSparse(t.problem.sparse(), KeaOptions{});
    ASSERT_EQ(cold.status, KeaStatus::Solved) << t.name;
    KeaOptions warm;
    warm.warmStart = cold.lambda;
    const KeaResult again = KeaSolveSparse(t.problem.sparse(), warm);
    EXPECT_EQ(again.status, KeaStatus::Solved) << t.name;
    EXPECT_EQ(again.iterations, 1) << t.name;
    EXPECT_EQ(again.factorizations, 1) << t.name;
    EXPECT_EQ(again.frictionRounds, 0) << t.name;
    const double scale = 1 + MaxAbs(cold.lambda);
    for (std::size_t i = 0; i < cold.lambda.size(); ++i)
      EXPECT_NEAR(again.lambda[i], cold.lambda[i], kTol * scale) << t.name << " row " << i;
  }
}

TEST(KeaWarmStart, PerturbedProblemConvergesInFewSolves) {
  for (const Named &t : Problems()) {
    const KeaResult cold = KeaSolveSparse(t.problem.sparse(), KeaOptions{});
    ASSERT_EQ(cold.status, KeaStatus::Solved) << t.name;
    ContactProblem next = t.problem;
    const double bMax = MaxAbs(next.b);
    for (std::size_t i = 0; i < next.b.size(); ++i)
      next.b[i] += static_cast<MeReal>(1e-3 * bMax * kea_test::Jitter(99, static_cast<unsigned>(i)));
    KeaOptions warm;
    warm.warmStart = cold.lambda;
    const KeaResult w = KeaSolveSparse(next.sparse(), warm);
    const KeaResult c = KeaSolveSparse(next.sparse(), KeaOptions{});
    ASSERT_EQ(w.status, KeaStatus::Solved) << t.name;
    ASSERT_EQ(c.status, KeaStatus::Solved) << t.name;
    // A few solves, about half the cold ones or fewer.
    const std::string counts =
        t.name + ": warm " + std::to_string(w.iterations) + " solves, cold " + std::to_string(c.iterations);
    EXPECT_LE(w.iterations, 6) << counts;
    EXPECT_LE(2 * w.iterations, c.iterations + 1) << counts;
    // Both answers solve the same LCP to its tolerance.
    const double scale = 1 + MaxAbs(c.lambda);
    for (std::size_t i = 0; i < c.lambda.size(); ++i)
      EXPECT_NEAR(w.lambda[i], c.lambda[i], 10 * kTol * scale) << t.name << " row " << i;
  }
}

TEST(KeaWarmStart, WorkspaceEntryMatchesTheAllocatingOneBitForBit) {
  Workspace workspace(KeaWorkspaceCreate());
  KeaResult reused;
  for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
    // Largest first, so that later solves run in a grown workspace.
    std::vector<Named> problems = Problems();
    for (auto it = problems.rbegin(); it != problems.rend(); ++it) {
      KeaOptions o;
      o.method = method;
      o.warnings = false;
      const KeaResult fresh = KeaSolveSparse(it->problem.sparse(), o);
      KeaSolveSparse(it->problem.sparse(), o, *workspace, reused);
      EXPECT_EQ(reused.status, fresh.status) << it->name;
      EXPECT_EQ(reused.iterations, fresh.iterations) << it->name;
      EXPECT_TRUE(reused.lambda == fresh.lambda) << it->name;
      EXPECT_TRUE(reused.w == fresh.w) << it->name;
    }
  }
}

TEST(KeaFactorisations, SparseAndEnvelopePathsAgree) {
  // The same problems with every free block forced onto the sparse LDL^T,
  // onto the envelope LDL^T, and under the default rule: the same answers
  // to the tolerance (the paths differ in rounding only).
  std::vector<Named> problems = Problems();
  problems.push_back({"pile32", kea_test::Pile(32, 20, 1)});
  problems.push_back({"pile64", kea_test::Pile(64, 40, 2)});
  for (const Named &t : problems) {
    KeaOptions sparse, envelope, byRule;
    sparse.envelopeRows = -1;
    envelope.envelopeRows = 1 << 20;
    const KeaResult s = KeaSolveSparse(t.problem.sparse(), sparse);
    const KeaResult e = KeaSolveSparse(t.problem.sparse(), envelope);
    const KeaResult d = KeaSolveSparse(t.problem.sparse(), byRule);
    ASSERT_EQ(s.status, KeaStatus::Solved) << t.name;
    ASSERT_EQ(e.status, KeaStatus::Solved) << t.name;
    ASSERT_EQ(d.status, KeaStatus::Solved) << t.name;
    const double scale = 1 + MaxAbs(s.lambda);
    for (std::size_t i = 0; i < s.lambda.size(); ++i) {
      EXPECT_NEAR(e.lambda[i], s.lambda[i], 10 * kTol * scale) << t.name << " row " << i;
      EXPECT_NEAR(d.lambda[i], s.lambda[i], 10 * kTol * scale) << t.name << " row " << i;
    }
  }
}

TEST(KeaWarmStart, ResultReusedAsItsOwnWarmStart) {
  // A caller may warm-start a workspace solve from the result it writes
  // into: the answer is the same as from a copy.
  Workspace workspace(KeaWorkspaceCreate());
  for (const Named &t : Problems()) {
    for (KeaMethod method : {KeaMethod::ActiveSet, KeaMethod::PGS}) {
      KeaOptions o;
      o.method = method;
      o.warnings = false;
      KeaResult result;
      KeaSolveSparse(t.problem.sparse(), o, *workspace, result);
      const std::vector<MeReal> copy = result.lambda;
      KeaOptions fromCopy = o, fromItself = o;
      fromCopy.warmStart = copy;
      fromItself.warmStart = result.lambda;
      KeaResult expected;
      KeaSolveSparse(t.problem.sparse(), fromCopy, *workspace, expected);
      KeaSolveSparse(t.problem.sparse(), fromItself, *workspace, result);
      EXPECT_TRUE(result.lambda == expected.lambda) << t.name;
      EXPECT_EQ(result.iterations, expected.iterations) << t.name;
      if (method == KeaMethod::ActiveSet) {
        EXPECT_EQ(result.iterations, 1) << t.name;
      }
    }
  }
}

namespace {

// b of t's problem moved by 1e-3 of its largest entry, row by row: a
// problem its own answer no longer solves to the tolerance.
ContactProblem Perturbed(const ContactProblem &problem, double size = 1e-3) {
  ContactProblem next = problem;
  const double bMax = MaxAbs(next.b);
  for (std::size_t i = 0; i < next.b.size(); ++i)
    next.b[i] += static_cast<MeReal>(size * bMax * kea_test::Jitter(7, static_cast<unsigned>(i)));
  return next;
}

}  // namespace

TEST(KeaWarmStart, AnAnswerIsKeptAsItIsWhenAskedFor) {
  // A solve's own answer, given back as the warm start of the same
  // problem, is kept without a solve when its residual is within the
  // solved threshold over kWarmAcceptDivisor, and solved again otherwise
  // (a friction fixed point may stop anywhere within half the threshold).
  int keptCount = 0;
  for (const Named &t : Problems()) {
    const KeaResult cold = KeaSolveSparse(t.problem.sparse(), KeaOptions{});
    ASSERT_EQ(cold.status, KeaStatus::Solved) << t.name;
    std::vector<MeReal> w(cold.lambda.size());
    const MeReal residual = karma::kea::detail::SparseMultiplyResidual(karma::platform::DefaultKernels(),
                                                                       t.problem.sparse(), 0, cold.lambda, w);
    const MeReal threshold = KeaDefaultTolerance() * (1 + static_cast<MeReal>(MaxAbs(t.problem.b)));
    const bool keep = residual <= threshold / karma::kea::detail::kWarmAcceptDivisor;
    KeaOptions o;
    o.warmStart = cold.lambda;
    o.acceptWarmStart = true;
    const KeaResult kept = KeaSolveSparse(t.problem.sparse(), o);
    EXPECT_EQ(kept.status, KeaStatus::Solved) << t.name;
    EXPECT_EQ(kept.warmStartAccepted, keep) << t.name << ": residual " << residual << ", threshold " << threshold;
    if (!keep) continue;
    ++keptCount;
    EXPECT_EQ(kept.iterations, 0) << t.name;
    EXPECT_EQ(kept.factorizations, 0) << t.name;
    EXPECT_TRUE(kept.lambda == cold.lambda) << t.name;  // bit for bit: no solve touched it
    EXPECT_EQ(kept.residual, residual) << t.name;       // the warm start's own residual and w
    EXPECT_TRUE(kept.w == w) << t.name;
  }
  EXPECT_GE(keptCount, 10);  // most of the 15
}

TEST(KeaWarmStart, TheKeepBoundFollowsTheDivisor) {
  // Last problem's answer as the warm start of a perturbed problem (b moved
  // by up to 1/32 ... 2 tolerances of its largest value, so that the warm
  // start's residual falls on both sides of each bound): kept exactly when its
  // residual is within the solved threshold over
  // KeaOptions::warmAcceptDivisor, whatever the divisor; the result reports
  // the threshold it was held to.
  int keptLoosely = 0, keptAtDefault = 0;
  for (const Named &t : Problems()) {
    const KeaResult first = KeaSolveSparse(t.problem.sparse(), KeaOptions{});
    ASSERT_EQ(first.status, KeaStatus::Solved) << t.name;
    EXPECT_EQ(first.threshold, KeaDefaultTolerance() * (1 + static_cast<MeReal>(MaxAbs(t.problem.b)))) << t.name;
    for (double share : {1.0 / 32, 1.0 / 8, 1.0 / 5, 1.0 / 2, 2.0}) {
      const double size = share * static_cast<double>(KeaDefaultTolerance());
      const ContactProblem next = Perturbed(t.problem, size);
      std::vector<MeReal> w(first.lambda.size());
      const MeReal residual = karma::kea::detail::SparseMultiplyResidual(karma::platform::DefaultKernels(),
                                                                         next.sparse(), 0, first.lambda, w);
      const MeReal threshold = KeaDefaultTolerance() * (1 + static_cast<MeReal>(MaxAbs(next.b)));
      for (MeReal divisor : {MeReal(1), MeReal(2), MeReal(4), MeReal(16)}) {
        KeaOptions o;
        o.warmStart = first.lambda;
        o.acceptWarmStart = true;
        o.warmAcceptDivisor = divisor;
        const KeaResult r = KeaSolveSparse(next.sparse(), o);
        ASSERT_EQ(r.status, KeaStatus::Solved) << t.name;
        EXPECT_EQ(r.threshold, threshold) << t.name;
        const bool keep = residual <= threshold / divisor;
        EXPECT_EQ(r.warmStartAccepted, keep) << t.name << ": divisor " << divisor << ", residual " << residual;
        if (keep) {
          EXPECT_TRUE(r.lambda == first.lambda) << t.name;
        }
        if (divisor == 4 && keep) ++keptLoosely;
        if (divisor == 16 && keep) ++keptAtDefault;
      }
    }
  }
  EXPECT_GT(keptLoosely, keptAtDefault);  // some perturbations land between the two bounds
}

TEST(KeaWarmStart, AKeepDivisorBelowOneIsBadInput) {
  const std::vector<Named> problems = Problems();
  const ContactProblem &problem = problems.front().problem;
  for (MeReal divisor : {MeReal(0.5), MeReal(0), MeReal(-4), std::numeric_limits<MeReal>::quiet_NaN()}) {
    KeaOptions o;
    o.warnings = false;
    o.warmAcceptDivisor = divisor;
    const KeaResult r = KeaSolveSparse(problem.sparse(), o);
    EXPECT_EQ(r.status, KeaStatus::BadInput) << divisor;
    EXPECT_EQ(r.threshold, 0) << divisor;
  }
}

TEST(KeaWarmStart, AWarmStartThatIsNoLongerAnAnswerIsSolved) {
  for (const Named &t : Problems()) {
    const KeaResult first = KeaSolveSparse(t.problem.sparse(), KeaOptions{});
    ASSERT_EQ(first.status, KeaStatus::Solved) << t.name;
    const ContactProblem next = Perturbed(t.problem);
    KeaOptions o;
    o.warmStart = first.lambda;
    o.acceptWarmStart = true;
    const KeaResult w = KeaSolveSparse(next.sparse(), o);
    const KeaResult c = KeaSolveSparse(next.sparse(), KeaOptions{});
    ASSERT_EQ(w.status, KeaStatus::Solved) << t.name;
    ASSERT_EQ(c.status, KeaStatus::Solved) << t.name;
    EXPECT_FALSE(w.warmStartAccepted) << t.name;
    EXPECT_GE(w.iterations, 1) << t.name;
    const double scale = 1 + MaxAbs(c.lambda);
    for (std::size_t i = 0; i < c.lambda.size(); ++i)
      EXPECT_NEAR(w.lambda[i], c.lambda[i], 10 * kTol * scale) << t.name << " row " << i;
  }
}

TEST(KeaWarmStart, AWorkspaceWhoseChecksFailStopsCheckingForAWhile) {
  // Three checks that fail (a warm start from the unperturbed answer) take
  // the workspace's running mean below the floor: the next warm starts are
  // solved without a check even when they are answers, until the mean has
  // recovered toward its prior; then they are kept again.
  const ContactProblem problem = kea_test::Stack(6, 1, false);  // frictionless: its answer is kept
  const ContactProblem next = Perturbed(problem);
  const KeaResult answer = KeaSolveSparse(problem.sparse(), KeaOptions{});
  ASSERT_EQ(answer.status, KeaStatus::Solved);
  Workspace workspace(KeaWorkspaceCreate());
  KeaOptions o;
  o.warmStart = answer.lambda;
  o.acceptWarmStart = true;
  KeaResult r;
  for (int i = 0; i < 3; ++i) {
    KeaSolveSparse(next.sparse(), o, *workspace, r);
    ASSERT_EQ(r.status, KeaStatus::Solved);
    EXPECT_FALSE(r.warmStartAccepted) << "solve " << i;
  }
  int solvedBeforeKept = 0;
  for (; solvedBeforeKept < 100; ++solvedBeforeKept) {
    KeaSolveSparse(problem.sparse(), o, *workspace, r);
    ASSERT_EQ(r.status, KeaStatus::Solved);
    if (r.warmStartAccepted) break;
    EXPECT_GE(r.iterations, 1);
  }
  EXPECT_GE(solvedBeforeKept, 1);   // the check was skipped at least once
  EXPECT_LE(solvedBeforeKept, 20);  // and came back
  KeaSolveSparse(problem.sparse(), o, *workspace, r);
  EXPECT_TRUE(r.warmStartAccepted);  // a kept warm start raises the mean again
}

namespace {

// t's problem with A stored dense (row-major), for KeaSolveActiveSet.
struct DenseCopy {
  std::vector<MeReal> A;
  const ContactProblem &p;
  explicit DenseCopy(const ContactProblem &problem)
      : A(static_cast<std::size_t>(problem.n) * static_cast<std::size_t>(problem.n), MeReal(0)), p(problem) {
    const auto n = static_cast<std::size_t>(p.n);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
        A[i * n + static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)])] = p.val[static_cast<std::size_t>(k)];
  }
  LcpProblem problem() const { return {p.n, A, p.b, p.lo, p.hi, p.findex, p.mu}; }
};

}  // namespace

TEST(KeaWarmStart, TheDenseSolverKeepsAnAnswerAsItIsWhenAskedFor) {
  // KeaSolveActiveSet's warm-start check: its own answer, given back, is
  // kept without a solve exactly when its residual (KeaResidual) is within
  // the solved threshold over kWarmAcceptDivisor; then the answer is the
  // warm start bit for bit with its own residual and w.
  int keptCount = 0;
  for (const Named &t : Problems()) {
    const DenseCopy dense(t.problem);
    const KeaResult cold = KeaSolveActiveSet(dense.problem(), KeaOptions{});
    ASSERT_EQ(cold.status, KeaStatus::Solved) << t.name;
    std::vector<MeReal> w(cold.lambda.size());
    const MeReal residual = KeaResidual(dense.problem(), 0, cold.lambda, w);
    const MeReal threshold = KeaDefaultTolerance() * (1 + static_cast<MeReal>(MaxAbs(t.problem.b)));
    const bool keep = residual <= threshold / karma::kea::detail::kWarmAcceptDivisor;
    KeaOptions o;
    o.warmStart = cold.lambda;
    o.acceptWarmStart = true;
    const KeaResult kept = KeaSolveActiveSet(dense.problem(), o);
    EXPECT_EQ(kept.status, KeaStatus::Solved) << t.name;
    EXPECT_EQ(kept.warmStartAccepted, keep) << t.name << ": residual " << residual << ", threshold " << threshold;
    if (!keep) {
      EXPECT_GE(kept.iterations, 1) << t.name;
      continue;
    }
    ++keptCount;
    EXPECT_EQ(kept.iterations, 0) << t.name;
    EXPECT_EQ(kept.factorizations, 0) << t.name;
    EXPECT_TRUE(kept.lambda == cold.lambda) << t.name;
    EXPECT_EQ(kept.residual, residual) << t.name;
    EXPECT_TRUE(kept.w == w) << t.name;
  }
  // 13 of the 15: a friction fixed point may stop anywhere within half the
  // threshold, above its sixteenth.
  EXPECT_GE(keptCount, 11);
}

TEST(KeaWarmStart, EveryEntryPointRefusesAKeepDivisorBelowOne) {
  const std::vector<Named> problems = Problems();
  const DenseCopy dense(problems.front().problem);
  for (MeReal divisor : {MeReal(0.5), std::numeric_limits<MeReal>::quiet_NaN()}) {
    KeaOptions o;
    o.warnings = false;
    o.warmAcceptDivisor = divisor;
    EXPECT_EQ(KeaSolveActiveSet(dense.problem(), o).status, KeaStatus::BadInput) << divisor;
    EXPECT_EQ(KeaSolvePGS(dense.problem(), o).status, KeaStatus::BadInput) << divisor;
  }
}
