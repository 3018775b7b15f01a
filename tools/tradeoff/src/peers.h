// peers.h: the other engines' points for the plots, read from the
// Markdown table bench/peers/peer_bench prints (scripts/peers.sh): per row
// the scene, the engine, the median µs per step, whether it was stable and
// the scene's figures, from which the scene error (builtin_scenes.h) is
// computed the same way as for Karma's runs:
//   car      "x X m (analytic A)"            -> |X - A|
//   topple   "drift D mm, drop P mm"         -> max(D, |P - closure|)
//   stack21  "top box drift D mm, height Y m" -> max(D, |y0 - Y - closure|),
//            y0 the top box's start, closure = StackClosure (builtin_scenes.h)
//   ragdoll  "joint error: max J mm"         -> J
//   pile1000 the penetration column (mm)
// Rows of scenes that are not anchor scenes, or that do not parse, are
// skipped.
#pragma once

#include <string>
#include <vector>

#include "results.h"

namespace karma::tradeoff {

// Parses the table; returns false (with a message) only when the file
// cannot be read.
bool ReadPeerTable(const std::string &path, std::vector<ResultRow> &out, std::string &error);
// One row of the table, false when it is not a data row.
bool ParsePeerRow(const std::string &line, ResultRow &out);

}  // namespace karma::tradeoff
