// axis_sort_space.h: the axis-sort farfield of Karma Collision, as an
// internal C++ core over "proxies" (an AABB plus a user pointer). The public
// McdSpace* C functions are thin wrappers over this class; the core knows
// nothing of McdModel, McdModelPair or the framework.
//
// ## What it computes
// Each proxy has an AABB. On the sorted axes (any non-empty subset of x, y,
// z) two proxies overlap when their closed intervals overlap on every sorted
// axis: a.min <= b.max && b.min <= a.max (touching counts). The space keeps
// the set of overlapping pairs exact by an incremental sort-and-sweep: one
// endpoint array per sorted axis, re-sorted from last frame's order by
// insertion sort (temporal coherence), every adjacent min/max swap telling
// that one pair starts or stops overlapping on that axis. A pair's count of
// overlapping axes is read off the other axes' endpoint ranks at the swap
// (endpoint_axis.h), and the pair exists exactly when that count equals the
// number of sorted axes. Nothing O(n^2) is stored.
//
// A pair is *reported* when it overlaps, its two proxies are not both frozen,
// it is not disabled (DisablePair) and not culled (culling_table.h).
// SetKeepFrozenPairs(true) softens the frozen rule: a reported pair whose
// two proxies become frozen stays (staying, same record) instead of saying
// goodbye; two frozen proxies still never start a pair. The guide hints at
// this (the bridge skips the nearfield for frozen-frozen pairs and keeps
// their contacts, so a sleeping stack keeps the contact groups that wake it
// as a whole); the default is the guide's plain "not reported".
//
// ## Change blocks and pair events
// The space is either inside a change block (IsChanging) or outside.
// Modifications (insert, remove, update, update-all, enable/disable pair,
// culling parameters, EndChanges) are valid only inside; pair retrieval,
// SetAabbFn and BeginChanges only outside; freeze/unfreeze and every query
// anywhere. A call in the wrong mode warns (MeWarning naming the McdSpace
// function) and does nothing. A new space starts inside a change block.
//
// EndChanges brings the arrays up to date and compares the reported set
// with the one of the previous EndChanges:
//   hello    reported now, not before (a new PairRecord)
//   staying  reported now and before (the same PairRecord)
//   goodbye  reported before, not now: overlap ended, a proxy was removed,
//            the pair was disabled or culled, or both proxies are now frozen
// BeginChanges retires the goodbyes: their records go back to the pool and
// only then can serve a new pair. So a PairRecord has one identity from its
// hello to its goodbye, and every hello gets exactly one goodbye (removing a
// proxy produces the goodbyes of its pairs; destroying the space does not).
// An overlap that starts and ends within one change block is never seen.
//
// ## Pair order (sort keys)
// Each proxy has a sort key (SetKey; the McdModel's sort key, default 0) and
// an insertion serial. Its rank is the pair (key, serial), compared
// lexicographically. Within a pair, proxyA is the one of lower rank (the
// McdModelPair's model1). Each event list (goodbyes, hellos, stayings)
// ascends by PairRecord::Order() = (rank of A, rank of B). So:
//  - where the keys of the models differ, the order of the pairs and of the
//    two models in a pair follow the keys alone: they depend neither on
//    creation or insertion order nor on addresses;
//  - serials decide only between equal keys (then the earlier insertion
//    ranks first), so a space whose keys are all equal (all 0 by default)
//    orders by insertion as it always did;
//  - two identical runs report identical sequences.
// A key change (SetKey) takes effect at the next EndChanges: the reported
// pairs are re-ranked and the lists re-sorted; a reported pair whose two
// proxies swap ranks says goodbye and hello again (a new record with the new
// proxyA), because a pair's model order is fixed for the life of its record.
//
// ## Capacity
// At most objectCount proxies at a time (a removed proxy's slot is reused
// after the next BeginChanges). pairCount is a hint, not a cap: pair
// records are made as pairs need them (PairPool in pair_table.h), and when
// more than pairCount pairs are reported at once the pool grows and
// McdSpaceEndChanges warns once per space. Overlaps, reported or not
// (frozen-frozen, disabled, culled), are tracked in a hash that grows as
// needed. Memory running out inside EndChanges is not recovered from (the
// std::bad_alloc propagates and leaves the space unusable). Insertion
// serials are 32-bit: the order is defined for a space's first 2^32 - 1
// insertions.
//
// UpdateAll is treated like McdSpaceUpdateModels (inside a block only): the
// guide's loop calls McdSpaceUpdateAll between the bridge's BeginChanges and
// its next EndChanges. It calls the AABB function on every unfrozen proxy
// and re-sorts at once; EndChanges sorts whatever changed after it.
//
// ## Cost follows what moves (issue 17)
// A frame touches what is unfrozen or has changed, not every proxy or pair:
//  - unfrozen_ lists the Pending and Live proxies that are not frozen
//    (unfrozenPos_[slot] is the index, -1 for the others); UpdateAll and
//    ForEachUnfrozen walk it in ascending slot order, as a walk over every
//    slot skipping the frozen ones would.
//  - moved_ lists the Live proxies whose interval was set since the last
//    sort (movedFlag_ marks them); the sort visits only the endpoints near
//    them (EndpointAxis::SortNear), with the same swaps as a full pass.
//  - touched_ holds the keys of the overlap entries that swaps, new proxies
//    and pair filters added, changed or erased since the last EndChanges,
//    and touchedProxies_ the proxies frozen, thawed, removed or given new
//    culling parameters (all their entries, found through the table's
//    per-slot lists). Unless fullWalk_ is set (the first EndChanges), a
//    key changed, SetKeepFrozenPairs changed or a culling table's flags
//    changed (CullingTablesRevision), no other entry can have changed
//    whether it is reportable, and ComputeEvents settles only these.
//  - The stayings are last block's stayings and hellos less the goodbyes:
//    unchanged when nothing said hello or goodbye, else the goodbyes found
//    by their Order() and last block's hellos merged in, without reading
//    the records that stay (departed_ lists the records detached).
//  - GetActivePairs hands out the events like GetPairs, leaving out the
//    stayings of two frozen proxies (activeStayings_: the others, in
//    Order(); kept up to date with the stayings and, through frozenChanged_,
//    with the frozen flags when next used; rebuilt after a key change or
//    many freezes): with the same chunk boundaries while
//    goodbyes or hellos remain, then full chunks of the remaining active
//    stayings. Their
//    McdIntersect would be skipped anyway (the bridge's rule), so a caller
//    that handles each chunk's transitions and then collides its pairs
//    makes the same calls in the same order without paying for the frozen
//    ones.
//
// ## Mapping of the public C API (for the Mcd wrapper)
//   McdSpaceAxisSortCreate(fwk, axes, objectCount, pairCount)
//                                     -> AxisSortSpace::Create(axes, objectCount, pairCount)
//   McdSpaceDestroy                   -> AxisSortSpace::Destroy
//   McdSpaceInsertModel(s, m)         -> Insert(m, m's cached AABB); keep the ProxyId in m
//   McdSpaceInsertModelWithCulling    -> InsertWithCulling(m, aabb, table, index, id)
//   McdSpaceRemoveModel(m)            -> Remove(id)
//   McdSpaceUpdateModel(m)            -> McdModelUpdate + AABB, then Update(id, min, max)
//   McdSpaceUpdateAll / UpdateModels  -> UpdateAll() (calls the AABB function)
//   McdSpaceSetAABBFn(s, fn)          -> SetAabbFn(fn, data)
//   McdSpaceFreezeModel / Unfreeze / ModelIsFrozen -> Freeze / Unfreeze / IsFrozen
//   McdSpaceEnablePair / DisablePair / PairIsEnabled -> EnablePair / DisablePair / PairIsEnabled
//   McdSpaceSetModelCullingParameters -> SetCulling(id, table, index, id)
//   McdSpaceBeginChanges / EndChanges / IsChanging -> same names
//   McdSpaceBuild                     -> Build()
//   McdSpaceGetModelCount             -> ProxyCount()
//   McdSpaceModelIteratorBegin / GetModel -> cursor = kNoProxy; cursor = NextProxy(cursor),
//                                        model = ProxyUser(cursor)
//   McdSpaceSetUserData / GetUserData -> SetUserData / UserData
//   McdSpacePairIteratorBegin         -> PairIteratorBegin(&iter)
//   McdSpaceGetPairs(s, iter, c)      -> GetPairs(&iter, &chunk); chunk mirrors the
//                                        McdModelPairContainer fields; the wrapper keeps
//                                        one McdModelPair per PairRecord::index
//                                        (PairCapacity() of them), sets model1/model2 from userA/userB at
//                                        hello, and writes pairs[record->index] where the
//                                        chunk has the record
//   McdSpaceGetTransitions            -> GetTransitions(&iter, &chunk)
//   line-segment queries              -> RequireOutside(name), then ForEachProxyOverlapping
//   McdCullingTableCreate / Set       -> culling_table.h
#ifndef KARMA_MCD_FARFIELD_AXIS_SORT_SPACE_H
#define KARMA_MCD_FARFIELD_AXIS_SORT_SPACE_H

