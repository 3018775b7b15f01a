/* McdTriangleList.h: the triangle list geometry, for static terrain.
 *
 * A triangle list has no stored shape: it is a bounding box (in its own
 * frame) plus a callback that the nearfield calls whenever another model's
 * AABB overlaps it. The callback fills up to `maxTriangles` McdUserTriangle
 * records with the triangles near the other model and returns how many it
 * wrote; the nearfield then tests the other model against each triangle.
 *
 *   pos, radius   a sphere enclosing the other model, in the triangle
 *                 list's frame: the callback should return the triangles
 *                 that may touch it (every triangle is correct but slow)
 *   vertices      pointers to three vertices, counter-clockwise seen from
 *                 the front (right-hand rule about the normal), in the
 *                 triangle list's frame; the memory must stay valid until
 *                 the intersection test returns
 *   normal        pointer to the unit face normal
 *   flags         McdTriangleFlags, see below
 *   triangleData  free for the user (e.g. a material tag)
 *
 * A callback returning more than triangleMaxCount (or a negative count) is
 * a bug: the nearfield warns and uses the first triangleMaxCount (or none).
 *
 * The struct is public: programs written against the guide set
 * `((McdTriangleList*)g)->triangleMaxCount` directly (the scratch storage
 * follows the new value on the next query). It has no mass properties. */
#ifndef KARMA_MCDTRIANGLELIST_H
#define KARMA_MCDTRIANGLELIST_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

struct McdModelPair;

typedef enum McdTriangleFlags {
  /* Use the normal of least penetration (the direction that separates
     * the object from the triangle with the shortest move); when clear, the
     * triangle's face normal. */
  kMcdTriangleUseSmallestPenetration = 1,
  /* Two-sided triangle. When clear, a contact normal pointing against the
     * face normal is reversed. */
  kMcdTriangleTwoSided = 2,
  /* Sharp edges: contacts are made where the object meets the edge
     * v1-v0 / v2-v1 / v0-v2. Clear them for edges inside a smooth surface. */
  kMcdTriangleUseEdge0 = 4,
  kMcdTriangleUseEdge1 = 8,
  kMcdTriangleUseEdge2 = 16,
  kMcdTriangleUseEdges = 28,
  /* All of the above (Karma 1.0 behaviour). */
  kMcdTriangleStandard = 31
} McdTriangleFlags;

typedef struct McdUserTriangle {
  MeVector3 *vertices[3];
  MeVector3 *normal;
  union {
    void *ptr;
    int tag;
  } triangleData;
  int flags; /* McdTriangleFlags */
} McdUserTriangle;

typedef int(MEAPI *McdTriangleListFnPtr)(struct McdModelPair *modelTriListPair, McdUserTriangle *triangles,
                                         MeVector3 pos, MeReal radius, int maxTriangles);

typedef struct McdTriangleList {
  McdGeometry m_g;  /* private */
  MeVector3 boxMin; /* bounding box, triangle list's frame */
  MeVector3 boxMax;
  int triangleMaxCount; /* most triangles one callback may return */
  void *userData;       /* user geometry representation */
  McdTriangleListFnPtr triangleListGenerator;
  McdUserTriangle *list; /* private scratch of m_listCapacity */
  int m_listCapacity;
} McdTriangleList;
typedef McdGeometryID McdTriangleListID;

/* A triangle list bounded by [min, max] (min <= max componentwise, finite)
 * with room for triangleMaxCount (> 0) triangles per query and the
 * generator f (not NULL); NULL with a warning on bad input. */
MEPUBLIC McdTriangleListID MEAPI McdTriangleListCreate(McdFrameworkID framework, MeVector3 min, MeVector3 max,
                                                       int triangleMaxCount, McdTriangleListFnPtr f);
MEPUBLIC void MEAPI McdTriangleListSetMaxTriangles(McdTriangleListID g, int max);
MEPUBLIC int MEAPI McdTriangleListGetMaxTriangles(McdTriangleListID g);
MEPUBLIC void MEAPI McdTriangleListSetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max);
MEPUBLIC void MEAPI McdTriangleListGetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max);
MEPUBLIC void MEAPI McdTriangleListSetGenerator(McdTriangleListID g, McdTriangleListFnPtr f);
MEPUBLIC McdTriangleListFnPtr MEAPI McdTriangleListGetGenerator(McdTriangleListID g);
MEPUBLIC void MEAPI McdTriangleListSetUserData(McdTriangleListID g, void *data);
MEPUBLIC void *MEAPI McdTriangleListGetUserData(McdTriangleListID g);

/* Calls the generator for `pair` (one of whose models holds the triangle
 * list g) with the sphere (pos, radius) in g's frame, after making the
 * scratch list hold triangleMaxCount records. Returns the number of usable
 * triangles (clamped to [0, triangleMaxCount], with a warning when the
 * callback broke the limit) and sets *triangles to the list. This is what
 * every nearfield test against a triangle list calls. */
MEPUBLIC int MEAPI McdTriangleListGetTriangles(McdTriangleListID g, struct McdModelPair *pair, MeVector3 pos,
                                               MeReal radius, McdUserTriangle **triangles);

ME_EXTERN_C_END
#endif /* KARMA_MCDTRIANGLELIST_H */
