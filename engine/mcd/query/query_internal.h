// query_internal.h: the per-model line segment test shared by
// McdLineSegIntersect and the space-wide queries.
#pragma once

#include "McdLineSegment.h"

namespace karma::mcd::query {

// The segment a -> b against one (updated) model; fills *out on a hit.
bool SegmentModel(McdModelID model, const MeVector3 a, const MeVector3 b, McdLineSegIntersectResult *out);

// Checks a query's arguments; warns (naming fn) and returns false on NULL
// or non-finite end points.
bool ValidSegmentArgs(const void *model, const MeReal *a, const MeReal *b, const void *out, const char *fn);

}  // namespace karma::mcd::query
