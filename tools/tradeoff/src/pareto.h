// pareto.h: the Pareto front of (cost, error) points: a point is on the
// front when no other valid point is at most as costly and at most as
// wrong, and strictly better in one of the two. Invalid points (failed
// runs, NaN or infinite values) are never on the front and never
// dominate.
#pragma once

#include <vector>

namespace karma::tradeoff {

struct CostError {
  double cost = 0;  // µs per step
  double error = 0;
  bool valid = true;
};

// front[i] is true when point i is on the front. Equal points are all on it.
std::vector<bool> ParetoFront(const std::vector<CostError> &points);

}  // namespace karma::tradeoff
