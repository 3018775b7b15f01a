// step_budget.cpp: MdtWorldSetStepBudget on an anchor scene, against the
// fixed settings it chooses between, in one run:
//   build/release/bench/step_budget topple|pile1000 [STEPS]
// For each fixed setting (exact, exact:8, iterative:50/20/10/5) and each
// budget (a fraction of the exact run's dynamics time, measured first in
// the same run) it prints the median microseconds per whole step
// (collision and dynamics), the scene's error figure, and for the budgets
// the median dynamics time against the budget, the share of steps within
// 20 % of it, and the error the fixed settings predict at that cost: the
// smallest error among the fixed settings whose whole step costs no more.
// Medians skip the first tenth of the steps (the cost model learning).
//   build/release/bench/step_budget topple|pile1000 --trace BUDGET [STEPS]
// prints what the budget chose at each step instead.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
  std::unique_ptr<AnchorScene> scene =
      sceneName == "topple" ? karma::scenes::MakeTopple() : karma::scenes::MakePile1000();
  MdtWorldID world = scene->world();
  MdtWorldSetKeaMethod(world, setting.method);
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
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  const std::string scene = argc > 1 ? argv[1] : "";
  if (scene != "topple" && scene != "pile1000") {
    std::fprintf(stderr, "usage: %s topple|pile1000 [STEPS] | %s topple|pile1000 --trace BUDGET [STEPS]\n", argv[0],
                 argv[0]);
    return 2;
  }
  const int defaultSteps = scene == "topple" ? 600 : 120;
  if (argc > 3 && !std::strcmp(argv[2], "--trace"))
    return Trace(scene, std::atof(argv[3]), argc > 4 ? std::atoi(argv[4]) : defaultSteps);
  const int steps = argc > 2 ? std::atoi(argv[2]) : defaultSteps;
  const char *errorName = scene == "topple" ? "worst top-box drift" : "deepest overlap";

  // The exact run with an unbounded budget measures exact's dynamics time.
  const Outcome exactTimed = Run(scene, {"exact (timed)", MdtKeaMethodActiveSet, 0, 1e9}, steps);
  const double exactDynamics = exactTimed.dynamicsMedian;

  std::vector<Setting> fixed = {{"exact", MdtKeaMethodActiveSet, 0, 0},   {"exact:8", MdtKeaMethodActiveSet, 8, 0},
                                {"iterative:50", MdtKeaMethodPGS, 50, 0}, {"iterative:20", MdtKeaMethodPGS, 20, 0},
                                {"iterative:10", MdtKeaMethodPGS, 10, 0}, {"iterative:5", MdtKeaMethodPGS, 5, 0}};
  std::vector<Outcome> fixedOut;
  std::printf("%s, %d steps; the exact solver's dynamics: %.1f us per step\n\n", scene.c_str(), steps, exactDynamics);
  std::printf(
      "| setting | us per step (whole) | %s (mm) | dynamics us / budget | steps within 20%% | levels used | "
      "predicted %s (mm) |\n",
      errorName, errorName);
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Setting &s : fixed) {
    fixedOut.push_back(Run(scene, s, steps));
    const Outcome &o = fixedOut.back();
    std::printf("| %s | %.1f | %.2f | | | | |\n", s.name.c_str(), o.wholeMedian, o.error * 1e3);
  }
  for (double fraction : {1.0, 0.85, 0.7, 0.55}) {
    const double budget = fraction * exactDynamics;
    char name[64];
    std::snprintf(name, sizeof name, "budget %.0f us (%.0f%% of exact)", budget, fraction * 100);
    const Outcome o = Run(scene, {name, MdtKeaMethodActiveSet, 0, budget}, steps);
    double predicted = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < fixed.size(); ++k)
      if (fixedOut[k].wholeMedian <= o.wholeMedian) predicted = std::min(predicted, fixedOut[k].error);
    char levels[64], sweeps[16] = "", predictedText[32] = "none cheaper";
    if (o.fewestSweeps) std::snprintf(sweeps, sizeof sweeps, ":%d", o.fewestSweeps);
    std::snprintf(levels, sizeof levels, "down to %s%s", MdtWorldGetStepBudgetLevelName(o.worstLevel), sweeps);
    if (std::isfinite(predicted)) std::snprintf(predictedText, sizeof predictedText, "%.2f", predicted * 1e3);
    std::printf("| %s | %.1f | %.2f | %.2f | %.0f%% | %s | %s |\n", name, o.wholeMedian, o.error * 1e3,
                o.dynamicsMedian / budget, o.withinShare * 100, levels, predictedText);
  }
  return 0;
}
