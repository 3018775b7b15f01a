// space_internal.h: the McdSpace wrapper around the farfield core
// (farfield/axis_sort_space.h). Not installed.
//
// Invariants
//  - A model in a space has model->space == the space and
//    model->spaceIndex == its ProxyId; the proxy's user pointer is the model
//    and its key the model's EffectiveSortKey.
//  - pairs[i] is the McdModelPair of the core's PairRecord with index i
//    (as many as the core has records, min(pairCount, 4096) at first, more
//    as pairs appear and the records grow: they
//    are added at the back and never move): one McdModelPair per record, so
//    its identity and address run from hello to goodbye. EndChanges (re)initialises the pair of every
//    hello record: model1 = the record's proxyA (the lower sort key, or the
//    earlier insertion between equal keys: "Pair order" in
//    farfield/axis_sort_space.h), userData and
//    responseData NULL, m_spaceData = the space, m_spaceIndex = i.
//  - McdSpaceGetPairs fills a container through `chunk` (record pointers)
//    and maps each record to pairs[record->index].
#pragma once

#include "McdSpace.h"
#include "axis_sort_space.h"
#include "mcd_internal.h"

#include <deque>
#include <vector>

struct McdSpace {
  karma::mcd::AxisSortSpace *core;
  McdFramework *framework;
  std::deque<McdModelPair> pairs;  // one per core pair record, grown with them
  int pairCount;                   // as created (the pair limit before the space warns)
  McdSpaceAABBFnPtr aabbFn;
  std::vector<const karma::mcd::PairRecord *> chunk;
};

namespace karma::mcd {

// The space of a model that is in one, else a warning naming fn and NULL.
McdSpace *SpaceOf(McdModelID model, const char *fn);
// The model's AABB as the space sees it (the AABB function or the cache).
void SpaceAabb(const McdSpace *space, McdModelID model, MeReal min[3], MeReal max[3]);
// The core's AABB callback (user = the model, data = the space):
// McdModelUpdate, then SpaceAabb.
void UpdateAndReadAabb(void *user, void *data, MeReal min[3], MeReal max[3]);
// Initialises the McdModelPairs of the hellos of the last EndChanges.
void InitHelloPairs(McdSpace *space);
// McdSpaceGetPairs less the stayings of two frozen models
// (AxisSortSpace::GetActivePairs): the same chunks, iterator and return
// value, for a caller whose work on such a pair is nothing (the bridge).
int GetActivePairs(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *pairs);

}  // namespace karma::mcd
