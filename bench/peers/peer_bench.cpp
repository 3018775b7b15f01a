// peer_bench.cpp: the five anchor scenes of ../shared/bench/SCENES.md in
// this project's engine and, when built with them, ODE 0.16 (dWorldStep
// and dWorldQuickStep with 20 iterations) and Bullet 3.24 (default solver,
// 10 iterations), every engine built from the same scene description.
//
// For each scene, each repetition runs every engine once, one after the
// other (the starting engine rotates from one repetition to the next), so
// that the machine's drift in speed touches all engines alike. The time
// of a run is the sum over its steps of the engine's step alone (drives,
// collision, solve, integration; building and bookkeeping excluded),
// divided by the steps. It prints a Markdown table: the median and range
// over the repetitions, the ratios of the medians to ODE's two solvers,
// and the figures of SCENES.md from the last repetition.
//
// pile10k (10,000 cubes in 100 columns, not an anchor scene) runs only
// when named in --scenes. When both piles run, a line per engine gives the
// growth of the time per step from pile1000 to pile10k (ten times the
// bodies); give both the same step count (--pile-steps, --pile10k-steps)
// for a like-for-like ratio.
//
// --sleep lets every engine's resting bodies sleep by its own rule at its
// default thresholds (SetPeersSleep); the line above the table says so.
//
// --epsilon E (>= 0) and --joint-projection N (>= 0) set Karma's world
// softness (MdtWorldSetEpsilon; the guide's default, 0.01 at length scale
// 1) and joint projection sweeps (MdtWorldSetJointProjection; 0, off, by
// default) in every scene, to show what a setting the user chooses costs
// next to the peers' defaults; the line above the table names them.
//
// --platform NAME picks Karma's platform backend (MdtPlatform.h) for the
// whole run, with the usual fallback and warning when the CPU lacks it; the
// line above the table names the backend Karma's worlds ran on.
//
//   peer_bench [--scenes car,topple,...] [--engines karma,ode-step,...]
//              [--reps N] [--steps N] [--pile-steps N] [--pile10k-steps N]
//              [--ode-contacts N] [--iterative-rows N] [--max-iterations N]
//              [--epsilon E] [--joint-projection N]
//              [--platform reference|sse4|avx2|avx512] [--sleep]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "MdtPlatform.h"
#include "peer_engine.h"

namespace {

using karma::peers::EngineKind;
using karma::peers::PeerEngine;
using karma::scenes::BodyState;
using karma::scenes::SceneFigures;
using karma::scenes::SceneMonitor;
using karma::scenes::SceneSpec;

// pile1000's first second: ODE's exact solver takes over a second a step
// once the pile has landed (and Karma's exact solver a few hundred ms).
constexpr int kDefaultPileSteps = 60;
constexpr int kDefaultPile10kSteps = 60;

struct Options {
  std::vector<std::string> scenes, engines;
  int reps = 5;
  int steps = 0;  // 0: each scene's own length
  int pileSteps = kDefaultPileSteps;
  int pile10kSteps = kDefaultPile10kSteps;
  int odeContacts = 8;
  int iterativeRows = -1;          // Karma's MdtWorldSetKeaIterativeRows; < 0: the engine's default
  int maxIterations = 0;           // Karma's MdtWorldSetKeaMaxIterations (the iterative solver's sweeps); 0: default
  double epsilon = -1;             // Karma's MdtWorldSetEpsilon; < 0: the default
  int jointProjection = -1;        // Karma's MdtWorldSetJointProjection; < 0: the default (off)
  const char *platform = nullptr;  // Karma's platform backend; nullptr: the process default
  bool sleep = false;              // every engine's sleeping on (SetPeersSleep)
};

// Whether `text` is all of a finite number >= 0, stored in *out if so.
bool NonNegativeNumber(const char *text, double *out) {
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v) || v < 0) return false;
  *out = v;
  return true;
}

