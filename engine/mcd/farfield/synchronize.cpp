// synchronize.cpp: the sort-and-sweep. Brings the sorted axes and the
// overlap table up to date with the proxies, in three stages:
//   1. removed proxies leave the arrays (one compaction pass per axis);
//   2. every axis is re-sorted by insertion sort from last frame's order,
//      each overlap-changing swap updating the overlap table;
//   3. proxies inserted since are merged in as a batch and a sweep along the
//      first sorted axis finds their overlaps.
// Invariant after each stage: the overlap table holds an entry with
// overlapping == true exactly for the pairs of Live proxies that overlap on
// every sorted axis in the current rank order (endpoint_axis.h). Entries with
// overlapping == false (or naming a Removed/Retired proxy) are pairs that
// stopped overlapping and still own a record; ComputeEvents settles them.
#include "axis_sort_space.h"

namespace karma::mcd {

bool AxisSortSpace::OverlapsOnOtherAxes(int axis, int a, int b) const {
  for (int k = 0; k < axisCount_; ++k) {
    if (k != axis && !axis_[k].Overlaps(a, b)) return false;
  }
  return true;
}

// One swap on sorted axis `axis` changed whether a and b overlap there. The
// pair's overlap count reaches (or leaves) the number of sorted axes exactly
// when the other axes all overlap.
void AxisSortSpace::OnAxisSwap(int axis, int a, int b, bool begins) {
  ++swaps_;
  if (!OverlapsOnOtherAxes(axis, a, b)) return;
  const std::uint64_t key = SlotPairKey(a, b);
  NoteTouched(key);
  if (begins) {
    overlaps_.FindOrAdd(key).overlapping = true;  // new, or back within the block
  } else if (OverlapEntry *e = overlaps_.Find(key)) {
    if (e->record < 0) {
      overlaps_.Erase(key);
    } else {
      e->overlapping = false;  // keeps its record until ComputeEvents
    }
  }
}

void AxisSortSpace::Synchronize() {
  // 1. Removals.
  if (anyRemoved_) {
    const int n = static_cast<int>(proxies_.size());
    for (int s = 0; s < n; ++s) {
      gone_[static_cast<std::size_t>(s)] = proxies_[static_cast<std::size_t>(s)].state == ProxyState::Removed;
    }
    for (int k = 0; k < axisCount_; ++k) axis_[k].Compact(gone_);
    for (int s = 0; s < n; ++s) {
      if (gone_[static_cast<std::size_t>(s)]) {
        proxies_[static_cast<std::size_t>(s)].state = ProxyState::Retired;
        retired_.push_back(s);
        gone_[static_cast<std::size_t>(s)] = 0;
      }
    }
    anyRemoved_ = false;
  }
  // 2. Insertion sort, axis by axis. The other axes may still be unsorted;
  // the rank-order invariant makes that harmless.
  if (dirty_) {
    swaps_ = 0;
    SortAxes();
    dirty_ = false;
  }
  // 3. New proxies.
  if (!pending_.empty()) SweepNewProxies();
}

// Merges the pending proxies into every axis and adds their overlaps: one
// pass along the first sorted axis with the set of intervals open at each
// point. A new proxy is tested against every open interval; an old one only
// against the open new ones (old-old pairs are already known).
void AxisSortSpace::SweepNewProxies() {
  std::vector<NewInterval> added;
  added.reserve(pending_.size());
  for (int k = 0; k < axisCount_; ++k) {
    added.clear();
    const int w = axisIndex_[k];
    for (int s : pending_) {
      const Proxy &p = proxies_[static_cast<std::size_t>(s)];
      if (p.state != ProxyState::Pending) continue;  // removed again before this sync
      added.push_back({s, p.min[w], p.max[w]});
    }
    axis_[k].Merge(added);
  }
  for (int s : pending_) {
    Proxy &p = proxies_[static_cast<std::size_t>(s)];
    if (p.state != ProxyState::Pending) continue;
    p.state = ProxyState::Live;
    isNew_[static_cast<std::size_t>(s)] = 1;
  }

  auto open = [](std::vector<int> &list, std::vector<int> &pos, int s) {
    pos[static_cast<std::size_t>(s)] = static_cast<int>(list.size());
    list.push_back(s);
  };
  auto close = [](std::vector<int> &list, std::vector<int> &pos, int s) {
    const int at = pos[static_cast<std::size_t>(s)];
    const int last = list.back();
    list[static_cast<std::size_t>(at)] = last;
    pos[static_cast<std::size_t>(last)] = at;
    list.pop_back();
    pos[static_cast<std::size_t>(s)] = -1;
  };
  active_.clear();
  activeNew_.clear();
  const EndpointAxis &sweep = axis_[0];
  for (int i = 0; i < sweep.Size(); ++i) {
    const Endpoint &e = sweep.At(i);
    const int s = e.Slot();
    const bool fresh = isNew_[static_cast<std::size_t>(s)] != 0;
    if (e.IsMax()) {
      close(active_, activePos_, s);
      if (fresh) close(activeNew_, activeNewPos_, s);
      continue;
    }
    // Every open interval overlaps s on the sweep axis (rank order).
    for (int t : fresh ? active_ : activeNew_) {
      if (!OverlapsOnOtherAxes(0, s, t)) continue;
      NoteTouched(SlotPairKey(s, t));
      overlaps_.FindOrAdd(SlotPairKey(s, t)).overlapping = true;
    }
    open(active_, activePos_, s);
    if (fresh) open(activeNew_, activeNewPos_, s);
  }
  for (int s : pending_) isNew_[static_cast<std::size_t>(s)] = 0;
  pending_.clear();
}

}  // namespace karma::mcd
