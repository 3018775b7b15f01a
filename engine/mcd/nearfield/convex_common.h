// convex_common.h: what the convex, aggregate and triangle list families
// share: the general convex test and dispatching a pair of (sub)models
// through the interaction table.
#pragma once

#include "nearfield.h"
#include "convex/shape.h"

namespace karma::mcd {

// A (model1) against B (model2) through libccd and the manifold builder;
// fills r (Emit) and returns touch.
int ConvexIntersect(const convex::Shape &a, const convex::Shape &b, double tol, McdIntersectResult *r);

// Runs the table's interaction for the pair as it stands (model1, model2),
// turning a mirrored entry round like McdIntersect does. The result's
// contacts, contactMaxCount must be set; returns touch (0 when no entry).
int DispatchPair(McdModelPair *pair, McdIntersectResult *r);

}  // namespace karma::mcd
