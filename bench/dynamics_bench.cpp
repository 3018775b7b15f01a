// Dynamics benchmarks: MdtWorldStep on a hanging chain of 10/100/1000 links
// (ball-and-socket joints, the first link to the world) and on a free-falling
// 10-body ragdoll, at 60 Hz after a warm-up; and Kea's solvers alone on
// chain-structured sparse problems of 30 to 30000 rows (sparse active set,
// dense active set up to 300 rows, sparse PGS).
//
// Times are per step (per solve for Kea) in microseconds; the chain's
// "per_link" counter is the step time divided by the number of links and
// Kea's "per_row" the solve time per row: flat across sizes means linear
// cost.
#include <benchmark/benchmark.h>

#include "Mdt.h"
#include "kea_lcp.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

constexpr MeReal kStep = MeReal(1) / MeReal(60);
constexpr int kWarmUpSteps = 60;

// Seconds per item, shown by Google Benchmark with an SI prefix (u = us).
benchmark::Counter PerItem(double items) {
  return benchmark::Counter(items, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

MdtWorldID MakeWorld(int bodies, int constraints) {
  MdtWorldID w = MdtWorldCreate(static_cast<unsigned>(bodies), static_cast<unsigned>(constraints), 1, 1);
  MdtWorldSetGravity(w, 0, MeReal(-9.81), 0);
  // Measure the solve every step: no body goes to sleep.
  MdtWorldSetAutoDisable(w, 0);
  return w;
}

// A chain of `links` links of length 0.5 hanging from the world at the
// origin, tilted 30 degrees from the vertical so that it swings.
void BM_HangingChain(benchmark::State &state) {
  const int links = static_cast<int>(state.range(0));
  MdtWorldID w = MakeWorld(links + 1, links + 1);
  const MeReal len = MeReal(0.5);
  const MeReal dx = len * std::sin(MeReal(0.5236)), dy = -len * std::cos(MeReal(0.5236));
  MdtBodyID prev = nullptr;
  for (int i = 0; i < links; ++i) {
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetPosition(b, dx * (MeReal(i) + MeReal(0.5)), dy * (MeReal(i) + MeReal(0.5)), 0);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, b, prev);
    MdtBSJointSetPosition(j, dx * MeReal(i), dy * MeReal(i), 0);
    MdtBSJointEnable(j);
    prev = b;
  }
  for (int i = 0; i < kWarmUpSteps; ++i) MdtWorldStep(w, kStep);
  for (auto _ : state) MdtWorldStep(w, kStep);
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(w, &stats);
  state.counters["per_link"] = PerItem(links);
  state.counters["rows"] = stats.rows;
  state.counters["kea_iters"] = stats.keaIterations;
  state.counters["unsolved"] = stats.keaUnsolved;
  MdtWorldDestroy(w);
}
BENCHMARK(BM_HangingChain)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// A ragdoll of 10 bodies and 9 ball-and-socket joints falling freely:
// torso, head, upper and lower arms, thighs and shins.
void BM_RagdollFreeFall(benchmark::State &state) {
  MdtWorldID w = MakeWorld(10, 9);
  struct Part {
    MeReal x, y;
    int parent;
    MeReal jx, jy;  // the joint to the parent
  };
  const Part parts[10] = {
      {0, MeReal(1.3), -1, 0, 0},                                     // 0 torso
      {0, MeReal(1.85), 0, 0, MeReal(1.65)},                          // 1 head
      {MeReal(-0.35), MeReal(1.45), 0, MeReal(-0.2), MeReal(1.55)},   // 2 upper arm L
      {MeReal(-0.75), MeReal(1.45), 2, MeReal(-0.55), MeReal(1.45)},  // 3 forearm L
      {MeReal(0.35), MeReal(1.45), 0, MeReal(0.2), MeReal(1.55)},     // 4 upper arm R
      {MeReal(0.75), MeReal(1.45), 4, MeReal(0.55), MeReal(1.45)},    // 5 forearm R
      {MeReal(-0.12), MeReal(0.75), 0, MeReal(-0.12), MeReal(0.95)},  // 6 thigh L
      {MeReal(-0.12), MeReal(0.3), 6, MeReal(-0.12), MeReal(0.52)},   // 7 shin L
      {MeReal(0.12), MeReal(0.75), 0, MeReal(0.12), MeReal(0.95)},    // 8 thigh R
      {MeReal(0.12), MeReal(0.3), 8, MeReal(0.12), MeReal(0.52)},     // 9 shin R
  };
  MdtBodyID body[10];
  for (int i = 0; i < 10; ++i) {
    body[i] = MdtBodyCreate(w);
    MdtBodySetPosition(body[i], parts[i].x, parts[i].y, 0);
    MdtBodyEnable(body[i]);
  }
  for (int i = 1; i < 10; ++i) {
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, body[i], body[parts[i].parent]);
    MdtBSJointSetPosition(j, parts[i].jx, parts[i].jy, 0);
    MdtBSJointEnable(j);
  }
  // A tumble, so the joints work.
  MdtBodySetAngularVelocity(body[0], 1, 2, MeReal(0.5));
  for (int i = 0; i < kWarmUpSteps; ++i) MdtWorldStep(w, kStep);
  for (auto _ : state) MdtWorldStep(w, kStep);
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(w, &stats);
  state.counters["rows"] = stats.rows;
  state.counters["kea_iters"] = stats.keaIterations;
  MdtWorldDestroy(w);
}
BENCHMARK(BM_RagdollFreeFall)->Unit(benchmark::kMicrosecond);