#include "culling_table.h"
#include "endpoint_axis.h"
#include "pair_table.h"

#include "MePrecision.h"

#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

namespace karma::mcd {

// The guide's McdXAxis, McdYAxis, McdZAxis, McdAllAxes.
inline constexpr int kAxisX = 1, kAxisY = 2, kAxisZ = 4, kAllAxes = 7;

using ProxyId = int;  // a slot index, stable while the proxy is in the space
inline constexpr ProxyId kNoProxy = -1;

// Computes a proxy's world AABB for UpdateAll: `user` is the proxy's user
// pointer, `data` the pointer given to SetAabbFn.
using AabbFn = void (*)(void *user, void *data, MeReal min[3], MeReal max[3]);

// Position in the current events. Valid from PairIteratorBegin until the
// next EndChanges.
struct PairIterator {
  std::uint64_t generation = 0;
  int nextGoodbye = 0, nextHello = 0, nextStaying = 0;
};

// A caller's fixed-size block of pairs, filled in chunks. Layout after a
// fill (the McdModelPairContainer's fields):
//   goodbyes in [goodbyeFirst, goodbyeEnd), hellos in [helloFirst, helloEnd),
//   stayings in [helloEnd, stayingEnd); goodbyeFirst = 0,
//   helloFirst = goodbyeEnd, stayingEnd <= size.
struct PairChunk {
  const PairRecord **array = nullptr;
  int size = 0;
  int goodbyeFirst = 0, goodbyeEnd = 0;
  int helloFirst = 0, helloEnd = 0;  // helloEnd is also stayingFirst
  int stayingEnd = 0;
};

struct SpaceStats {
  int overlaps = 0;      // pairs overlapping on all sorted axes (reported or not)
  int reported = 0;      // hellos + stayings of the current events
  int recordsInUse = 0;  // including goodbyes not yet retired
  long long swaps = 0;   // endpoint swaps that changed an overlap, last sync
  int pairRecords = 0;   // pair records made so far (PairCapacity)
};

class AxisSortSpace {
 public:
  // axes: a non-empty combination of kAxisX/Y/Z (anything else warns and
  // uses what is valid, or all axes). objectCount >= 1, pairCount >= 1.
  // Returns NULL with a warning on bad counts or when memory runs out. The
  // memory taken grows with objectCount, not with pairCount (pair storage
  // grows with the pairs). The space starts inside a change block.
  static AxisSortSpace *Create(int axes, int objectCount, int pairCount);
  // Destroys the space; its records and events go with it.
  static void Destroy(AxisSortSpace *space);

