// sweep.cpp: the sweep's loop and its progress line (sweep.h).
#include "sweep.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "run.h"

namespace karma::tradeoff {

namespace {

// One line on stderr, rewritten in place on a terminal.
class Progress {
 public:
  Progress() : tty_(isatty(2) != 0) {}
  ~Progress() {
    if (tty_ && dirty_) std::fprintf(stderr, "\n");
  }
  void show(const std::string &line) {
    if (tty_)
      std::fprintf(stderr, "\r\033[K%s", line.c_str()), dirty_ = true;
    else
      std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
  }

 private:
  bool tty_;
  bool dirty_ = false;
};

std::string Line(const char *format, ...) __attribute__((format(printf, 1, 2)));
std::string Line(const char *format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  return text;
}

void Fill(ResultRow &row, const RunRecord &run, const RunRecord &reference) {
  const Errors e = CompareWithReference(run, reference);
  row.steps = run.steps;
  row.drift = e.drift;
  row.energyError = e.energy;
  row.momentumError = e.momentum;
  row.jointError = run.jointError;
  row.penetration = run.penetration;
  row.residual = run.residual;
  row.unsolvedSteps = run.unsolvedSteps;
  row.maxSpeed = run.maxSpeed;
  row.sceneError = run.finite ? run.outcome.sceneError : std::nan("");
  row.held = run.held();
  row.detail = run.finite ? run.outcome.detail : "not finite";
}

}  // namespace

double ReferenceStep(const SweepPlan &plan) {
  if (plan.referenceStep > 0) return plan.referenceStep;
  double h = 1.0 / 60;
  for (const Setting &s : plan.settings) h = std::min(h, s.h);
  return h / 8;
}

// The exact solver at the reference step, every collision pair tested
// every step (no contact reuse).
Setting ReferenceSetting(const SweepPlan &plan) {
  Setting s;
  s.h = ReferenceStep(plan);
  s.reuse = 0;
  return s;
}

std::vector<ResultRow> RunSweep(const SweepPlan &plan) {
  std::vector<ResultRow> rows;
  Progress progress;
  const Setting reference = ReferenceSetting(plan);
  const size_t n = plan.settings.size();
  for (const SceneEntry &scene : plan.scenes) {
    const double seconds = plan.seconds > 0 ? plan.seconds : scene.seconds;
    progress.show(
        Line("karma-tradeoff: %s: reference run (%s, %.3g s)", scene.name.c_str(), reference.label().c_str(), seconds));
    RunRecord ref;
    if (!RunScene(scene, reference, seconds, ref)) {
      progress.show(Line("karma-tradeoff: %s: the scene could not be built; skipped", scene.name.c_str()));
      continue;
    }
    const size_t first = rows.size();
    for (const Setting &s : plan.settings) {
      ResultRow row;
      row.scene = scene.name;
      row.precision = plan.precision;
      row.setting = s;
      rows.push_back(row);
    }
    for (int rep = 0; rep < plan.repeat; ++rep) {
      for (size_t k = 0; k < n; ++k) {
        const size_t i = (k + (size_t)rep) % n;  // rotate the first setting
        ResultRow &row = rows[first + i];
        RunRecord run;
        if (!RunScene(scene, row.setting, seconds, run)) continue;
        if (rep == 0) Fill(row, run, ref);
        row.micros.push_back(run.microsPerStep());
        progress.show(Line("karma-tradeoff: %s: run %zu/%zu (repetition %d/%d) %s: %.4g µs/step, drift %.3g m%s",
                           scene.name.c_str(), (size_t)rep * n + k + 1, n * (size_t)plan.repeat, rep + 1, plan.repeat,
                           row.setting.label().c_str(), run.microsPerStep(), row.drift, row.held ? "" : " [failed]"));
      }
    }
  }
  return rows;
}

}  // namespace karma::tradeoff
