// pareto.cpp: the Pareto front (pareto.h), by pairwise dominance: O(n^2),
// n is a sweep's handful of settings.
#include "pareto.h"

#include <cmath>

namespace karma::tradeoff {

namespace {

bool Usable(const CostError &p) { return p.valid && std::isfinite(p.cost) && std::isfinite(p.error); }

// a dominates b: no worse in both, better in one.
bool Dominates(const CostError &a, const CostError &b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

}  // namespace

std::vector<bool> ParetoFront(const std::vector<CostError> &points) {
  std::vector<bool> front(points.size(), false);
  for (size_t i = 0; i < points.size(); ++i) {
    if (!Usable(points[i])) continue;
    bool dominated = false;
    for (size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && Usable(points[j]) && Dominates(points[j], points[i]);
    front[i] = !dominated;
  }
  return front;
}

}  // namespace karma::tradeoff