  // --- change blocks (change_block.cpp)
  bool IsChanging() const { return changing_; }
  void BeginChanges();
  void EndChanges();
  // True when the mode fits; otherwise one MeWarning naming `api`.
  bool RequireInside(const char *api) const;
  bool RequireOutside(const char *api) const;

  // --- proxies (proxies.cpp). Inside a change block.
  ProxyId Insert(void *user, const MeReal min[3], const MeReal max[3]);
  ProxyId InsertWithCulling(void *user, const MeReal min[3], const MeReal max[3], CullingTable *table, int cullingIndex,
                            int cullingId);
  bool Remove(ProxyId id);
  bool Update(ProxyId id, const MeReal min[3], const MeReal max[3]);
  void UpdateAll();
  bool SetCulling(ProxyId id, CullingTable *table, int cullingIndex, int cullingId);
  // Anywhere; effective for pairs at the next EndChanges.
  bool Freeze(ProxyId id);
  bool Unfreeze(ProxyId id);
  bool IsFrozen(ProxyId id) const;
  // Anywhere; effective at the next EndChanges (see "Pair order"). Default 0.
  bool SetKey(ProxyId id, std::uint32_t key);
  std::uint32_t Key(ProxyId id) const;
  // Anywhere; effective at the next EndChanges. Default false.
  void SetKeepFrozenPairs(bool keep) { keepFrozenPairs_ = keep; }
  bool KeepFrozenPairs() const { return keepFrozenPairs_; }
  // Outside a change block.
  void SetAabbFn(AabbFn fn, void *data);
  // Anywhere: brings the sorted arrays up to date now (else EndChanges does).
  void Build();

