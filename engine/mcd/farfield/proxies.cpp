// proxies.cpp: inserting, removing, updating and freezing proxies.
//
// Proxy states: Free -> Pending (inserted this block, not yet in the sorted
// arrays) -> Live (in the arrays) -> Removed (endpoints still in the arrays
// until the next Synchronize) -> Retired (out of the arrays; its pairs get
// their goodbyes at EndChanges) -> Free at the next BeginChanges. A Pending
// proxy removed in its own block goes straight to Retired.
// Invariant: proxyCount_ == number of Pending + Live proxies <= objectCount_.
#include "axis_sort_space.h"

#include "MeMessage.h"

#include <cmath>

namespace karma::mcd {

namespace {
// A usable AABB: no NaN, min <= max on every axis (infinities are fine: a
// plane's box is infinite).
bool ValidAabb(const MeReal min[3], const MeReal max[3]) {
  for (int k = 0; k < 3; ++k) {
    if (std::isnan(min[k]) || std::isnan(max[k]) || !(min[k] <= max[k])) return false;
  }
  return true;
}
}  // namespace

ProxyId AxisSortSpace::InsertImpl(void *user, const MeReal min[3], const MeReal max[3], const char *api) {
  if (!RequireInside(api)) return kNoProxy;
  if (!min || !max || !ValidAabb(min, max)) {
    MeWarning(0, "%s: the AABB is missing, NaN or has min > max; model not inserted", api);
    return kNoProxy;
  }
  if (proxyCount_ >= objectCount_) {
    MeWarning(0, "%s: the space is full (objectCount %d); model not inserted", api, objectCount_);
    return kNoProxy;
  }
  if (freeSlots_.empty()) {
    MeWarning(0,
              "%s: more than objectCount (%d) models removed and inserted in one change block; "
              "model not inserted",
              api, objectCount_);
    return kNoProxy;
  }
  const int slot = freeSlots_.back();
  freeSlots_.pop_back();
  Proxy &p = proxies_[static_cast<std::size_t>(slot)];
  p = Proxy{};
  p.user = user;
  for (int k = 0; k < 3; ++k) {
    p.min[k] = min[k];
    p.max[k] = max[k];
  }
  p.serial = nextSerial_++;
  p.state = ProxyState::Pending;
  pending_.push_back(slot);
  NoteUnfrozen(slot);
  ++proxyCount_;
  return slot;
}

ProxyId AxisSortSpace::Insert(void *user, const MeReal min[3], const MeReal max[3]) {
  return InsertImpl(user, min, max, "McdSpaceInsertModel");
}

ProxyId AxisSortSpace::InsertWithCulling(void *user, const MeReal min[3], const MeReal max[3], CullingTable *table,
                                         int cullingIndex, int cullingId) {
  const char *api = "McdSpaceInsertModelWithCulling";
  if (!RequireInside(api)) return kNoProxy;
  if (table && (cullingIndex < 0 || cullingIndex >= table->size)) {
    MeWarning(0, "%s: culling index %d outside the table of size %d; model not inserted", api, cullingIndex,
              table->size);
    return kNoProxy;
  }
  const ProxyId id = InsertImpl(user, min, max, api);
  if (id == kNoProxy) return id;
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  p.table = table;
  p.cullingIndex = cullingIndex;
  p.cullingId = cullingId;
  return id;
}

bool AxisSortSpace::SetCulling(ProxyId id, CullingTable *table, int cullingIndex, int cullingId) {
  const char *api = "McdSpaceSetModelCullingParameters";
  if (!RequireInside(api) || !CheckProxy(id, api)) return false;
  if (table && (cullingIndex < 0 || cullingIndex >= table->size)) {
    MeWarning(0, "%s: culling index %d outside the table of size %d; parameters unchanged", api, cullingIndex,
              table->size);
    return false;
  }
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  NoteTouchedProxy(id);
  p.table = table;  // NULL clears the parameters
  p.cullingIndex = cullingIndex;
  p.cullingId = cullingId;
  return true;
}

bool AxisSortSpace::Remove(ProxyId id) {
  const char *api = "McdSpaceRemoveModel";
  if (!RequireInside(api) || !CheckProxy(id, api)) return false;
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  DropUnfrozen(id);
  NoteTouchedProxy(id);
  if (p.state == ProxyState::Pending) {
    p.state = ProxyState::Retired;  // never reached the arrays: no pairs
    retired_.push_back(id);
  } else {
    p.state = ProxyState::Removed;
    anyRemoved_ = true;
  }
  --proxyCount_;
  // Forget the proxy's disabled pairs (the slot will name another proxy).
  if (p.disabledCount > 0) {
    for (auto it = disabled_.begin(); it != disabled_.end();) {
      const int lo = static_cast<int>(*it >> 32), hi = static_cast<int>(*it & 0xffffffffu);
      if (lo == id || hi == id) {
        --proxies_[static_cast<std::size_t>(lo == id ? hi : lo)].disabledCount;
        it = disabled_.erase(it);
      } else {
        ++it;
      }
    }
    p.disabledCount = 0;
  }
  return true;
}

bool AxisSortSpace::SetAabb(ProxyId id, const MeReal min[3], const MeReal max[3], const char *api) {
  if (!min || !max || !ValidAabb(min, max)) {
    MeWarning(0, "%s: the AABB of model %d is NaN or has min > max; left unchanged", api, id);
    return false;
  }
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  for (int k = 0; k < 3; ++k) {
    p.min[k] = min[k];
    p.max[k] = max[k];
  }
  if (p.state == ProxyState::Live) {
    for (int k = 0; k < axisCount_; ++k) {
      axis_[k].SetInterval(id, min[axisIndex_[k]], max[axisIndex_[k]]);
    }
    NoteMoved(id);
    dirty_ = true;
  }
  return true;
}

bool AxisSortSpace::Update(ProxyId id, const MeReal min[3], const MeReal max[3]) {
  const char *api = "McdSpaceUpdateModel";
  if (!RequireInside(api) || !CheckProxy(id, api)) return false;
  if (proxies_[static_cast<std::size_t>(id)].frozen) {
    MeWarning(0, "%s: model %d is frozen (unfreeze it before updating); ignored", api, id);
    return false;
  }
  return SetAabb(id, min, max, api);
}

void AxisSortSpace::UpdateAll() {
  const char *api = "McdSpaceUpdateAll";
  if (!RequireInside(api)) return;
  if (aabbFn_) {
    ForEachUnfrozen([this, api](int id, void *user) {
      MeReal min[3], max[3];
      aabbFn_(user, aabbFnData_, min, max);
      SetAabb(id, min, max, api);
    });
  }
  Synchronize();
}

bool AxisSortSpace::Freeze(ProxyId id) {
  if (!CheckProxy(id, "McdSpaceFreezeModel")) return false;
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  if (!p.frozen) {
    p.frozen = true;
    DropUnfrozen(id);
    NoteTouchedProxy(id);
    NoteFrozenChange(id);
  }
  return true;
}

bool AxisSortSpace::Unfreeze(ProxyId id) {
  if (!CheckProxy(id, "McdSpaceUnfreezeModel")) return false;
  Proxy &p = proxies_[static_cast<std::size_t>(id)];
  if (p.frozen) {
    p.frozen = false;
    NoteUnfrozen(id);
    NoteTouchedProxy(id);
    NoteFrozenChange(id);
  }
  return true;
}

}  // namespace karma::mcd
