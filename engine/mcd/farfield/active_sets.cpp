// active_sets.cpp: the lists that let a frame cost what moves ("Cost" in
// axis_sort_space.h): unfrozen proxies, moved proxies and the sort near
// them, and the stayings that are not frozen on both sides.
#include "axis_sort_space.h"

#include <algorithm>

namespace karma::mcd {

void AxisSortSpace::NoteUnfrozen(int slot) {
  int &pos = unfrozenPos_[static_cast<std::size_t>(slot)];
  if (pos >= 0) return;
  if (!unfrozen_.empty() && unfrozen_.back() > slot) unfrozenSorted_ = false;
  pos = static_cast<int>(unfrozen_.size());
  unfrozen_.push_back(slot);
}

void AxisSortSpace::DropUnfrozen(int slot) {
  int &pos = unfrozenPos_[static_cast<std::size_t>(slot)];
  if (pos < 0) return;
  const int last = unfrozen_.back();
  unfrozen_[static_cast<std::size_t>(pos)] = last;
  unfrozenPos_[static_cast<std::size_t>(last)] = pos;
  unfrozen_.pop_back();
  pos = -1;
  if (last != slot) unfrozenSorted_ = false;
}

void AxisSortSpace::SortUnfrozen() {
  if (unfrozenSorted_) return;
  std::sort(unfrozen_.begin(), unfrozen_.end());
  for (std::size_t i = 0; i < unfrozen_.size(); ++i) unfrozenPos_[static_cast<std::size_t>(unfrozen_[i])] = (int)i;
  unfrozenSorted_ = true;
}

void AxisSortSpace::NoteMoved(int slot) {
  std::uint8_t &flag = movedFlag_[static_cast<std::size_t>(slot)];
  if (flag) return;
  flag = 1;
  moved_.push_back(slot);
}

// Stage 2 of Synchronize: every axis re-sorted, each overlap-changing swap
// reported to OnAxisSwap. When many proxies moved, the plain pass is as
// cheap; both make the same swaps in the same order.
void AxisSortSpace::SortAxes() {
  const bool few = moved_.size() * 8 < static_cast<std::size_t>(proxyCount_ > 0 ? proxyCount_ : 1);
  for (int k = 0; k < axisCount_; ++k) {
    auto onSwap = [this, k](int a, int b, bool begins) { OnAxisSwap(k, a, b, begins); };
    if (!few) {
      axis_[k].Sort(onSwap);
      continue;
    }
    movedPositions_.clear();
    for (int s : moved_) {
      if (proxies_[static_cast<std::size_t>(s)].state != ProxyState::Live) continue;
      movedPositions_.push_back(axis_[k].MinPos(s));
      movedPositions_.push_back(axis_[k].MaxPos(s));
    }
    std::sort(movedPositions_.begin(), movedPositions_.end());
    axis_[k].SortNear(movedPositions_, onSwap);
  }
  for (int s : moved_) movedFlag_[static_cast<std::size_t>(s)] = 0;
  moved_.clear();
}

void AxisSortSpace::NoteFrozenChange(int slot) {
  if (frozenChanged_.size() >= 64) {  // cheaper to rebuild than to patch
    ++stayingsVersion_;
    frozenChanged_.clear();
    return;
  }
  frozenChanged_.push_back(slot);
}

// Up to date with the stayings and the frozen flags: patched for the
// proxies frozen or thawed since (their staying pairs join or leave), or
// rebuilt.
void AxisSortSpace::BuildActiveStayings() {
  auto byOrder = [](const PairRecord *l, const PairRecord *r) { return l->Order() < r->Order(); };
  if (activeStayingsVersion_ == stayingsVersion_) {
    for (int slot : frozenChanged_) {
      overlaps_.ForEachOf(slot, [&](OverlapEntry &e) {
        if (e.record < 0) return;
        PairRecord *r = &pairs_.At(e.record);
        if (r->state != PairState::Staying) return;
        const bool active = !(proxies_[static_cast<std::size_t>(r->proxyA)].frozen &&
                              proxies_[static_cast<std::size_t>(r->proxyB)].frozen);
        auto at = std::lower_bound(activeStayings_.begin(), activeStayings_.end(), r, byOrder);
        const bool present = at != activeStayings_.end() && *at == r;
        if (active && !present) activeStayings_.insert(at, r);
        if (!active && present) activeStayings_.erase(at);
      });
    }
    frozenChanged_.clear();
    return;
  }
  frozenChanged_.clear();
  activeStayings_.clear();
  for (PairRecord *r : stayings_) {
    const bool frozenA = proxies_[static_cast<std::size_t>(r->proxyA)].frozen;
    const bool frozenB = proxies_[static_cast<std::size_t>(r->proxyB)].frozen;
    if (!(frozenA && frozenB)) activeStayings_.push_back(r);
  }
  activeStayingsVersion_ = stayingsVersion_;
}

}  // namespace karma::mcd
