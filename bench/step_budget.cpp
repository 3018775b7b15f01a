// step_budget.cpp: MdtWorldSetStepBudget on an anchor scene, against the
// fixed settings it chooses between, in one run:
//   build/release/bench/step_budget topple|pile1000 [STEPS] [--reps N]
// It first measures two dynamics times (MdtWorldStep alone): exact's, with
// an unbounded budget, and the floor, with a starved one (the step outside
// the solves plus the cheapest solves: no budget buys less). Budgets are
// fractions of exact's; one below the floor is marked so. For each fixed
// setting (exact, exact:8, iterative with 50, 20, 15, 12, 11, 10, 9 and 5 sweeps)
// and each budget it prints the median microseconds per whole step
// (collision and dynamics), the scene's error figure, and for the budgets
// the median dynamics time against the budget, the share of steps within
// 20 % of it, and the range of the errors of the fixed settings whose whole
// step costs no more: what that time buys without a budget. Every figure is the
// median of N runs (default 3), run interleaved setting by setting; the
// medians inside a run skip its first tenth of steps (the model learning).
//   build/release/bench/step_budget topple|pile1000 --trace BUDGET [STEPS]
// prints what the budget chose at each step instead, and the error figure.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cctype>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "anchor_scene.h"

namespace {

using karma::scenes::AnchorScene;
using Clock = std::chrono::steady_clock;

struct Setting {
  std::string name;
  MdtKeaMethod method = MdtKeaMethodActiveSet;
  int iterations = 0;
  double budget = 0;  // microseconds; 0: a fixed setting
};

struct Outcome {
  double wholeMedian = 0;     // microseconds per step, collision and dynamics
  double dynamicsMedian = 0;  // budget runs: MdtWorldStep, measured by the budget
  double withinShare = 0;     // budget runs: steps within 20 % of the budget
  double error = 0;           // the scene's error figure, m
  int worstLevel = -1;        // budget runs: least accurate level used
  int fewestSweeps = 0;       // budget runs: fewest sweeps given
};

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + (long)v.size() / 2, v.end());
  return v[v.size() / 2];
}

// topple: the worst watched top box's sideways drift; pile1000: the
// deepest overlap after the last step.
double ErrorFigure(const std::string &scene, const karma::scenes::SceneFigures &f) {
  return scene == "topple" ? f.drift : f.penetration;
}

std::unique_ptr<AnchorScene> MakeScene(const std::string &name) {
  return name == "topple" ? karma::scenes::MakeTopple() : karma::scenes::MakePile1000();
}

Outcome Run(const std::string &sceneName, const Setting &setting, int steps) {
  std::unique_ptr<AnchorScene> scene = MakeScene(sceneName);
  MdtWorldID world = scene->world();
  MdtWorldSetKeaMethod(world, setting.method);
  MdtWorldSetKeaIterativeRows(world, 0);  // the fixed settings apply to every partition
  MdtWorldSetKeaMaxIterations(world, setting.iterations);
  MdtWorldSetStepBudget(world, (MeReal)setting.budget);
  std::vector<double> whole, dynamics;
  Outcome out;
  int within = 0, counted = 0;
  for (int i = 0; i < steps; ++i) {
    const Clock::time_point t0 = Clock::now();
    scene->step();
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    if (i < steps / 10) continue;
    whole.push_back(us);
    if (setting.budget <= 0) continue;
    MdtWorldStepStats s;
    MdtWorldGetStepStats(world, &s);
    dynamics.push_back(s.budgetMeasured);
    ++counted;
    if (s.budgetMeasured >= 0.8 * setting.budget && s.budgetMeasured <= 1.2 * setting.budget) ++within;
    out.worstLevel = std::max(out.worstLevel, s.budgetLevel);
    if (s.budgetSweeps > 0)
      out.fewestSweeps = out.fewestSweeps ? std::min(out.fewestSweeps, s.budgetSweeps) : s.budgetSweeps;
  }
  out.wholeMedian = Median(whole);
  out.dynamicsMedian = Median(dynamics);
  out.withinShare = counted ? (double)within / counted : 0;
  out.error = ErrorFigure(sceneName, scene->finish());
  return out;
}

