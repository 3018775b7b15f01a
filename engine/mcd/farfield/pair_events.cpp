// pair_events.cpp: turning the overlap table into hello / staying / goodbye
// events at EndChanges, and retiring goodbyes at BeginChanges.
//
// Invariants between EndChanges and the next BeginChanges:
//  - each record in hellos_ or stayings_ is owned by exactly one overlap
//    entry (entry.record == record.index), and that entry is reportable;
//  - goodbyes_ records are owned by no entry and go back to the pool at
//    BeginChanges, never earlier;
//  - hellos_, stayings_ and goodbyes_ each ascend by PairRecord::OrderKey,
//    so the order depends on the pairs and the insertion order only.
#include "axis_sort_space.h"

#include "MeMessage.h"

#include <algorithm>
#include <iterator>

namespace karma::mcd {

void AxisSortSpace::RetireGoodbyes() {
  for (PairRecord *r : goodbyes_) pairs_.Release(r);
  goodbyes_.clear();
}

void AxisSortSpace::ComputeEvents() {
  // The pairs reported by the previous EndChanges, in order.
  auto byKey = [](const PairRecord *l, const PairRecord *r) { return l->OrderKey() < r->OrderKey(); };
  previous_.clear();
  std::merge(stayings_.begin(), stayings_.end(), hellos_.begin(), hellos_.end(), std::back_inserter(previous_),
             byKey);
  goodbyes_.clear();
  hellos_.clear();
  stayings_.clear();
  candidates_.clear();
  eraseKeys_.clear();

  // Walk every overlap entry once: detach records whose pair is no longer
  // reportable, collect reportable pairs without a record, and drop entries
  // that neither overlap nor own a record.
  for (int i = 0; i < overlaps_.Size(); ++i) {
    OverlapEntry &e = overlaps_.At(i);
    const bool reportable = Reportable(e);
    if (e.record >= 0 && !reportable) {
      pairs_.At(e.record).state = PairState::Goodbye;
      e.record = -1;
    }
    if (e.record >= 0) continue;
    const Proxy &a = proxies_[static_cast<std::size_t>(e.SlotLo())];
    const Proxy &b = proxies_[static_cast<std::size_t>(e.SlotHi())];
    if (reportable) {
      const std::uint32_t lo = std::min(a.serial, b.serial), hi = std::max(a.serial, b.serial);
      candidates_.push_back({(std::uint64_t{lo} << 32) | hi, e.key});
    } else if (!e.overlapping || a.state != ProxyState::Live || b.state != ProxyState::Live) {
      eraseKeys_.push_back(e.key);
    }
  }
  for (std::uint64_t key : eraseKeys_) overlaps_.Erase(key);

  // Split last block's pairs into goodbyes and stayings, keeping the order.
  for (PairRecord *r : previous_) {
    if (r->state == PairState::Goodbye) {
      goodbyes_.push_back(r);
    } else {
      r->state = PairState::Staying;
      stayings_.push_back(r);
    }
  }

  // New pairs in order; the last ones go unreported if records run out.
  std::sort(candidates_.begin(), candidates_.end());
  droppedHellos_ = 0;
  for (const auto &[order, key] : candidates_) {
    PairRecord *r = pairs_.Acquire();
    if (!r) {
      ++droppedHellos_;
      continue;
    }
    OverlapEntry *e = overlaps_.Find(key);
    const int s0 = e->SlotLo(), s1 = e->SlotHi();
    const Proxy &p0 = proxies_[static_cast<std::size_t>(s0)];
    const Proxy &p1 = proxies_[static_cast<std::size_t>(s1)];
    const bool firstIsLo = p0.serial < p1.serial;
    r->proxyA = firstIsLo ? s0 : s1;
    r->proxyB = firstIsLo ? s1 : s0;
    r->userA = firstIsLo ? p0.user : p1.user;
    r->userB = firstIsLo ? p1.user : p0.user;
    r->serialA = static_cast<std::uint32_t>(order >> 32);
    r->serialB = static_cast<std::uint32_t>(order & 0xffffffffu);
    r->state = PairState::Hello;
    e->record = r->index;
    hellos_.push_back(r);
  }
  if (droppedHellos_ > 0) {
    MeWarning(0,
              "McdSpaceEndChanges: more overlapping pairs than pairCount (%d); %d new pairs not "
              "reported this step (raise pairCount in McdSpaceAxisSortCreate)",
              pairs_.Capacity(), droppedHellos_);
  }
}

}  // namespace karma::mcd