  // --- queries, anywhere
  int ProxyCount() const { return proxyCount_; }
  ProxyId NextProxy(ProxyId after) const;  // ascending slots; kNoProxy at the end
  bool IsProxy(ProxyId id) const;
  void *ProxyUser(ProxyId id) const;
  std::uint32_t ProxySerial(ProxyId id) const;
  ProxyRank Rank(ProxyId id) const;  // {key, serial}
  bool GetAabb(ProxyId id, MeReal min[3], MeReal max[3]) const;
  void SetUserData(void *data) { userData_ = data; }
  void *UserData() const { return userData_; }
  int Axes() const { return axes_; }
  int ObjectCapacity() const { return objectCount_; }
  // The pair records made so far: every PairRecord::index is below it. It
  // starts at min(pairCount, PairPool::kFirstRecords) and grows at EndChanges.
  int PairCapacity() const { return pairs_.Capacity(); }
  SpaceStats Stats() const;
  // Checks every internal invariant (sorted axes, endpoint positions, the
  // overlap table against an O(n^2) pass over the ranks, record ownership
  // and event order). For tests; outside a change block. On failure, one
  // MeWarning says what broke and the result is false.
  bool Validate() const;
  // Calls fn(id, user) for each proxy whose AABB overlaps [min, max] on all
  // three axes (closed intervals), in ascending slot order.
  template <class Fn>
  void ForEachProxyOverlapping(const MeReal min[3], const MeReal max[3], Fn &&fn) const {
    for (ProxyId id = NextProxy(kNoProxy); id != kNoProxy; id = NextProxy(id)) {
      const Proxy &p = proxies_[static_cast<std::size_t>(id)];
      bool hit = true;
      for (int k = 0; k < 3; ++k) hit = hit && p.min[k] <= max[k] && min[k] <= p.max[k];
      if (hit) fn(id, p.user);
    }
  }

  // --- pair filters (pair_filter.cpp)
  bool DisablePair(ProxyId a, ProxyId b);          // inside
  bool EnablePair(ProxyId a, ProxyId b);           // inside
  bool PairIsEnabled(ProxyId a, ProxyId b) const;  // anywhere: not disabled, not culled

  // --- pair events (pair_iterator.cpp). Outside a change block.
  void PairIteratorBegin(PairIterator *iter) const;
  // Fills `chunk` (its array and size set by the caller); returns true when
  // events remain ("overflow: call again with the same iterator").
  bool GetPairs(PairIterator *iter, PairChunk *chunk);
  bool GetTransitions(PairIterator *iter, PairChunk *chunk);  // no stayings
  // GetPairs less the stayings of two frozen proxies (see "Cost").
  bool GetActivePairs(PairIterator *iter, PairChunk *chunk);
  // Calls fn(id, user) for each unfrozen proxy, in ascending slot order.
  template <class Fn>
  void ForEachUnfrozen(Fn &&fn) {
    SortUnfrozen();
    unfrozenWalk_.assign(unfrozen_.begin(), unfrozen_.end());
    for (int id : unfrozenWalk_) fn(id, proxies_[static_cast<std::size_t>(id)].user);
  }
  // The current events, each list in Order() order.
  std::span<PairRecord *const> Goodbyes() const { return goodbyes_; }
  std::span<PairRecord *const> Hellos() const { return hellos_; }
  std::span<PairRecord *const> Stayings() const { return stayings_; }

 private:
  enum class ProxyState : std::uint8_t { Free, Pending, Live, Removed, Retired };
  struct Proxy {
    void *user = nullptr;
    MeReal min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
    std::uint32_t serial = 0;
    std::uint32_t key = 0;  // sort key (see "Pair order")
    ProxyState state = ProxyState::Free;
    bool frozen = false;
    CullingTable *table = nullptr;  // NULL: no culling parameters
    int cullingIndex = 0, cullingId = 0;
    int disabledCount = 0;  // entries of disabled_ naming this proxy
  };