// One line per step: the budget's choices, prediction and measurement.
int Trace(const std::string &sceneName, double budget, int steps) {
  std::unique_ptr<AnchorScene> scene = MakeScene(sceneName);
  MdtWorldSetStepBudget(scene->world(), (MeReal)budget);
  std::printf("step partitions rows level fewest_sweeps iterative_partitions solves predicted_us measured_us\n");
  for (int i = 0; i < steps; ++i) {
    scene->step();
    MdtWorldStepStats s;
    MdtWorldGetStepStats(scene->world(), &s);
    std::printf("%d %d %d %s %d %d %d %.1f %.1f\n", i, s.partitions, s.rows,
                MdtWorldGetStepBudgetLevelName(s.budgetLevel), s.budgetSweeps, s.iterativePartitions, s.keaIterations,
                (double)s.budgetPredicted, (double)s.budgetMeasured);
  }
  std::printf("# %s: %.2f mm\n", sceneName == "topple" ? "worst top-box drift" : "deepest overlap",
              1000 * ErrorFigure(sceneName, scene->finish()));
  return 0;
}

// The median outcome of `reps` runs of each setting, run interleaved
// (setting 1, 2, ..., then again) so that the machine's drift in speed
// touches every setting alike.
std::vector<Outcome> RunInterleaved(const std::string &scene, const std::vector<Setting> &settings, int steps,
                                    int reps) {
  std::vector<std::vector<Outcome>> runs(settings.size());
  for (int r = 0; r < reps; ++r)
    for (size_t k = 0; k < settings.size(); ++k) runs[k].push_back(Run(scene, settings[k], steps));
  std::vector<Outcome> medians;
  for (const std::vector<Outcome> &v : runs) {
    const auto median = [&](double Outcome::*field) {
      std::vector<double> x;
      for (const Outcome &o : v) x.push_back(o.*field);
      return Median(x);
    };
    Outcome m;
    m.wholeMedian = median(&Outcome::wholeMedian);
    m.dynamicsMedian = median(&Outcome::dynamicsMedian);
    m.withinShare = median(&Outcome::withinShare);
    m.error = median(&Outcome::error);
    for (const Outcome &o : v) {
      m.worstLevel = std::max(m.worstLevel, o.worstLevel);
      if (o.fewestSweeps) m.fewestSweeps = m.fewestSweeps ? std::min(m.fewestSweeps, o.fewestSweeps) : o.fewestSweeps;
    }
    medians.push_back(m);
  }
  return medians;
}

struct Options {
  std::string scene;
  int steps = 0;
  int reps = 3;
  double trace = 0;  // > 0: print the budget's choices at this budget
};

bool ParseOptions(int argc, char **argv, Options &o) {
  if (argc < 2) return false;
  o.scene = argv[1];
  if (o.scene != "topple" && o.scene != "pile1000") return false;
  o.steps = o.scene == "topple" ? 600 : 120;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--trace" && i + 1 < argc)
      o.trace = std::atof(argv[++i]);
    else if (a == "--reps" && i + 1 < argc)
      o.reps = std::max(1, std::atoi(argv[++i]));
    else if (std::isdigit((unsigned char)a[0]))
      o.steps = std::atoi(a.c_str());
    else
      return false;
  }
  return o.trace >= 0;
}

}  // namespace

