// axis_sort_space.cpp: creation, destruction and the read-only queries of
// the axis-sort space (see axis_sort_space.h for the contract).
#include "axis_sort_space.h"

#include "MeMemory.h"
#include "MeMessage.h"

#include <algorithm>
#include <new>

namespace karma::mcd {

AxisSortSpace *AxisSortSpace::Create(int axes, int objectCount, int pairCount) {
  if (objectCount < 1 || pairCount < 1) {
    MeWarning(0,
              "McdSpaceAxisSortCreate: objectCount (%d) and pairCount (%d) must be at least 1; "
              "no space created",
              objectCount, pairCount);
    return nullptr;
  }
  // Slots are 31-bit in the endpoint data word and doubled for removals.
  if (objectCount > (1 << 28)) {
    MeWarning(0, "McdSpaceAxisSortCreate: objectCount %d is too large; no space created", objectCount);
    return nullptr;
  }
  void *mem = MeMemoryAPI.create(sizeof(AxisSortSpace));
  if (!mem) return nullptr;
  auto *space = new (mem) AxisSortSpace();
  try {
    if (space->Init(axes, objectCount, pairCount)) return space;
  } catch (const std::bad_alloc &) {
    MeWarning(0, "McdSpaceAxisSortCreate: out of memory for objectCount %d; no space created", objectCount);
  }
  Destroy(space);
  return nullptr;
}

void AxisSortSpace::Destroy(AxisSortSpace *space) {
  if (!space) return;
  space->~AxisSortSpace();
  MeMemoryAPI.destroy(space);
}

bool AxisSortSpace::Init(int axes, int objectCount, int pairCount) {
  if ((axes & ~kAllAxes) != 0 || (axes & kAllAxes) == 0) {
    const int fixed = (axes & kAllAxes) != 0 ? (axes & kAllAxes) : kAllAxes;
    MeWarning(0,
              "McdSpaceAxisSortCreate: axes 0x%x is not a non-empty combination of McdXAxis (1), "
              "McdYAxis (2), McdZAxis (4); using 0x%x",
              static_cast<unsigned>(axes), static_cast<unsigned>(fixed));
    axes = fixed;
  }
  axes_ = axes;
  axisCount_ = 0;
  for (int k = 0; k < 3; ++k) {
    if (axes & (1 << k)) axisIndex_[axisCount_++] = k;
  }
  objectCount_ = objectCount;
  // A proxy removed in a change block keeps its slot until the next
  // BeginChanges (its goodbyes still name it), so twice the slots let a full
  // space remove and insert within one block.
  const int slots = 2 * objectCount;
  proxies_.assign(static_cast<std::size_t>(slots), Proxy{});
  freeSlots_.clear();
  for (int s = slots - 1; s >= 0; --s) freeSlots_.push_back(s);
  for (int k = 0; k < axisCount_; ++k) axis_[k].Reserve(slots);
  gone_.assign(static_cast<std::size_t>(slots), 0);
  isNew_.assign(static_cast<std::size_t>(slots), 0);
  activePos_.assign(static_cast<std::size_t>(slots), -1);
  activeNewPos_.assign(static_cast<std::size_t>(slots), -1);
  unfrozenPos_.assign(static_cast<std::size_t>(slots), -1);
  movedFlag_.assign(static_cast<std::size_t>(slots), 0);
  // Pair storage is sized for the first pairs only and grows with them.
  const int firstPairs = std::min(pairCount, PairPool::kFirstRecords);
  overlaps_.Reserve(firstPairs);
  overlaps_.ReserveSlots(slots);
  pairs_.Create(pairCount);
  goodbyes_.reserve(static_cast<std::size_t>(firstPairs));
  hellos_.reserve(static_cast<std::size_t>(firstPairs));
  stayings_.reserve(static_cast<std::size_t>(firstPairs));
  previous_.reserve(static_cast<std::size_t>(firstPairs));
  changing_ = true;  // McdSpaceAxisSortCreate begins a change block
  return true;
}

bool AxisSortSpace::IsProxy(ProxyId id) const {
  if (id < 0 || id >= static_cast<int>(proxies_.size())) return false;
  const ProxyState s = proxies_[static_cast<std::size_t>(id)].state;
  return s == ProxyState::Pending || s == ProxyState::Live;
}

bool AxisSortSpace::CheckProxy(ProxyId id, const char *api) const {
  if (IsProxy(id)) return true;
  MeWarning(0, "%s: %d is not a model in this space; ignored", api, id);
  return false;
}

ProxyId AxisSortSpace::NextProxy(ProxyId after) const {
  const int n = static_cast<int>(proxies_.size());
  for (int id = after < 0 ? 0 : after + 1; id < n; ++id) {
    if (IsProxy(id)) return id;
  }
  return kNoProxy;
}

void *AxisSortSpace::ProxyUser(ProxyId id) const {
  return IsProxy(id) ? proxies_[static_cast<std::size_t>(id)].user : nullptr;
}

std::uint32_t AxisSortSpace::ProxySerial(ProxyId id) const {
  return IsProxy(id) ? proxies_[static_cast<std::size_t>(id)].serial : 0;
}

ProxyRank AxisSortSpace::Rank(ProxyId id) const {
  if (!IsProxy(id)) return {};
  const Proxy &p = proxies_[static_cast<std::size_t>(id)];
  return {p.key, p.serial};
}

bool AxisSortSpace::SetKey(ProxyId id, std::uint32_t key) {
  if (!CheckProxy(id, "McdModelSetSortKey")) return false;
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  if (p.key != key) {
    p.key = key;
    keysChanged_ = true;
  }
  return true;
}

std::uint32_t AxisSortSpace::Key(ProxyId id) const {
  return IsProxy(id) ? proxies_[static_cast<std::size_t>(id)].key : 0;
}

bool AxisSortSpace::GetAabb(ProxyId id, MeReal min[3], MeReal max[3]) const {
  if (!CheckProxy(id, "McdModelGetAABB")) return false;
  const Proxy &p = proxies_[static_cast<std::size_t>(id)];
  for (int k = 0; k < 3; ++k) {
    min[k] = p.min[k];
    max[k] = p.max[k];
  }
  return true;
}

bool AxisSortSpace::IsFrozen(ProxyId id) const {
  if (!CheckProxy(id, "McdSpaceModelIsFrozen")) return false;
  return proxies_[static_cast<std::size_t>(id)].frozen;
}

void AxisSortSpace::SetAabbFn(AabbFn fn, void *data) {
  if (!RequireOutside("McdSpaceSetAABBFn")) return;
  aabbFn_ = fn;
  aabbFnData_ = data;
}

void AxisSortSpace::Build() { Synchronize(); }

SpaceStats AxisSortSpace::Stats() const {
  SpaceStats s;
  s.overlaps = overlaps_.Size();
  s.reported = static_cast<int>(hellos_.size() + stayings_.size());
  s.recordsInUse = pairs_.InUse();
  s.swaps = swaps_;
  s.pairRecords = pairs_.Capacity();
  return s;
}

}  // namespace karma::mcd
