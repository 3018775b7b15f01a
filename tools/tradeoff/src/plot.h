// plot.h: a scene's trade-off plot through gnuplot: error against the
// cost of 1/60 s of simulated time (µs per step x (1/60) / h), log-log,
// one point per setting, the Pareto front drawn as a line through its
// points (labelled with their settings), failed runs as red crosses
// (unlabelled: the table names them), peers' points (when given) as
// labelled squares. Errors at or below kErrorFloor are drawn at it (a log
// axis has no zero).
#pragma once

#include <string>
#include <vector>

#include "results.h"

namespace karma::tradeoff {

inline constexpr double kErrorFloor = 1e-7;

struct PlotRequest {
  std::string scene;
  bool sceneError = false;  // the scene's error (with the peers) or the drift
  std::string title, yLabel;
  std::string path;  // the PNG to write; its script goes beside it
  int width = 800, height = 600;
};

// The gnuplot to run: $KARMA_GNUPLOT, else the one found at configure
// time, else "gnuplot" on the PATH. Empty when none can be run.
std::string FindGnuplot();
// Writes path.gp (the script with its data) and runs gnuplot; false with
// a message (gnuplot's own messages in path.log).
bool Plot(const std::string &gnuplot, const PlotRequest &request, const std::vector<ResultRow> &rows,
          std::string &error);

}  // namespace karma::tradeoff
