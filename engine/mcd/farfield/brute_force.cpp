// brute_force.cpp: the O(n^2) reference (see brute_force.h).
#include "brute_force.h"

#include <algorithm>

namespace karma::mcd {

namespace {
bool Overlap(const MeReal amin[3], const MeReal amax[3], const MeReal bmin[3], const MeReal bmax[3], int axes) {
  for (int k = 0; k < 3; ++k) {
    if ((axes & (1 << k)) && !(amin[k] <= bmax[k] && bmin[k] <= amax[k])) return false;
  }
  return true;
}
}  // namespace

void BruteForceOverlaps(std::span<const Aabb> boxes, int axes, std::vector<std::pair<int, int>> &out) {
  out.clear();
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i) {
    const Aabb &a = boxes[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < n; ++j) {
      const Aabb &b = boxes[static_cast<std::size_t>(j)];
      if (Overlap(a.min, a.max, b.min, b.max, axes)) out.emplace_back(i, j);
    }
  }
}

std::vector<std::uint64_t> BruteForceReported(const AxisSortSpace &space) {
  std::vector<ProxyId> ids;
  std::vector<Aabb> boxes;
  for (ProxyId id = space.NextProxy(kNoProxy); id != kNoProxy; id = space.NextProxy(id)) {
    Aabb box;
    space.GetAabb(id, box.min, box.max);
    ids.push_back(id);
    boxes.push_back(box);
  }
  std::vector<std::pair<int, int>> pairs;
  BruteForceOverlaps(boxes, space.Axes(), pairs);
  std::vector<std::uint64_t> keys;
  for (const auto &[i, j] : pairs) {
    const ProxyId a = ids[static_cast<std::size_t>(i)], b = ids[static_cast<std::size_t>(j)];
    if (space.IsFrozen(a) && space.IsFrozen(b)) continue;
    if (!space.PairIsEnabled(a, b)) continue;
    const std::uint32_t sa = space.ProxySerial(a), sb = space.ProxySerial(b);
    keys.push_back((std::uint64_t{std::min(sa, sb)} << 32) | std::max(sa, sb));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace karma::mcd