  AxisSortSpace() = default;
  bool Init(int axes, int objectCount, int pairCount);
  bool CheckProxy(ProxyId id, const char *api) const;
  ProxyId InsertImpl(void *user, const MeReal min[3], const MeReal max[3], const char *api);
  bool SetAabb(ProxyId id, const MeReal min[3], const MeReal max[3], const char *api);
  // synchronize.cpp: removals, insertion sort, batch merge of new proxies.
  void Synchronize();
  void OnAxisSwap(int axis, int a, int b, bool begins);
  bool OverlapsOnOtherAxes(int axis, int a, int b) const;
  void SweepNewProxies();
  // pair_events.cpp
  void ComputeEvents();
  bool SettleEntry(OverlapEntry &e);
  void UpdateStayings();
  void RerankReported();
  void StartPair(PairRecord *r, int slotA, int slotB);
  void RetireGoodbyes();
  bool Reportable(const OverlapEntry &e) const;
  bool Culled(const Proxy &a, const Proxy &b) const;
  enum class StayingFilter { None, All, Active };
  bool FillChunk(PairIterator *iter, PairChunk *chunk, StayingFilter stayings, const char *api);
  bool FillActiveStayings(PairIterator *iter, PairChunk *chunk);
  std::vector<PairRecord *>::const_iterator ActiveFrom(int index) const;
  // active sets (see "Cost"; active_sets.cpp)
  void NoteUnfrozen(int slot);
  void DropUnfrozen(int slot);
  void SortUnfrozen();
  void NoteMoved(int slot);
  void NoteTouched(std::uint64_t key) {
    if (!fullWalk_) touched_.push_back(key);
  }
  void NoteTouchedProxy(int slot) {
    if (!fullWalk_) touchedProxies_.push_back(slot);
  }
  void NoteFrozenChange(int slot);
  void SortAxes();
  void BuildActiveStayings();

  int axes_ = kAllAxes;
  int axisCount_ = 0;
  int axisIndex_[3] = {0, 1, 2};  // world axis of each sorted axis
  EndpointAxis axis_[3];
  int objectCount_ = 0;
  int proxyCount_ = 0;  // Pending + Live
  std::uint32_t nextSerial_ = 1;
  std::vector<Proxy> proxies_;  // 2 * objectCount slots (see proxies.cpp)
  std::vector<int> freeSlots_;  // LIFO, lowest first
  std::vector<int> pending_;    // inserted, not yet in the arrays
  std::vector<int> retired_;    // removed; slots free at the next BeginChanges
  bool anyRemoved_ = false;
  bool keysChanged_ = false;  // a SetKey changed a key since the last EndChanges
  bool dirty_ = false;        // values changed since the last sort
  long long swaps_ = 0;

  OverlapTable overlaps_;
  PairPool pairs_;
  std::unordered_set<std::uint64_t> disabled_;  // SlotPairKey of disabled pairs

  std::vector<PairRecord *> goodbyes_, hellos_, stayings_;
  std::uint64_t generation_ = 0;  // bumped by every EndChanges
  bool warnedGrowth_ = false;     // the pair records' growth has been reported

  bool changing_ = true;
  bool keepFrozenPairs_ = false;
  AabbFn aabbFn_ = nullptr;
  void *aabbFnData_ = nullptr;
  void *userData_ = nullptr;

  // Scratch kept between frames to avoid reallocation.
  std::vector<std::uint8_t> gone_, isNew_;
  std::vector<int> active_, activeNew_, activePos_, activeNewPos_;
  std::vector<std::uint64_t> eraseKeys_;
  struct Candidate {
    PairOrder order;
    std::uint64_t slots;  // SlotPairKey
    bool operator<(const Candidate &o) const { return order < o.order; }
  };
  std::vector<Candidate> candidates_;
  std::vector<PairRecord *> previous_;

  // Active sets (see "Cost").
  std::vector<int> unfrozen_, unfrozenPos_, unfrozenWalk_;
  bool unfrozenSorted_ = true;
  std::vector<int> moved_;
  std::vector<std::uint8_t> movedFlag_;
  std::vector<int> movedPositions_;
  std::vector<std::uint64_t> touched_;
  std::vector<int> touchedProxies_;  // proxies whose every entry may have changed
  bool fullWalk_ = true;
  bool lastKeepFrozenPairs_ = false;
  std::uint64_t lastCullingRevision_ = 0;     // CullingTablesRevision() at the last ComputeEvents
  std::vector<PairRecord *> activeStayings_;  // in Order()
  std::vector<int> frozenChanged_;            // proxies frozen or thawed since activeStayings_ was brought up to date
  std::uint64_t stayingsVersion_ = 1, activeStayingsVersion_ = 0;
  struct Departure {
    PairRecord *record;
    bool wasHello;
  };
  std::vector<Departure> departed_;              // records detached by this ComputeEvents
  std::vector<PairRecord *> leaving_, joining_;  // scratch of UpdateStayings
};

}  // namespace karma::mcd

#endif
