// change_block.cpp: the two modes of a space and the transitions between
// them (the guide's validity tables are enforced by RequireInside /
// RequireOutside at the top of each operation).
//
//   outside --BeginChanges--> inside: last events' goodbyes retired (their
//                                     records return to the pool), removed
//                                     proxies' slots freed
//   inside --EndChanges--> outside:   arrays synchronised, new events computed
//                                     (generation + 1; iterators restart)
#include "axis_sort_space.h"

#include "MeMessage.h"

namespace karma::mcd {

bool AxisSortSpace::RequireInside(const char *api) const {
  if (changing_) return true;
  MeWarning(0, "%s: only valid inside a change block (call McdSpaceBeginChanges first); ignored", api);
  return false;
}

bool AxisSortSpace::RequireOutside(const char *api) const {
  if (!changing_) return true;
  MeWarning(0, "%s: only valid outside a change block (call McdSpaceEndChanges first); ignored", api);
  return false;
}

void AxisSortSpace::BeginChanges() {
  if (!RequireOutside("McdSpaceBeginChanges")) return;
  RetireGoodbyes();
  for (int s : retired_) {
    proxies_[static_cast<std::size_t>(s)] = Proxy{};
    freeSlots_.push_back(s);
  }
  retired_.clear();
  changing_ = true;
}

void AxisSortSpace::EndChanges() {
  if (!RequireInside("McdSpaceEndChanges")) return;
  Synchronize();
  ComputeEvents();
  ++generation_;
  changing_ = false;
}

}  // namespace karma::mcd
