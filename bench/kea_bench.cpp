// kea_bench.cpp: Kea's sparse active-set solver alone, on problems with the
// structure of the step's partitions (tests/unit/kea/kea_contact_problems.h):
// stacks of 3-21 boxes (4 contacts per face, 3 rows per contact, as in
// topple and stack21), a car (hinged wheels touching the ground, 32 rows), a
// 300-row chain and contact piles in random row order.
//
//   BM_Solve/<problem>/<entry>/<start>  one solve of the problem's next step
//       (b changed by 0.2%, as from one step to the next of a resting
//       scene); entry 0 = the allocating KeaSolveSparse, 1 = the workspace
//       one; start 0 = cold (lambda = 0), 1 = warm-started from the
//       previous step's solution, 2 = from its own solution (the least a
//       solve costs: one factorisation and one check).
//   BM_Path/<problem>/<path>/<start>  the same with the free blocks forced
//       onto one factorisation (path 0 = sparse LDL^T, 1 = envelope LDL^T),
//       for the crossover that sets the default rule.
// Counters: solves (linear solves per solve), factorizations, friction_rounds
// (fixed-point rounds after the first consistent set).
// Run e.g.  build/release/bench/kea_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include "kea_contact_problems.h"
#include "kea_lcp.h"

#include <climits>
#include <cstdint>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using karma::kea::KeaOptions;
using karma::kea::KeaResult;
using karma::kea::KeaWorkspace;
using kea_test::ContactProblem;

struct Case {
  std::string name;
  ContactProblem previous, next;
  std::vector<MeReal> warm;  // the previous step's solution
  std::vector<MeReal> own;   // this step's own solution
};

ContactProblem NextStep(const ContactProblem &p) {
  ContactProblem next = p;
  double bMax = 0;
  for (MeReal v : p.b) bMax = std::max(bMax, std::fabs(double(v)));
  for (std::size_t i = 0; i < next.b.size(); ++i)
    next.b[i] += static_cast<MeReal>(2e-3 * bMax * kea_test::Jitter(17, static_cast<unsigned>(i)));
  return next;
}

Case Make(std::string name, ContactProblem p) {
  Case c{std::move(name), p, NextStep(p), {}, {}};
  c.warm = karma::kea::KeaSolveSparse(c.previous.sparse(), KeaOptions{}).lambda;
  c.own = karma::kea::KeaSolveSparse(c.next.sparse(), KeaOptions{}).lambda;
  return c;
}

const std::vector<Case> &Cases() {
  static const std::vector<Case> cases = [] {
    std::vector<Case> all;
    all.push_back(Make("stack3", kea_test::Stack(3, 1)));
    all.push_back(Make("stack6", kea_test::Stack(6, 1)));
    all.push_back(Make("stack12", kea_test::Stack(12, 1)));
    all.push_back(Make("stack21", kea_test::Stack(21, 1)));
    all.push_back(Make("car", kea_test::Car(1)));
    all.push_back(Make("chain300", kea_test::Chain(100, 1)));
    all.push_back(Make("pile24", kea_test::Pile(8, 6, 1)));
    all.push_back(Make("pile48", kea_test::Pile(16, 10, 1)));
    all.push_back(Make("pile96", kea_test::Pile(32, 20, 1)));
    all.push_back(Make("pile192", kea_test::Pile(64, 40, 1)));
    return all;
  }();
  return cases;
}

struct WorkspaceDeleter {
  void operator()(KeaWorkspace *w) const { karma::kea::KeaWorkspaceDestroy(w); }
};

template <class R>
void Count(benchmark::State &state, const R &r) {
  state.counters["solves"] = r.iterations;
  if constexpr (requires { r.factorizations; }) {
    state.counters["factorizations"] = r.factorizations;
    state.counters["friction_rounds"] = r.frictionRounds;
  }
}

// The start: 0 cold, 1 the previous step's solution, 2 the problem's own.
void SetStart(KeaOptions &o, const Case &c, std::int64_t start) {
  if (start == 1) o.warmStart = c.warm;
  if (start == 2) o.warmStart = c.own;
}

const char *StartName(std::int64_t start) { return start == 0 ? " cold" : start == 1 ? " warm" : " own"; }

// args: case, entry (0 allocating, 1 workspace), start
void BM_Solve(benchmark::State &state) {
  const Case &c = Cases()[static_cast<std::size_t>(state.range(0))];
  const bool workspaceEntry = state.range(1) == 1;
  KeaOptions o;
  o.warnings = false;
  SetStart(o, c, state.range(2));
  const karma::kea::SparseLcpProblem p = c.next.sparse();
  std::unique_ptr<KeaWorkspace, WorkspaceDeleter> workspace(karma::kea::KeaWorkspaceCreate());
  KeaResult r;
  for (auto _ : state) {
    if (workspaceEntry)
      karma::kea::KeaSolveSparse(p, o, *workspace, r);
    else
      r = karma::kea::KeaSolveSparse(p, o);
    benchmark::DoNotOptimize(r.lambda.data());
  }
  state.SetLabel(c.name + (workspaceEntry ? " workspace" : " allocating") + StartName(state.range(2)));
  Count(state, r);
}

// Forces the factorisation (a no-op for a Kea without the option).
template <class O>
void ForcePath(O &o, bool envelope) {
  if constexpr (requires { o.envelopeRows; }) o.envelopeRows = envelope ? INT_MAX : -1;
}

// args: case, path (0 sparse LDL^T, 1 envelope LDL^T), start
void BM_Path(benchmark::State &state) {
  const Case &c = Cases()[static_cast<std::size_t>(state.range(0))];
  KeaOptions o;
  o.warnings = false;
  ForcePath(o, state.range(1) == 1);
  SetStart(o, c, state.range(2));
  const karma::kea::SparseLcpProblem p = c.next.sparse();
  std::unique_ptr<KeaWorkspace, WorkspaceDeleter> workspace(karma::kea::KeaWorkspaceCreate());
  KeaResult r;
  for (auto _ : state) {
    karma::kea::KeaSolveSparse(p, o, *workspace, r);
    benchmark::DoNotOptimize(r.lambda.data());
  }
  state.SetLabel(c.name + (state.range(1) ? " envelope" : " sparse") + StartName(state.range(2)));
  Count(state, r);
}

void SolveArgs(benchmark::internal::Benchmark *b) {
  for (int c = 0; c < 6; ++c)
    for (int entry = 0; entry < 2; ++entry)
      for (int start = 0; start < 3; ++start) b->Args({c, entry, start});
}

void PathArgs(benchmark::internal::Benchmark *b) {
  for (int c = 0; c < 10; ++c)
    for (int path = 0; path < 2; ++path)
      for (int start = 0; start < 2; ++start) b->Args({c, path, start});
}

BENCHMARK(BM_Solve)->Apply(SolveArgs)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Path)->Apply(PathArgs)->Unit(benchmark::kMicrosecond);

}  // namespace
