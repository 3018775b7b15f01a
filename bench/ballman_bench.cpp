// ballman_bench.cpp: what the guide's Ballman is about -- the cheap
// materials (viscous friction through slip with an infinite friction
// bound, infinitely adhesive contacts) against the high-quality model
// (normal-force Coulomb friction) -- timed in one run, in the Ballman scene
// of tutorials/ballman (ballman_sim), so the ratio compares like with like
// on the same machine at the same moment.
//
//   friction_models   a scripted run (the doll falls down the stairs; the
//                     push at frame 130 sends it into the boxes; 300
//                     frames, one world step each) once per model:
//                     dynamics time per frame (MdtWorldStep: Kea's solve,
//                     the integration and the joint projection) mean and
//                     peak, Kea's iterations and rows per step, and the
//                     ratios high / cheap.
//                     The two runs take different paths (the cheap doll
//                     slides, the Coulomb one stops on the steps), so
//                     their contact sets differ too; hence the next one.
//   same_states       twenty states of the cheap run (every 15 frames):
//                     from each, one frame is stepped with each model and
//                     its dynamics timed, so both solve the same bodies
//                     and contacts.
// Times are the thread's CPU time (clock_gettime THREAD_CPUTIME), in
// microseconds per frame (one step).
// Run e.g.  build/release/bench/ballman_bench --benchmark_repetitions=5
// (the machines are shared and noisy: read the ratios, and the medians).
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>

#include "ballman_sim.h"

namespace {

constexpr int kFrames = 300, kPushAt = 130, kSameStateEvery = 15;

// This thread's CPU time in microseconds: on a shared machine, time spent
// descheduled would otherwise swamp frames of a few hundred microseconds.
double CpuUs() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec * 1e6 + (double)t.tv_nsec * 1e-3;
}

struct Figures {
  double dynamicsUs = 0;   // per frame, mean
  double peakUs = 0;       // the slowest frame's dynamics
  double collisionUs = 0;  // per frame, mean
  double iterations = 0;   // Kea's, per frame
  double rows = 0;         // per frame
  int frames = 0;
};

// One frame (one step), collision and dynamics timed apart.
void Frame(Ballman *b, Figures &f) {
  const double t0 = CpuUs();
  BallmanCollide(b);
  const double t1 = CpuUs();
  BallmanDynamics(b);
  const double t2 = CpuUs();
  f.collisionUs += t1 - t0;
  const double dynamics = t2 - t1;
  MdtWorldStepStats st;
  BallmanStepStats(b, &st);
  f.iterations += st.keaIterations;
  f.rows += st.rows;
  f.dynamicsUs += dynamics;
  f.peakUs = std::max(f.peakUs, dynamics);
  ++f.frames;
}

void Finish(Figures &f) {
  f.dynamicsUs /= f.frames;
  f.collisionUs /= f.frames;
  f.iterations /= f.frames;
  f.rows /= f.frames;
}

Figures Scripted(bool highQuality) {
  Ballman *b = BallmanCreate();
  BallmanSetHighQualityFriction(b, highQuality);
  Figures f;
  for (int frame = 0; frame < kFrames; ++frame) {
    if (frame == kPushAt) BallmanPropel(b);
    Frame(b, f);
  }
  BallmanDestroy(b);
  Finish(f);
  return f;
}

void Report(benchmark::State &state, const Figures &cheap, const Figures &hq) {
  state.counters["cheap_dyn_us"] = cheap.dynamicsUs;
  state.counters["hq_dyn_us"] = hq.dynamicsUs;
  state.counters["ratio_dyn"] = hq.dynamicsUs / cheap.dynamicsUs;
  state.counters["cheap_peak_us"] = cheap.peakUs;
  state.counters["hq_peak_us"] = hq.peakUs;
  state.counters["ratio_peak"] = hq.peakUs / cheap.peakUs;
  state.counters["cheap_coll_us"] = cheap.collisionUs;
  state.counters["hq_coll_us"] = hq.collisionUs;
  state.counters["cheap_kea_it"] = cheap.iterations;
  state.counters["hq_kea_it"] = hq.iterations;
  state.counters["cheap_rows"] = cheap.rows;
  state.counters["hq_rows"] = hq.rows;
}

void BM_FrictionModels(benchmark::State &state) {
  Figures cheap, hq;
  for (auto _ : state) {
    cheap = Scripted(false);
    hq = Scripted(true);
  }
  Report(state, cheap, hq);
}

void BM_SameStates(benchmark::State &state) {
  Figures cheap, hq;
  for (auto _ : state) {
    cheap = Figures(), hq = Figures();
    for (int at = kSameStateEvery; at <= kFrames; at += kSameStateEvery) {
      for (bool highQuality : {false, true}) {
        state.PauseTiming();
        Ballman *b = BallmanCreate();
        Figures ignored;
        for (int frame = 0; frame < at; ++frame) {
          if (frame == kPushAt) BallmanPropel(b);
          Frame(b, ignored);
        }
        BallmanSetHighQualityFriction(b, highQuality);
        state.ResumeTiming();
        Frame(b, highQuality ? hq : cheap);
        state.PauseTiming();
        BallmanDestroy(b);
        state.ResumeTiming();
      }
    }
    Finish(cheap);
    Finish(hq);
  }
  Report(state, cheap, hq);
}

BENCHMARK(BM_FrictionModels)->Name("ballman/friction_models")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SameStates)->Name("ballman/same_states")->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
