// brute_force.h: the O(n^2) reference for the axis-sort farfield. Tests
// compare the space against it every frame; the benchmark times it.
#ifndef KARMA_MCD_FARFIELD_BRUTE_FORCE_H
#define KARMA_MCD_FARFIELD_BRUTE_FORCE_H

#include "axis_sort_space.h"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace karma::mcd {

struct Aabb {
  MeReal min[3];
  MeReal max[3];
};

// Every index pair (i < j), ascending, whose boxes overlap on each axis in
// the `axes` mask: a.min <= b.max && b.min <= a.max (closed intervals, the
// space's own test).
void BruteForceOverlaps(std::span<const Aabb> boxes, int axes, std::vector<std::pair<int, int>> &out);

// The pairs `space` should report right now (outside a change block), by
// brute force over its proxies' current AABBs: overlapping on its axes, not
// both frozen, enabled and not culled (the default frozen rule: with
// KeepFrozenPairs the answer depends on history and this does not apply). Each as the SerialPair its PairRecord
// would have ((earlier serial << 32) | later serial), ascending.
std::vector<std::uint64_t> BruteForceReported(const AxisSortSpace &space);

}  // namespace karma::mcd

#endif
