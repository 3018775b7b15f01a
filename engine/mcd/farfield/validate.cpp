// validate.cpp: AxisSortSpace::Validate, the invariants of the other files
// checked from scratch (O(n^2); tests only).
#include "axis_sort_space.h"

#include "MeMessage.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace karma::mcd {

namespace {
bool Fail(const char *what) {
  MeWarning(0, "AxisSortSpace::Validate: %s", what);
  return false;
}
}  // namespace

bool AxisSortSpace::Validate() const {
  if (changing_) return Fail("called inside a change block");
  const int slots = static_cast<int>(proxies_.size());
  int live = 0;
  for (int s = 0; s < slots; ++s) {
    const ProxyState st = proxies_[static_cast<std::size_t>(s)].state;
    if (st == ProxyState::Pending || st == ProxyState::Removed) return Fail("unsynchronised proxy after EndChanges");
    if (st == ProxyState::Live) ++live;
  }
  if (live != proxyCount_) return Fail("proxy count");
  // The active sets ("Cost" in the header): the unfrozen list holds exactly
  // the live unfrozen proxies, each at its recorded index; nothing is left
  // marked as moved after a sort; every stayings entry is still settled.
  int unfrozen = 0;
  for (int s = 0; s < slots; ++s) {
    const Proxy &p = proxies_[static_cast<std::size_t>(s)];
    const int pos = unfrozenPos_[static_cast<std::size_t>(s)];
    const bool listed =
        pos >= 0 && pos < static_cast<int>(unfrozen_.size()) && unfrozen_[static_cast<std::size_t>(pos)] == s;
    if (listed != (p.state == ProxyState::Live && !p.frozen)) return Fail("unfrozen list");
    unfrozen += listed;
    if (movedFlag_[static_cast<std::size_t>(s)] && !dirty_) return Fail("a moved mark survived the sort");
  }
  if (unfrozen != static_cast<int>(unfrozen_.size())) return Fail("unfrozen list size");
  std::vector<const PairRecord *> active;
  for (const PairRecord *r : stayings_) {
    if (r->state != PairState::Staying) return Fail("a staying record in another state");
    if (!(proxies_[static_cast<std::size_t>(r->proxyA)].frozen && proxies_[static_cast<std::size_t>(r->proxyB)].frozen))
      active.push_back(r);
  }
  if (activeStayingsVersion_ == stayingsVersion_ && frozenChanged_.empty() &&
      !std::equal(active.begin(), active.end(), activeStayings_.begin(), activeStayings_.end()))
    return Fail("the active stayings are not the stayings of an unfrozen proxy");
  for (int k = 0; k < axisCount_; ++k) {
    const EndpointAxis &ax = axis_[k];
    if (!ax.IsSorted()) return Fail("an axis is not sorted");
    if (ax.Size() != 2 * live) return Fail("endpoint count");
    for (int i = 0; i < ax.Size(); ++i) {
      const Endpoint &e = ax.At(i);
      if (proxies_[static_cast<std::size_t>(e.Slot())].state != ProxyState::Live)
        return Fail("endpoint of a dead proxy");
      if ((e.IsMax() ? ax.MaxPos(e.Slot()) : ax.MinPos(e.Slot())) != i) return Fail("endpoint position");
      const Proxy &p = proxies_[static_cast<std::size_t>(e.Slot())];
      if (e.Value() != (e.IsMax() ? p.max : p.min)[axisIndex_[k]]) return Fail("endpoint value");
    }
  }
  // The overlap table holds exactly the overlapping pairs, all overlapping.
  std::unordered_map<std::uint64_t, int> entries;
  for (const OverlapEntry &e : overlaps_.Entries()) {
    if (!e.overlapping) return Fail("an entry that ended survived EndChanges");
    entries[e.key] = e.record;
  }
  long long overlapping = 0;
  for (int a = 0; a < slots; ++a) {
    if (proxies_[static_cast<std::size_t>(a)].state != ProxyState::Live) continue;
    for (int b = a + 1; b < slots; ++b) {
      if (proxies_[static_cast<std::size_t>(b)].state != ProxyState::Live) continue;
      if (!OverlapsOnOtherAxes(-1, a, b)) continue;
      ++overlapping;
      if (!entries.count(SlotPairKey(a, b))) return Fail("an overlapping pair is missing from the table");
    }
  }
  if (overlapping != static_cast<long long>(entries.size())) return Fail("a pair in the table does not overlap");
  // The per-slot lists: every entry reached once from each of its slots.
  std::unordered_map<std::uint64_t, int> reached;
  for (int s = 0; s < slots; ++s) {
    int steps = 0;
    for (int i = overlaps_.Head(s); i >= 0; ++steps) {
      if (steps > overlaps_.Size()) return Fail("a per-slot list loops");
      const OverlapEntry &e = overlaps_.Entries()[static_cast<std::size_t>(i)];
      if (e.SlotLo() != s && e.SlotHi() != s) return Fail("an entry in the list of a slot it does not name");
      ++reached[e.key];
      i = e.next[OverlapTable::Side(e, s)];
    }
  }
  for (const OverlapEntry &e : overlaps_.Entries()) {
    if (reached[e.key] != 2) return Fail("an entry not in both its slots' lists");
  }
  // Records: each reported one owned by its entry; lists in order.
  int owned = 0;
  for (const auto &kv : entries) owned += kv.second >= 0;
  if (owned != static_cast<int>(hellos_.size() + stayings_.size())) return Fail("record ownership");
  for (const auto *list : {&goodbyes_, &hellos_, &stayings_}) {
    for (std::size_t i = 1; i < list->size(); ++i) {
      if ((*list)[i - 1]->Order() >= (*list)[i]->Order()) return Fail("events out of order");
    }
  }
  for (const auto *list : {&hellos_, &stayings_}) {
    for (const PairRecord *r : *list) {
      auto it = entries.find(SlotPairKey(r->proxyA, r->proxyB));
      if (it == entries.end() || it->second != r->index) return Fail("a reported record without its entry");
      if (r->Order().first >= r->Order().second) return Fail("proxyA does not rank before proxyB");
    }
  }
  if (pairs_.InUse() != static_cast<int>(goodbyes_.size() + hellos_.size() + stayings_.size())) {
    return Fail("records in use");
  }
  return true;
}

}  // namespace karma::mcd
