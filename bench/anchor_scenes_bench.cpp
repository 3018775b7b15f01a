// anchor_scenes_bench.cpp: the five anchor scenes of ../shared/bench/SCENES.md
// through Mst, in microseconds per step (collision + solve + integration,
// summed over a run and divided by its steps; building the scene is not
// timed), with the figures that file asks for as counters:
//   stable       1 when no NaN, every body under 50 m/s and the scene's check met
//   penetration  deepest contact penetration after the last step (mm)
//   car_v, car_x chassis velocity (m/s) and position (m) at 5 s (analytic 16.18, 40.45)
//   joint_err    ragdoll: largest joint gap over the run (mm)
//   rows, solves, factorizations, friction_rounds, stale_solves, warm_starts
//                per step, summed over partitions (MdtWorldGetStepStats;
//                warm_starts: partitions that kept their warm start)
//   unsolved     partition solves over the run that did not reach tolerance
// Each exact scene also runs as NAME/warm:0, with MdtWorldSetKeaAcceptWarmStart
// off: every partition solved, what the kept warm starts save.
// Run e.g.  build/bench/bench/anchor_scenes_bench --benchmark_repetitions=5
// (Google Benchmark then reports the median and spread of the runs).
#include <benchmark/benchmark.h>

#include <chrono>

#include "anchor_scene.h"

namespace {

using karma::scenes::AnchorScene;

// The solver's work over a run (MdtWorldGetStepStats after every step).
struct StatsSum {
  double rows = 0, solves = 0, factorizations = 0, frictionRounds = 0, staleSolves = 0, warmStarts = 0, unsolved = 0;
  void add(MdtWorldID world) {
    MdtWorldStepStats s;
    MdtWorldGetStepStats(world, &s);
    rows += s.rows;
    solves += s.keaIterations;
    factorizations += s.keaFactorizations;
    frictionRounds += s.keaFrictionRounds;
    staleSolves += s.keaStaleSolves;
    warmStarts += s.keaWarmStarts;
    unsolved += s.keaUnsolved;
  }
  void report(benchmark::State &state, int steps) const {
    state.counters["rows"] = rows / steps;
    state.counters["solves"] = solves / steps;
    state.counters["factorizations"] = factorizations / steps;
    state.counters["friction_rounds"] = frictionRounds / steps;
    state.counters["stale_solves"] = staleSolves / steps;
    state.counters["warm_starts"] = warmStarts / steps;
    state.counters["unsolved"] = unsolved;
  }
};

// Steps = 0 runs the scene's own length; pile1000_first90 runs the first 90
// steps of pile1000 (its landing, as the test does) for a quick figure.
// KeepWarm = false turns MdtWorldSetKeaAcceptWarmStart off.
template <std::unique_ptr<AnchorScene> (*Make)(), int Steps = 0, bool KeepWarm = true>
void BM_Scene(benchmark::State &state) {
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<AnchorScene> scene = Make();
    MdtWorldSetKeaAcceptWarmStart(scene->world(), KeepWarm);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const int steps = Steps > 0 ? Steps : scene->steps();
    StatsSum sum;
    for (int i = 0; i < steps; ++i) {
      scene->step();
      sum.add(scene->world());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    sum.report(state, steps);
    const karma::scenes::SceneFigures f = scene->finish();
    state.counters["us_per_step"] = seconds * 1e6 / f.steps;
    state.counters["stable"] = f.stable() ? 1 : 0;
    state.counters["penetration_mm"] = f.penetration * 1e3;
    if (scene->name() == std::string("car")) {
      state.counters["car_v"] = f.carVelocity;
      state.counters["car_x"] = f.carPosition;
    }
    if (scene->name() == std::string("ragdoll")) state.counters["joint_err_mm"] = f.jointErrorMax * 1e3;
    scene.reset();
    state.ResumeTiming();
  }
}

BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeCar)->Name("car")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeTopple)->Name("topple")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeStack21)->Name("stack21")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeRagdoll)->Name("ragdoll")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakePile1000)
    ->Name("pile1000")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakePile1000, 90)
    ->Name("pile1000_first90")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeCar, 0, false)
    ->Name("car/warm:0")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeTopple, 0, false)
    ->Name("topple/warm:0")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeStack21, 0, false)
    ->Name("stack21/warm:0")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Scene, karma::scenes::MakeRagdoll, 0, false)
    ->Name("ragdoll/warm:0")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// Walking every body's contacts (MdtBodyGetFirstContact / NextContact, as
// DeepestPenetration does) after the scene's first Steps steps; the time
// per contact reached (seconds) is about the same for 25 bodies and 1,000
// when a walk costs the body's own constraints, not the world's.
template <std::unique_ptr<AnchorScene> (*Make)(), int Steps>
void BM_ContactWalk(benchmark::State &state) {
  std::unique_ptr<AnchorScene> scene = Make();
  for (int i = 0; i < Steps; ++i) scene->step();
  long reached = 0;
  for (McdModelID m : scene->models()) {
    MdtBodyID b = McdModelGetBody(m);
    for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c)) ++reached;
  }
  for (auto _ : state) benchmark::DoNotOptimize(karma::scenes::DeepestPenetration(scene->models()));
  state.counters["contacts"] = static_cast<double>(reached);
  state.counters["time_per_contact"] = benchmark::Counter(
      static_cast<double>(reached), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_TEMPLATE(BM_ContactWalk, karma::scenes::MakeTopple, 60)->Name("contact_walk/topple");
BENCHMARK_TEMPLATE(BM_ContactWalk, karma::scenes::MakePile1000, 90)->Name("contact_walk/pile1000");

}  // namespace
