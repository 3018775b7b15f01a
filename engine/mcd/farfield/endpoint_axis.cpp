// endpoint_axis.cpp: batch changes of one sorted axis (merge of new
// intervals, removal of gone slots) and the sortedness check. The per-frame
// insertion sort lives inline in endpoint_axis.h.
#include "endpoint_axis.h"

#include <algorithm>

namespace karma::mcd {

namespace {
// Total order used for batches: the sort key, then the data word, so equal
// keys still come out in one defined order whatever std::sort does.
bool BatchLess(const Endpoint &l, const Endpoint &r) {
  if (Greater(r, l)) return true;
  if (Greater(l, r)) return false;
  return l.data < r.data;
}
}  // namespace

void EndpointAxis::Reserve(int slotCount) {
  const auto n = static_cast<std::size_t>(slotCount);
  ends_.reserve(2 * n);
  scratch_.reserve(2 * n);
  minPos_.assign(n, -1);
  maxPos_.assign(n, -1);
}

void EndpointAxis::Reindex() {
  for (int i = 0; i < Size(); ++i) Place(ends_[static_cast<std::size_t>(i)], i);
}

void EndpointAxis::Merge(std::span<const NewInterval> added) {
  if (added.empty()) return;
  scratch_.clear();
  for (const NewInterval &a : added) {
    const auto slot = static_cast<std::uint32_t>(a.slot);
    scratch_.push_back({KeyOf(a.min), slot << 1});
    scratch_.push_back({KeyOf(a.max), (slot << 1) | 1u});
  }
  std::sort(scratch_.begin(), scratch_.end(), BatchLess);
  // Merge from the back so the existing array can grow in place. On equal
  // keys the existing endpoint stays first.
  const std::size_t oldSize = ends_.size();
  ends_.resize(oldSize + scratch_.size());
  std::size_t i = oldSize, k = scratch_.size(), out = ends_.size();
  while (k > 0) {
    if (i > 0 && Greater(ends_[i - 1], scratch_[k - 1])) {
      ends_[--out] = ends_[--i];
    } else {
      ends_[--out] = scratch_[--k];
    }
  }
  Reindex();
}

void EndpointAxis::Compact(const std::vector<std::uint8_t> &gone) {
  std::size_t out = 0;
  for (const Endpoint &e : ends_) {
    const auto slot = static_cast<std::size_t>(e.Slot());
    if (gone[slot]) {
      minPos_[slot] = maxPos_[slot] = -1;
      continue;
    }
    ends_[out++] = e;
  }
  ends_.resize(out);
  Reindex();
}

bool EndpointAxis::IsSorted() const {
  for (std::size_t i = 1; i < ends_.size(); ++i) {
    if (Greater(ends_[i - 1], ends_[i])) return false;
  }
  return true;
}

}  // namespace karma::mcd