bool KnownPlatform(const char *name) {
  for (int i = 0; i < MdtPlatformCount(); ++i)
    if (!std::strcmp(MdtPlatformName(i), name)) return true;
  return false;
}

std::vector<EngineKind> AllEngines() {
  std::vector<EngineKind> all = {{"karma", &karma::peers::MakeKarma}};
#if KARMA_PEERS_HAVE_ODE
  all.push_back({"ode-step", &karma::peers::MakeOdeStep});
  all.push_back({"ode-quickstep", &karma::peers::MakeOdeQuickStep});
#endif
#if KARMA_PEERS_HAVE_BULLET
  all.push_back({"bullet", &karma::peers::MakeBullet});
#endif
  return all;
}

std::vector<std::string> Split(const char *list) {
  std::vector<std::string> out;
  std::string item;
  for (const char *c = list;; ++c) {
    if (*c == ',' || *c == 0) {
      if (!item.empty()) out.push_back(item);
      item.clear();
      if (*c == 0) break;
    } else {
      item += *c;
    }
  }
  return out;
}

bool Parse(int argc, char **argv, Options &o) {
  for (int i = 1; i < argc; ++i) {
    const bool hasValue = i + 1 < argc;
    if (!std::strcmp(argv[i], "--scenes") && hasValue)
      o.scenes = Split(argv[++i]);
    else if (!std::strcmp(argv[i], "--engines") && hasValue)
      o.engines = Split(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && hasValue)
      o.reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--steps") && hasValue)
      o.steps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--pile-steps") && hasValue)
      o.pileSteps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--pile10k-steps") && hasValue)
      o.pile10kSteps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--ode-contacts") && hasValue)
      o.odeContacts = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--iterative-rows") && hasValue && std::atoi(argv[i + 1]) >= 0)
      o.iterativeRows = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--max-iterations") && hasValue && std::atoi(argv[i + 1]) > 0)
      o.maxIterations = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--epsilon") && hasValue && NonNegativeNumber(argv[i + 1], &o.epsilon))
      ++i;
    else if (!std::strcmp(argv[i], "--joint-projection") && hasValue && std::atoi(argv[i + 1]) >= 0)
      o.jointProjection = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--platform") && hasValue && KnownPlatform(argv[i + 1]))
      o.platform = argv[++i];
    else if (!std::strcmp(argv[i], "--sleep"))
      o.sleep = true;
    else
      return false;
  }
  return o.reps > 0 && o.steps >= 0 && o.pileSteps > 0 && o.pile10kSteps > 0 && o.odeContacts >= 1 &&
         o.odeContacts <= 8;
}

// One run of a scene in an engine: the step time and the figures.
struct Run {
  double microsPerStep = 0;
  SceneFigures figures;
};

Run RunOnce(const EngineKind &engine, const SceneSpec &spec, int steps) {
  std::unique_ptr<PeerEngine> world = engine.make(spec);
  std::vector<BodyState> states;
  SceneMonitor monitor(spec);
  world->states(states);
  monitor.start(states);
  std::chrono::steady_clock::duration spent{};
  for (int i = 0; i < steps; ++i) {
    const auto start = std::chrono::steady_clock::now();
    world->step();
    spent += std::chrono::steady_clock::now() - start;
    world->states(states);
    monitor.observe(states);
  }
  Run run;
  run.microsPerStep = std::chrono::duration<double, std::micro>(spent).count() / steps;
  world->states(states);
  run.figures = monitor.finish(states, steps, world->penetration());
  return run;
}

struct Result {
  std::string engine;
  std::vector<double> micros;  // per repetition
  SceneFigures figures;        // of the last repetition
  double median() const {
    std::vector<double> m = micros;
    std::sort(m.begin(), m.end());
    const size_t n = m.size();
    return n % 2 ? m[n / 2] : (m[n / 2 - 1] + m[n / 2]) / 2;
  }
};

