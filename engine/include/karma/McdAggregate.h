/* McdAggregate.h: the aggregate geometry, a group of geometries each placed
 * by a relative transform in the aggregate's frame.
 *
 * Elements are any geometries (aggregates included, nested to any depth)
 * except planes and triangle lists. McdAggregateAddElement keeps the relTM
 * POINTER, not a copy: the matrix must outlive the aggregate (allocate it
 * on the heap or in static storage). Changing the matrix moves the element
 * on the models' next update.
 *
 * A model of an aggregate gets one child geometry instance per element
 * (recursively), taken from the framework's instance pool (McdInit's
 * instanceCount). Each child's world TM is relTM composed with its parent
 * instance's TM ("apply relTM, then the parent's"). The elements must all be
 * added before the first model uses the aggregate, or the aggregate is put
 * inside another aggregate: once referenced it is closed (adding warns).
 *
 * Mass properties: the elements' masses add; the centre of mass is their
 * mass-weighted mean; the inertia is each element's, rotated into the
 * aggregate frame and moved to the common centre by the parallel-axis
 * theorem. Overlapping elements count twice. */
#ifndef KARMA_MCDAGGREGATE_H
#define KARMA_MCDAGGREGATE_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdAggregateID;

/* An empty aggregate with room for maxChildren (> 0) elements, or NULL. */
MEPUBLIC McdAggregateID MEAPI McdAggregateCreate(McdFrameworkID framework, int maxChildren);
/* Adds geom at relTM (kept by pointer). Returns the element's index, or -1
 * with a warning (full, NULL, a plane or triangle list, the aggregate itself
 * or one containing it, a closed aggregate, a relTM that is not a finite
 * rigid transform). */
MEPUBLIC int MEAPI McdAggregateAddElement(McdAggregateID agg, McdGeometryID geom, MeMatrix4Ptr relTM);
MEPUBLIC int MEAPI McdAggregateGetElementCount(McdAggregateID agg);
MEPUBLIC int MEAPI McdAggregateGetElementMaxCount(McdAggregateID agg);
MEPUBLIC McdGeometryID MEAPI McdAggregateGetElementGeometry(McdAggregateID agg, int element);
MEPUBLIC MeMatrix4Ptr MEAPI McdAggregateGetElementTransformPtr(McdAggregateID agg, int element);

ME_EXTERN_C_END
#endif /* KARMA_MCDAGGREGATE_H */
