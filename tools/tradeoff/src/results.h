// results.h: the rows of a sweep's report: one per scene and setting
// (plus the peers' points), with the errors against the scene's
// reference run.
#pragma once

#include <string>
#include <vector>

#include "settings.h"

namespace karma::tradeoff {

struct ResultRow {
  std::string scene;
  std::string precision;  // "single" or "double"
  Setting setting;
  std::string engine = "karma";  // a peer's name for a peer's point
  std::vector<double> micros;    // µs per step, one per repetition
  int steps = 0;
  double drift = 0, jointError = 0, penetration = 0, energyError = 0, momentumError = 0;
  double residual = 0;
  int unsolvedSteps = 0;
  double maxSpeed = 0;
  double sceneError = 0;    // NaN: the scene has none
  bool held = true;         // stable and the scene's check held
  std::string detail;       // the scene's figures
  bool frontDrift = false;  // on the Pareto front of (µs, drift)
  bool frontScene = false;  // on the Pareto front of (µs, scene error), peers excluded
  bool isPeer() const { return engine != "karma"; }
  // µs per step: the median and range of the repetitions.
  double median() const;
  double low() const;
  double high() const;
  // The cost of 1/60 s of simulated time, µs: median() x (1/60) / h. The
  // plots, fronts and summaries use it, so that a smaller step pays for
  // the extra steps it takes.
  double perFrame() const { return median() * (1.0 / 60) / setting.h; }
};

// Marks the two Pareto fronts among the rows of `scene` (peers excluded).
void MarkFronts(std::vector<ResultRow> &rows, const std::string &scene);

// The knobs in which two settings differ, e.g. "solver and h".
std::string DifferingKnobs(const Setting &a, const Setting &b);

// One sentence on a scene's front (costs per 1/60 s simulated): which change buys most accuracy per
// microsecond. `sceneError` picks the error (scene error or drift).
std::string FrontSummary(const std::vector<ResultRow> &rows, const std::string &scene, bool sceneError);

}  // namespace karma::tradeoff