std::string Format(const char *format, double a, double b = 0, double c = 0) {
  char text[96];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

// Microseconds: one decimal below 1000, else whole with thousands commas.
std::string Micros(double us) {
  if (us < 1000) return Format("%.1f", us);
  std::string digits = Format("%.0f", us), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string Stability(const SceneFigures &f) {
  if (f.stable()) return "yes";
  if (!f.finite) return "**no**: NaN";
  if (f.maxSpeed >= 50) return Format("**no**: %.0f m/s", f.maxSpeed);
  return "**no**: check";
}

std::string Ratio(double value, const Result *reference) {
  if (!reference) return "–";
  return Format("%.2f", value / reference->median());
}

void PrintScene(const SceneSpec &spec, int steps, const std::vector<Result> &results) {
  const Result *step = nullptr, *quick = nullptr;
  for (const Result &r : results) {
    if (r.engine == "ode-step") step = &r;
    if (r.engine == "ode-quickstep") quick = &r;
  }
  for (const Result &r : results) {
    const auto [lo, hi] = std::minmax_element(r.micros.begin(), r.micros.end());
    const SceneFigures &f = r.figures;
    std::printf("| %s (%d%s) | %s | %s [%s–%s] | %s | %s | %s | %s | %.2f | %.1f |\n", spec.name.c_str(), steps,
                steps < spec.steps ? Format(" of %.0f", spec.steps).c_str() : "", r.engine.c_str(),
                Micros(r.median()).c_str(), Micros(*lo).c_str(), Micros(*hi).c_str(), Ratio(r.median(), step).c_str(),
                Ratio(r.median(), quick).c_str(), Stability(f).c_str(), f.detail.c_str(), f.maxSpeed,
                f.penetration * 1e3);
  }
}

bool Wanted(const std::vector<std::string> &list, const std::string &name) {
  return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
}

bool Named(const std::vector<std::string> &list, const std::string &name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// The scene's step count under the options.
int StepsOf(const SceneSpec &spec, const Options &o) {
  int steps = spec.steps;
  if (spec.name == "pile1000") steps = std::min(steps, o.pileSteps);
  if (spec.name == "pile10k") steps = std::min(steps, o.pile10kSteps);
  if (o.steps > 0) steps = std::min(steps, o.steps);
  return steps;
}

// One scene's results, kept for the growth lines.
struct SceneResults {
  std::string scene;
  int steps = 0;
  std::vector<Result> results;
};

const Result *Find(const std::vector<SceneResults> &all, const std::string &scene, const std::string &engine,
                   int &steps) {
  for (const SceneResults &s : all)
    if (s.scene == scene)
      for (const Result &r : s.results)
        if (r.engine == engine) {
          steps = s.steps;
          return &r;
        }
  return nullptr;
}

// Per engine that ran both piles: the ratio of the median times per step.
void PrintGrowth(const std::vector<SceneResults> &all, const std::vector<EngineKind> &engines) {
  for (const EngineKind &e : engines) {
    int smallSteps = 0, largeSteps = 0;
    const Result *small = Find(all, "pile1000", e.name, smallSteps);
    const Result *large = Find(all, "pile10k", e.name, largeSteps);
    if (!small || !large) continue;
    std::printf(
        "\n%s: pile1000 (%d steps) %s µs/step, pile10k (%d steps) %s µs/step: growth %.2f× for 10× the bodies\n",
        e.name.c_str(), smallSteps, Micros(small->median()).c_str(), largeSteps, Micros(large->median()).c_str(),
        large->median() / small->median());
  }
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  if (!Parse(argc, argv, o)) {
    std::fprintf(
        stderr,
        "usage: %s [--scenes car,topple,stack21,ragdoll,pile1000] "
        "[--engines karma,ode-step,ode-quickstep,bullet] [--reps N (5)] "
        "[--steps N (each scene's own)] [--pile-steps N (%d)] [--pile10k-steps N (%d)] "
        "[--ode-contacts 1..8 (8)] [--iterative-rows N (0: exact; default: the engine's, 300)]\n"
        "  [--max-iterations N (Karma's iteration cap: the iterative solver's sweeps; default: the engine's)]\n"
        "  [--epsilon E (Karma's world softness, >= 0; default: the guide's, 0.01 at length scale 1)]\n"
        "  [--joint-projection N (Karma's joint projection sweeps; default: 0, off)]\n"
        "  [--platform reference|sse4|avx2|avx512 (Karma's platform backend; default: KARMA_PLATFORM, else the "
        "best the CPU runs)]\n"
        "  [--sleep (every engine's resting bodies sleep by its own rule and default thresholds; default: off)]\n"
        "  scenes: the five anchor scenes (the default) and pile10k (only when named)\n",
        argv[0], kDefaultPileSteps, kDefaultPile10kSteps);
    return 2;
  }
#if KARMA_PEERS_HAVE_ODE
  karma::peers::SetOdeMaxContacts(o.odeContacts);
#endif
  karma::peers::SetKarmaIterativeRows(o.iterativeRows);
  karma::peers::SetKarmaMaxIterations(o.maxIterations);
  karma::peers::SetKarmaEpsilon(o.epsilon);
  karma::peers::SetKarmaJointProjection(o.jointProjection);
  karma::peers::SetPeersSleep(o.sleep);
  if (o.platform) MdtPlatformSetDefault(o.platform);
  std::vector<EngineKind> engines;
  for (const EngineKind &e : AllEngines())
    if (Wanted(o.engines, e.name)) engines.push_back(e);
  std::vector<SceneSpec> specs;
  for (SceneSpec &s : karma::scenes::AnchorSpecs())
    if (Wanted(o.scenes, s.name)) specs.push_back(std::move(s));
  if (Named(o.scenes, "pile10k")) specs.push_back(karma::scenes::Pile10kSpec());
  if (engines.empty() || specs.empty()) {
    std::fprintf(stderr, "peer_bench: no engine or no scene selected\n");
    return 2;
  }
  std::printf("Karma build: %s\n",
              KARMA_PEERS_LTO ? "link-time optimised (KARMA_LTO)" : "without link-time optimisation");
  // Every Karma world of the run is created after this and takes the default.
  std::printf("Karma platform backend: %s\n", MdtPlatformGetDefaultName());
  if (o.epsilon >= 0) std::printf("Karma epsilon: %g (set by --epsilon)\n", o.epsilon);
  if (o.jointProjection >= 0)
    std::printf("Karma joint projection: %d sweeps (set by --joint-projection)\n", o.jointProjection);
  std::printf("Sleeping: %s\n\n", o.sleep ? "on in every engine, by its own rule and default thresholds" : "off");
  std::printf(
      "| scene (steps) | engine | µs/step, median [range] | × ODE step | × ODE QuickStep | stable "
      "| scene figures | max speed (m/s) | penetration (mm) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::vector<SceneResults> all;
  for (const SceneSpec &spec : specs) {
    const int steps = StepsOf(spec, o);
    std::vector<Result> results(engines.size());
    for (int rep = 0; rep < o.reps; ++rep) {
      for (size_t k = 0; k < engines.size(); ++k) {
        const size_t e = (k + (size_t)rep) % engines.size();  // rotate the first engine
        std::fprintf(stderr, "%s, repetition %d: %s\n", spec.name.c_str(), rep + 1, engines[e].name.c_str());
        const Run run = RunOnce(engines[e], spec, steps);
        results[e].engine = engines[e].name;
        results[e].micros.push_back(run.microsPerStep);
        results[e].figures = run.figures;
      }
    }
    PrintScene(spec, steps, results);
    std::fflush(stdout);
    all.push_back({spec.name, steps, results});
  }
  PrintGrowth(all, engines);
  return 0;
}
