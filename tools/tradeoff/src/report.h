// report.h: the sweep's CSV and Markdown.
//
// CSV (one row per scene and setting, peers' points last; units in the
// column names; empty cell: not measured):
//   scene, precision, engine, setting, solver, epsilon, gamma, h,
//   tolerance, cap, projection, warm, reuse, repeats, us_per_step (median), us_min, us_max,
//   us_per_frame (the median's cost of 1/60 s simulated: x (1/60) / h), steps,
//   drift_m (largest RMS distance of the bodies from the reference run),
//   joint_error_m, penetration_m (deepest over the run), energy_error_J,
//   momentum_error_Ns (largest difference from the reference run),
//   residual (largest Kea residual of a step), unsolved_steps,
//   max_speed_mps, scene_error (the scene's own figure, see
//   builtin_scenes.h), held (1: stable and the scene's check held),
//   front_drift, front_scene (1: on that Pareto front), detail
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "results.h"

namespace karma::tradeoff {

// The CSV header line's columns, in order.
const std::vector<std::string> &CsvColumns();
// The index of the column `name` in CsvColumns(). Every name the tool asks
// for is one of them: a name that is not stops the program with a message
// (a bug, not a property of the file read).
size_t CsvColumn(const char *name);
void WriteCsv(std::FILE *f, const std::vector<ResultRow> &rows);

// What the Markdown says about a scene besides its rows.
struct SceneNote {
  std::string name, about;
  double seconds = 0;
  std::string reference;             // the reference run's setting
  std::string driftPlot, scenePlot;  // file names of the plots ("" if none)
};
void WriteMarkdown(std::FILE *f, const std::vector<ResultRow> &rows, const std::vector<SceneNote> &scenes,
                   const std::string &command);

}  // namespace karma::tradeoff

namespace karma::tradeoff {
// Reads a CSV written by WriteCsv (another build's sweep) back into rows;
// false with a message when the file cannot be read or its header differs.
bool ReadCsv(const std::string &path, std::vector<ResultRow> &out, std::string &error);
// Splits one CSV line (quoted cells, "" inside quotes).
std::vector<std::string> SplitCsvLine(const std::string &line);
}  // namespace karma::tradeoff
