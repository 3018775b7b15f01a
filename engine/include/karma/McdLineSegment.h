/* McdLineSegment.h: where a directed line segment first enters a model.
 *
 * A query walks from inOrig to inDest and reports, per model, the point
 * where the segment first enters the model's solid: its position, the
 * model's outward unit normal there, and the distance from inOrig. Rules
 * (the guide's notes on line segment queries):
 *  - a segment that starts inside a model reports distance 0, position
 *    inOrig and a zero normal (the normal is undefined there);
 *  - at most one hit per model, where the segment first enters it; leaving
 *    or re-entering is not reported; an aggregate reports its earliest
 *    child hit only;
 *  - triangle lists are ignored (no hit, no occlusion);
 *  - the plane is solid below it (its local z <= 0);
 *  - a convex mesh is tested as its sharp hull (fatness is not included).
 * The model's transforms must be current (McdModelUpdate, or its space). */
#ifndef KARMA_MCDLINESEGMENT_H
#define KARMA_MCDLINESEGMENT_H
#include "MeCall.h"
#include "MePrecision.h"
#include "MeMath.h"
#include "McdModel.h"
#include "McdSpace.h"

ME_EXTERN_C_BEGIN

typedef struct McdLineSegIntersectResult {
  McdModelID model;   /* the model hit */
  MeReal position[3]; /* entry point, world frame */
  MeReal normal[3];   /* outward unit normal at the entry point (zero when inside) */
  MeReal distance;    /* from inOrig to position */
} McdLineSegIntersectResult;

/* Filter of McdSpaceGetLineSegFirstEnabledIntersection: the query tests
 * the models for which it returns non-zero. */
typedef int(MEAPI *McdLineSegIntersectEnableCallback)(McdModelID model, void *filterData);

/* Intersects the segment with one model: 1 and *outOverlap filled when
 * the segment enters (or starts in) the model, else 0. NULL or non-finite
 * arguments: a warning and 0. */
MEPUBLIC unsigned int MEAPI McdLineSegIntersect(const McdModelID cm, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                                McdLineSegIntersectResult *outOverlap);

/* Space-wide queries (valid only outside a change block: inside one they
 * warn and report nothing). The first hit over every model of the space; */
MEPUBLIC int MEAPI McdSpaceGetLineSegFirstIntersection(McdSpaceID space, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                                       McdLineSegIntersectResult *outResult);
/* every hit, one per model, nearest first, at most inMaxListSize; returns
 * how many were written; */
MEPUBLIC int MEAPI McdSpaceGetLineSegIntersections(McdSpaceID space, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                                   McdLineSegIntersectResult *outList, int inMaxListSize);
/* the first hit among the models for which filterCB returns non-zero. */
MEPUBLIC int MEAPI McdSpaceGetLineSegFirstEnabledIntersection(McdSpaceID space, MeVector3Ptr inOrig,
                                                              MeVector3Ptr inDest,
                                                              McdLineSegIntersectEnableCallback filterCB,
                                                              void *filterData, McdLineSegIntersectResult *outResult);

ME_EXTERN_C_END
#endif
