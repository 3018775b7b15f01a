// pair_events.cpp: turning the overlap table into hello / staying / goodbye
// events at EndChanges, and retiring goodbyes at BeginChanges.
//
// Invariants between EndChanges and the next BeginChanges:
//  - each record in hellos_ or stayings_ is owned by exactly one overlap
//    entry (entry.record == record.index), and that entry is reportable;
//  - goodbyes_ records are owned by no entry and go back to the pool at
//    BeginChanges, never earlier;
//  - hellos_, stayings_ and goodbyes_ each ascend by PairRecord::Order(),
//    so the order depends on the pairs' sort keys and, between equal keys,
//    on the insertion order only (see "Pair order" in axis_sort_space.h);
//  - the proxyA of a hello or staying record ranks before its proxyB.
#include "axis_sort_space.h"

#include "MeMessage.h"

#include <algorithm>
#include <iterator>

namespace karma::mcd {

void AxisSortSpace::RetireGoodbyes() {
  for (PairRecord *r : goodbyes_) pairs_.Release(r);
  goodbyes_.clear();
}

namespace {
std::uint64_t Packed(std::uint32_t key, std::uint32_t serial) { return ProxyRank{key, serial}.Packed(); }
}  // namespace

// Fills a new record for the pair of slots s0 and s1, the lower rank as A.
void AxisSortSpace::StartPair(PairRecord *r, int s0, int s1) {
  const Proxy &p0 = proxies_[static_cast<std::size_t>(s0)];
  const Proxy &p1 = proxies_[static_cast<std::size_t>(s1)];
  const bool firstIsA = Packed(p0.key, p0.serial) < Packed(p1.key, p1.serial);
  const int a = firstIsA ? s0 : s1, b = firstIsA ? s1 : s0;
  const Proxy &pa = proxies_[static_cast<std::size_t>(a)];
  const Proxy &pb = proxies_[static_cast<std::size_t>(b)];
  r->proxyA = a;
  r->proxyB = b;
  r->userA = pa.user;
  r->userB = pb.user;
  r->serialA = pa.serial;
  r->serialB = pb.serial;
  r->keyA = pa.key;
  r->keyB = pb.key;
  r->state = PairState::Hello;
}

// After a key change: every reported pair of two present proxies takes its
// proxies' current keys; one whose proxies now rank the other way round is
// marked Goodbye and left on its entry, for SettleEntry to detach (it says
// goodbye, and hello again as a new record if it is still reportable).
void AxisSortSpace::RerankReported() {
  auto present = [](const Proxy &p) { return p.state == ProxyState::Live || p.state == ProxyState::Pending; };
  for (const auto *list : {&stayings_, &hellos_}) {
    for (PairRecord *r : *list) {
      const Proxy &a = proxies_[static_cast<std::size_t>(r->proxyA)];
      const Proxy &b = proxies_[static_cast<std::size_t>(r->proxyB)];
      if (!present(a) || !present(b) || a.serial != r->serialA || b.serial != r->serialB) continue;
      if (Packed(a.key, a.serial) > Packed(b.key, b.serial)) {
        r->state = PairState::Goodbye;
        continue;
      }
      r->keyA = a.key;
      r->keyB = b.key;
    }
  }
}

// Settles one overlap entry: detaches its record if the pair is no longer
// reportable (true then) or its proxies swapped ranks (RerankReported marked
// the record Goodbye: the only attached record in that state), collects it
// as a candidate if it is reportable without a record, and marks it for
// erasure if it neither overlaps nor owns a record. Reportable is read
// while the record is attached, so a kept frozen pair that swapped ranks
// stays reported (with a new record).
bool AxisSortSpace::SettleEntry(OverlapEntry &e) {
  const bool reportable = Reportable(e);
  bool goodbye = false;
  if (e.record >= 0 && pairs_.At(e.record).state == PairState::Goodbye) e.record = -1;
  if (e.record >= 0 && !reportable) {
    PairRecord &r = pairs_.At(e.record);
    departed_.push_back({&r, r.state == PairState::Hello});
    r.state = PairState::Goodbye;
    e.record = -1;
    goodbye = true;
  }
  if (e.record >= 0) return goodbye;
  const Proxy &a = proxies_[static_cast<std::size_t>(e.SlotLo())];
  const Proxy &b = proxies_[static_cast<std::size_t>(e.SlotHi())];
  if (reportable) {
    const std::uint64_t ra = Packed(a.key, a.serial), rb = Packed(b.key, b.serial);
    candidates_.push_back({PairOrder{std::min(ra, rb), std::max(ra, rb)}, e.key});
  } else if (!e.overlapping || a.state != ProxyState::Live || b.state != ProxyState::Live) {
    eraseKeys_.push_back(e.key);
  }
  return goodbye;
}

namespace {

bool ByOrder(const PairRecord *l, const PairRecord *r) { return l->Order() < r->Order(); }

// Few records move in or out at a time: then a search and a block move
// each; else one pass.
constexpr std::size_t kFew = 8;

// Removes from `list` (ascending by Order()) each record of `gone` (also
// ascending) that it holds.
void RemoveByOrder(std::vector<PairRecord *> &list, const std::vector<PairRecord *> &gone) {
  if (gone.empty()) return;
  if (gone.size() <= kFew) {
    for (PairRecord *r : gone) {
      auto found = std::lower_bound(list.begin(), list.end(), r, ByOrder);
      if (found != list.end() && *found == r) list.erase(found);
    }
    return;
  }
  std::size_t out = 0, g = 0;
  auto at = list.begin();
  for (PairRecord *r : gone) {
    auto found = std::lower_bound(at, list.end(), r, ByOrder);
    if (found == list.end() || *found != r) continue;
    const std::size_t pos = static_cast<std::size_t>(found - list.begin());
    while (g < pos) list[out++] = list[g++];
    ++g;  // drop it
    at = found + 1;
  }
  while (g < list.size()) list[out++] = list[g++];
  list.resize(out);
}

// Merges `joining` (ascending by Order()) into `list` (ascending).
void MergeByOrder(std::vector<PairRecord *> &list, const std::vector<PairRecord *> &joining,
                  std::vector<PairRecord *> &scratch) {
  if (joining.empty()) return;
  if (joining.size() <= kFew) {
    for (PairRecord *r : joining) list.insert(std::upper_bound(list.begin(), list.end(), r, ByOrder), r);
    return;
  }
  scratch.clear();
  std::merge(list.begin(), list.end(), joining.begin(), joining.end(), std::back_inserter(scratch), ByOrder);
  list.swap(scratch);
}

}  // namespace

// The stayings after some goodbyes or last block's hellos, touching only
// the records that change: the goodbyes (departed_) in order; the stayings
// less the departed ones; last block's hellos that stay merged in as
// stayings. The active stayings follow when they are up to date.
void AxisSortSpace::UpdateStayings() {
  leaving_.clear();
  for (const Departure &d : departed_) {
    goodbyes_.push_back(d.record);
    if (!d.wasHello) leaving_.push_back(d.record);
  }
  std::sort(goodbyes_.begin(), goodbyes_.end(), ByOrder);
  std::sort(leaving_.begin(), leaving_.end(), ByOrder);
  RemoveByOrder(stayings_, leaving_);
  joining_.clear();
  for (PairRecord *r : hellos_) {
    if (r->state == PairState::Goodbye) continue;
    r->state = PairState::Staying;
    joining_.push_back(r);
  }
  hellos_.clear();
  MergeByOrder(stayings_, joining_, previous_);
  if (activeStayingsVersion_ != stayingsVersion_) return;  // rebuilt when next needed
  RemoveByOrder(activeStayings_, leaving_);
  std::size_t kept = 0;
  for (PairRecord *r : joining_) {
    const bool frozenPair =
        proxies_[static_cast<std::size_t>(r->proxyA)].frozen && proxies_[static_cast<std::size_t>(r->proxyB)].frozen;
    if (!frozenPair) joining_[kept++] = r;
  }
  joining_.resize(kept);
  MergeByOrder(activeStayings_, joining_, previous_);
}

void AxisSortSpace::ComputeEvents() {
  auto byOrder = ByOrder;
  const bool keysChanged = keysChanged_;
  if (keysChanged) RerankReported();
  candidates_.clear();
  eraseKeys_.clear();

  // Settle the overlap entries: every one, or (see "Cost" in the header)
  // only the touched ones and those of the touched proxies, the others
  // being unable to have changed.
  const std::uint64_t cullingRevision = CullingTablesRevision();
  const bool full =
      fullWalk_ || keysChanged || keepFrozenPairs_ != lastKeepFrozenPairs_ || cullingRevision != lastCullingRevision_;
  bool anyGoodbye = false;
  if (full) {
    for (int i = 0; i < overlaps_.Size(); ++i) anyGoodbye = SettleEntry(overlaps_.At(i)) || anyGoodbye;
  } else {
    for (int slot : touchedProxies_) overlaps_.ForEachOf(slot, [this](OverlapEntry &e) { touched_.push_back(e.key); });
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (std::uint64_t key : touched_)
      if (OverlapEntry *e = overlaps_.Find(key)) anyGoodbye = SettleEntry(*e) || anyGoodbye;
  }
  touched_.clear();
  touchedProxies_.clear();
  fullWalk_ = false;
  lastKeepFrozenPairs_ = keepFrozenPairs_;
  lastCullingRevision_ = cullingRevision;
  for (std::uint64_t key : eraseKeys_) overlaps_.Erase(key);

  // Last block's pairs, in order, split into goodbyes and stayings.
  goodbyes_.clear();
  if (keysChanged) {
    previous_.assign(stayings_.begin(), stayings_.end());
    previous_.insert(previous_.end(), hellos_.begin(), hellos_.end());
    std::sort(previous_.begin(), previous_.end(), byOrder);
    hellos_.clear();
    stayings_.clear();
    for (PairRecord *r : previous_) {
      if (r->state == PairState::Goodbye) {
        goodbyes_.push_back(r);
      } else {
        r->state = PairState::Staying;
        stayings_.push_back(r);
      }
    }
    ++stayingsVersion_;
  } else if (anyGoodbye || !hellos_.empty()) {
    UpdateStayings();
  }
  departed_.clear();
  keysChanged_ = false;

  // New pairs in order; the pool makes records as needed and raises its
  // limit when pairCount is exceeded (pair_table.h), reported once per space.
  std::sort(candidates_.begin(), candidates_.end());
  const int limit = pairs_.Limit();
  bool grew = false;
  for (const Candidate &c : candidates_) {
    PairRecord *r = pairs_.Acquire(&grew);
    OverlapEntry *e = overlaps_.Find(c.slots);
    StartPair(r, e->SlotLo(), e->SlotHi());
    e->record = r->index;
    hellos_.push_back(r);
  }
  if (grew && !warnedGrowth_) {
    MeWarning(0,
              "McdSpaceEndChanges: more overlapping pairs than pairCount (%d); the space now keeps up to %d "
              "(reported once per space: raise pairCount in McdSpaceAxisSortCreate to avoid growing)",
              limit, pairs_.Limit());
    warnedGrowth_ = true;
  }
}

}  // namespace karma::mcd
