// pair_filter.cpp: pairs that overlap but are not reported because the user
// disabled them (DisablePair) or their culling parameters say so.
//
// disabled_ holds SlotPairKeys; Proxy::disabledCount counts the keys naming
// each proxy, so the common case (no disabled pairs) costs no hash lookup.
// Both filters are read when events are computed (EndChanges): disabling a
// reported pair gives it a goodbye there, enabling an overlapping pair a
// hello (with a new record).
#include "axis_sort_space.h"

#include "MeMessage.h"

namespace karma::mcd {

bool AxisSortSpace::Culled(const Proxy &a, const Proxy &b) const {
  return a.table && a.table == b.table && a.cullingId == b.cullingId &&
         CullingTableGet(a.table, static_cast<std::uint32_t>(a.cullingIndex),
                         static_cast<std::uint32_t>(b.cullingIndex));
}

bool AxisSortSpace::DisablePair(ProxyId a, ProxyId b) {
  const char *api = "McdSpaceDisablePair";
  if (!RequireInside(api) || !CheckProxy(a, api) || !CheckProxy(b, api)) return false;
  if (a == b) {
    MeWarning(0, "%s: both models are %d; ignored", api, a);
    return false;
  }
  if (disabled_.insert(SlotPairKey(a, b)).second) {
    NoteTouched(SlotPairKey(a, b));
    ++proxies_[static_cast<std::size_t>(a)].disabledCount;
    ++proxies_[static_cast<std::size_t>(b)].disabledCount;
  }
  return true;
}

bool AxisSortSpace::EnablePair(ProxyId a, ProxyId b) {
  const char *api = "McdSpaceEnablePair";
  if (!RequireInside(api) || !CheckProxy(a, api) || !CheckProxy(b, api)) return false;
  if (a == b) {
    MeWarning(0, "%s: both models are %d; ignored", api, a);
    return false;
  }
  if (disabled_.erase(SlotPairKey(a, b)) > 0) {
    NoteTouched(SlotPairKey(a, b));
    --proxies_[static_cast<std::size_t>(a)].disabledCount;
    --proxies_[static_cast<std::size_t>(b)].disabledCount;
  }
  return true;
}

bool AxisSortSpace::PairIsEnabled(ProxyId a, ProxyId b) const {
  const char *api = "McdSpacePairIsEnabled";
  if (!CheckProxy(a, api) || !CheckProxy(b, api)) return false;
  const Proxy &pa = proxies_[static_cast<std::size_t>(a)];
  const Proxy &pb = proxies_[static_cast<std::size_t>(b)];
  if (pa.disabledCount > 0 && pb.disabledCount > 0 && disabled_.count(SlotPairKey(a, b)) > 0) return false;
  return !Culled(pa, pb);
}

bool AxisSortSpace::Reportable(const OverlapEntry &e) const {
  if (!e.overlapping) return false;
  const int a = e.SlotLo(), b = e.SlotHi();
  const Proxy &pa = proxies_[static_cast<std::size_t>(a)];
  const Proxy &pb = proxies_[static_cast<std::size_t>(b)];
  if (pa.state != ProxyState::Live || pb.state != ProxyState::Live) return false;
  if (pa.frozen && pb.frozen && !(keepFrozenPairs_ && e.record >= 0)) return false;
  if (pa.disabledCount > 0 && pb.disabledCount > 0 && disabled_.count(e.key) > 0) return false;
  return !Culled(pa, pb);
}

}  // namespace karma::mcd