int main(int argc, char **argv) {
  Options opt;
  if (!ParseOptions(argc, argv, opt)) {
    std::fprintf(stderr, "usage: %s topple|pile1000 [STEPS] [--reps N (3)] [--trace BUDGET]\n", argv[0]);
    return 2;
  }
  if (opt.trace > 0) return Trace(opt.scene, opt.trace, opt.steps);
  const std::string &scene = opt.scene;
  const char *errorName = scene == "topple" ? "worst top-box drift" : "deepest overlap";

  // An unbounded budget measures exact's dynamics time; a starved one the
  // floor: the step's cost outside the solves plus the cheapest solves,
  // which no budget can go below.
  const std::vector<Setting> timed = {{"exact (timed)", MdtKeaMethodActiveSet, 0, 1e9},
                                      {"floor (timed)", MdtKeaMethodActiveSet, 0, 1e-3}};
  const std::vector<Outcome> timedOut = RunInterleaved(scene, timed, opt.steps, opt.reps);
  const double exactDynamics = timedOut[0].dynamicsMedian, floorDynamics = timedOut[1].dynamicsMedian;

  // The iterative solver at the sweep counts a budget chooses among (10 to
  // 50) and below, odd and even.
  std::vector<Setting> fixed = {{"exact", MdtKeaMethodActiveSet, 0, 0}, {"exact:8", MdtKeaMethodActiveSet, 8, 0}};
  for (int sweeps : {50, 20, 15, 12, 11, 10, 9, 5})
    fixed.push_back({"iterative:" + std::to_string(sweeps), MdtKeaMethodPGS, sweeps, 0});
  std::vector<Setting> budgets;
  std::vector<double> fractions = {1.0, 0.85, 0.7, 0.55};
  for (double fraction : fractions) {
    const double budget = fraction * exactDynamics;
    char name[96];
    std::snprintf(name, sizeof name, "budget %.0f us (%.0f%% of exact%s)", budget, fraction * 100,
                  budget < floorDynamics ? ", below the floor" : "");
    budgets.push_back({name, MdtKeaMethodActiveSet, 0, budget});
  }
  std::vector<Setting> all = fixed;
  all.insert(all.end(), budgets.begin(), budgets.end());
  const std::vector<Outcome> out = RunInterleaved(scene, all, opt.steps, opt.reps);

  std::printf(
      "%s, %d steps, medians of %d interleaved runs, platform backend %s (KARMA_PLATFORM chooses); dynamics per "
      "step: exact %.1f us, floor %.1f us (%.0f%%)\n\n",
      scene.c_str(), opt.steps, opt.reps, MdtPlatformGetDefaultName(), exactDynamics, floorDynamics,
      100 * floorDynamics / exactDynamics);
  std::printf(
      "| setting | us per step (whole) | %s (mm) | dynamics us / budget | steps within 20%% | levels used | "
      "%s of the fixed settings that cost no more (mm) |\n",
      errorName, errorName);
  std::printf("|---|---|---|---|---|---|---|\n");
  for (size_t k = 0; k < fixed.size(); ++k)
    std::printf("| %s | %.1f | %.2f | | | | |\n", fixed[k].name.c_str(), out[k].wholeMedian, out[k].error * 1e3);
  for (size_t b = 0; b < budgets.size(); ++b) {
    const Outcome &o = out[fixed.size() + b];
    double least = std::numeric_limits<double>::infinity(), most = 0;
    for (size_t k = 0; k < fixed.size(); ++k)
      if (out[k].wholeMedian <= o.wholeMedian) {
        least = std::min(least, out[k].error);
        most = std::max(most, out[k].error);
      }
    char levels[64], sweeps[16] = "", predictedText[48] = "none cheaper";
    if (o.fewestSweeps) std::snprintf(sweeps, sizeof sweeps, ":%d", o.fewestSweeps);
    std::snprintf(levels, sizeof levels, "down to %s%s", MdtWorldGetStepBudgetLevelName(o.worstLevel), sweeps);
    if (std::isfinite(least))
      std::snprintf(predictedText, sizeof predictedText, "%.2f - %.2f", least * 1e3, most * 1e3);
    std::printf("| %s | %.1f | %.2f | %.2f | %.0f%% | %s | %s |\n", budgets[b].name.c_str(), o.wholeMedian,
                o.error * 1e3, o.dynamicsMedian / budgets[b].budget, o.withinShare * 100, levels, predictedText);
  }
  return 0;
}