// ---------------------------------------------------------------------------
// Kea alone: a chain of rows/3 joints, joint k tying body k-1 (the world for
// k = 0) to body k with three rows of random Jacobians; diagonal random
// inverse masses; A = J M^-1 J^T + 0.01 I in CSR (rows of neighbouring
// joints couple: 9 entries a row). Every 7th row is a contact [0, inf), the
// rest bilateral; b random.
struct ChainProblem {
  int n = 0;
  std::vector<int> rowStart, col;
  std::vector<MeReal> val, b, lo, hi, dense;
  karma::kea::SparseLcpProblem sparse() const { return {n, rowStart, col, val, b, lo, hi, {}, {}}; }
  karma::kea::LcpProblem problem() const { return {n, dense, b, lo, hi, {}, {}}; }
};

ChainProblem MakeChainProblem(int rows, bool withDense) {
  const int joints = rows / 3, n = 3 * joints;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0), m(0.5, 2.0);
  // J[row][side][6]: side 0 = body k, side 1 = body k-1.
  std::vector<double> J(static_cast<std::size_t>(n) * 12), minv(static_cast<std::size_t>(joints) * 6);
  for (double &x : J) x = u(rng);
  for (double &x : minv) x = m(rng);
  auto block = [&](int row, int body) -> const double * {
    const int k = row / 3;
    const std::size_t base = static_cast<std::size_t>(row) * 12;
    if (body == k) return &J[base];
    if (body == k - 1) return &J[base + 6];
    return nullptr;
  };
  ChainProblem p;
  p.n = n;
  p.rowStart.push_back(0);
  for (int i = 0; i < n; ++i) {
    const int k = i / 3;
    for (int j = std::max(0, 3 * (k - 1)); j < std::min(n, 3 * (k + 2)); ++j) {
      double a = i == j ? 0.01 : 0.0;
      for (int body = k - 1; body <= k; ++body) {
        if (body < 0) continue;
        const double *bi = block(i, body), *bj = block(j, body);
        if (!bj) continue;
        for (int d = 0; d < 6; ++d)
          a += bi[d] * minv[static_cast<std::size_t>(body) * 6 + static_cast<std::size_t>(d)] * bj[d];
      }
      p.col.push_back(j);
      p.val.push_back(static_cast<MeReal>(a));
    }
    p.rowStart.push_back(static_cast<int>(p.col.size()));
    p.b.push_back(static_cast<MeReal>(u(rng)));
    p.lo.push_back(i % 7 == 0 ? 0 : -MEINFINITY);
    p.hi.push_back(MEINFINITY);
  }
  if (withDense) {
    p.dense.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i)
      for (int k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1]; ++k)
        p.dense[static_cast<std::size_t>(i) * static_cast<std::size_t>(n) +
                static_cast<std::size_t>(p.col[static_cast<std::size_t>(k)])] = p.val[static_cast<std::size_t>(k)];
  }
  return p;
}

void Report(benchmark::State &state, const karma::kea::KeaResult &r, int n) {
  state.counters["per_row"] = PerItem(n);
  state.counters["iters"] = r.iterations;
  state.counters["solved"] = r.status == karma::kea::KeaStatus::Solved ? 1 : 0;
}

void BM_KeaSparseActiveSet(benchmark::State &state) {
  const ChainProblem p = MakeChainProblem(static_cast<int>(state.range(0)), false);
  karma::kea::KeaOptions opt;
  opt.warnings = false;
  karma::kea::KeaResult r;
  for (auto _ : state) {
    r = karma::kea::KeaSolveSparse(p.sparse(), opt);
    benchmark::DoNotOptimize(r.lambda.data());
  }
  Report(state, r, p.n);
}
BENCHMARK(BM_KeaSparseActiveSet)->Arg(30)->Arg(300)->Arg(3000)->Arg(30000)->Unit(benchmark::kMicrosecond);

void BM_KeaDenseActiveSet(benchmark::State &state) {
  const ChainProblem p = MakeChainProblem(static_cast<int>(state.range(0)), true);
  karma::kea::KeaOptions opt;
  opt.warnings = false;
  karma::kea::KeaResult r;
  for (auto _ : state) {
    r = karma::kea::KeaSolveActiveSet(p.problem(), opt);
    benchmark::DoNotOptimize(r.lambda.data());
  }
  Report(state, r, p.n);
}
BENCHMARK(BM_KeaDenseActiveSet)->Arg(30)->Arg(300)->Unit(benchmark::kMicrosecond);

// PGS with its default budget (50 sweeps): the cost of a fixed number of
// sweeps, whether or not they reach the tolerance ("solved").
void BM_KeaSparsePGS(benchmark::State &state) {
  const ChainProblem p = MakeChainProblem(static_cast<int>(state.range(0)), false);
  karma::kea::KeaOptions opt;
  opt.method = karma::kea::KeaMethod::PGS;
  opt.warnings = false;
  karma::kea::KeaResult r;
  for (auto _ : state) {
    r = karma::kea::KeaSolveSparse(p.sparse(), opt);
    benchmark::DoNotOptimize(r.lambda.data());
  }
  Report(state, r, p.n);
}
BENCHMARK(BM_KeaSparsePGS)->Arg(30)->Arg(300)->Arg(3000)->Arg(30000)->Unit(benchmark::kMicrosecond);

}  // namespace
