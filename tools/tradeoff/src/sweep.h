// sweep.h: running a sweep: for each scene, the reference run, then every
// setting `repeat` times. The repetitions are interleaved (all settings
// once, then all again, the first setting rotating) so that the machine's
// drift in speed touches every setting alike; µs per step is the median
// over the repetitions, the errors come from the first (runs are
// deterministic).
//
// The reference run: the exact solver (Kea's active set, default cap and
// tolerance), the scene's own epsilon and gamma, a step `referenceStep`
// (by default the smaller of 1/60 and the sweep's smallest h, divided by
// 8), in this build's precision. The errors of every run are measured
// against it at the common instants k/60 s.
#pragma once

#include <string>
#include <vector>

#include "results.h"
#include "scene.h"

namespace karma::tradeoff {

struct SweepPlan {
  std::vector<SceneEntry> scenes;
  std::vector<Setting> settings;
  int repeat = 3;
  double seconds = 0;        // 0: each scene's own
  double referenceStep = 0;  // 0: the default above
  std::string precision;     // this build's, written into the rows
};

// The reference step of a plan (see the top).
double ReferenceStep(const SweepPlan &plan);
// The reference run's setting, as written in the report.
Setting ReferenceSetting(const SweepPlan &plan);
// Runs the plan; a progress line goes to stderr. Scenes that cannot be
// built are reported there and skipped.
std::vector<ResultRow> RunSweep(const SweepPlan &plan);

}  // namespace karma::tradeoff
