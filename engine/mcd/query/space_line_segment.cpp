// space_line_segment.cpp: line segment queries over every model of a
// space: the first hit, all hits (one per model, nearest first), and the
// first hit among the models a filter accepts.
//
// These are state queries: valid only outside a change block (the guide's
// validity table); inside one they warn and report nothing. Models are
// tested with their transforms as of the space's last update. Ties in
// distance keep the space's model order, so results are deterministic.
#include <algorithm>
#include <vector>

#include "MeMessage.h"
#include "McdSpace.h"
#include "query_internal.h"

namespace {

using karma::mcd::query::SegmentModel;
using karma::mcd::query::ValidSegmentArgs;

// Every hit in the space accepted by the filter (NULL: all), nearest first.
bool Collect(McdSpaceID space, MeVector3Ptr a, MeVector3Ptr b, McdLineSegIntersectEnableCallback filter,
             void *filterData, const void *out, const char *fn, std::vector<McdLineSegIntersectResult> &hits) {
  if (!space) {
    MeWarning(0, "%s: space is NULL", fn);
    return false;
  }
  if (!ValidSegmentArgs(space, a, b, out, fn)) return false;
  if (McdSpaceIsChanging(space)) {
    MeWarning(0, "%s: not allowed inside a change block (call McdSpaceEndChanges first)", fn);
    return false;
  }
  McdSpaceModelIterator it;
  McdSpaceModelIteratorBegin(space, &it);
  McdModelID model = nullptr;
  while (McdSpaceGetModel(space, &it, &model)) {
    if (filter && !filter(model, filterData)) continue;
    McdLineSegIntersectResult r;
    if (SegmentModel(model, a, b, &r)) hits.push_back(r);
  }
  std::stable_sort(
      hits.begin(), hits.end(),
      [](const McdLineSegIntersectResult &x, const McdLineSegIntersectResult &y) { return x.distance < y.distance; });
  return true;
}

}  // namespace

int MEAPI McdSpaceGetLineSegFirstIntersection(McdSpaceID space, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                              McdLineSegIntersectResult *outResult) {
  return McdSpaceGetLineSegFirstEnabledIntersection(space, inOrig, inDest, nullptr, nullptr, outResult);
}

int MEAPI McdSpaceGetLineSegFirstEnabledIntersection(McdSpaceID space, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                                     McdLineSegIntersectEnableCallback filterCB, void *filterData,
                                                     McdLineSegIntersectResult *outResult) {
  std::vector<McdLineSegIntersectResult> hits;
  const char *fn = filterCB ? "McdSpaceGetLineSegFirstEnabledIntersection" : "McdSpaceGetLineSegFirstIntersection";
  if (!Collect(space, inOrig, inDest, filterCB, filterData, outResult, fn, hits) || hits.empty()) return 0;
  *outResult = hits.front();
  return 1;
}

int MEAPI McdSpaceGetLineSegIntersections(McdSpaceID space, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                          McdLineSegIntersectResult *outList, int inMaxListSize) {
  static const char *fn = "McdSpaceGetLineSegIntersections";
  if (inMaxListSize < 0) {
    MeWarning(0, "%s: inMaxListSize is negative (%d)", fn, inMaxListSize);
    return 0;
  }
  std::vector<McdLineSegIntersectResult> hits;
  if (!Collect(space, inOrig, inDest, nullptr, nullptr, outList, fn, hits)) return 0;
  const int n = std::min((int)hits.size(), inMaxListSize);
  std::copy(hits.begin(), hits.begin() + n, outList);
  return n;
}
