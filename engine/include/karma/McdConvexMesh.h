/* McdConvexMesh.h: the convex mesh geometry, a closed convex polyhedron.
 *
 * McdConvexMeshCreateHull builds the convex hull of a cloud of points (with
 * Qhull): points inside the hull, repeated points and points lying on a
 * face or an edge are dropped, and coplanar triangles are merged into one
 * polygonal face. Vertices keep the frame of the input points: the centre of
 * mass is wherever the shape puts it (McdGeometryGetMassProperties reports
 * it; the guide's pyramid has it below the origin).
 *
 * fatness (>= 0) rounds the mesh: the collision shape is every point within
 * `fatness` of the hull. It widens the AABB; the mass properties are those
 * of the sharp hull.
 *
 * Mass properties are exact for the polyhedron (divergence theorem over
 * tetrahedra from the faces). */
#ifndef KARMA_MCDCONVEXMESH_H
#define KARMA_MCDCONVEXMESH_H
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdConvexMeshID;

/* The hull of `count` points, or NULL with a warning when the points do not
 * span a volume (fewer than four points not all in one plane, relative to
 * the cloud's size), contain NaN or infinity, or fatness is negative. */
MEPUBLIC McdConvexMeshID MEAPI McdConvexMeshCreateHull(McdFrameworkID framework, const MeVector3 vertices[], int count,
                                                       MeReal fatness);

MEPUBLIC int MEAPI McdConvexMeshGetVertexCount(McdConvexMeshID mesh);
/* Pointer to vertex i (0 <= i < vertex count) in the mesh frame, or NULL. */
MEPUBLIC const MeReal *MEAPI McdConvexMeshGetVertex(McdConvexMeshID mesh, int i);
MEPUBLIC int MEAPI McdConvexMeshGetPolygonCount(McdConvexMeshID mesh);
/* Number of vertices of face `polygon`; they run counter-clockwise seen
 * from outside. */
MEPUBLIC int MEAPI McdConvexMeshGetPolygonVertexCount(McdConvexMeshID mesh, int polygon);
/* Vertex index of corner `corner` of face `polygon`, or -1. */
MEPUBLIC int MEAPI McdConvexMeshGetPolygonVertexIndex(McdConvexMeshID mesh, int polygon, int corner);
/* Outward unit normal of face `polygon`. */
MEPUBLIC void MEAPI McdConvexMeshGetPolygonNormal(McdConvexMeshID mesh, int polygon, MeVector3 normal);
MEPUBLIC MeReal MEAPI McdConvexMeshGetFatness(McdConvexMeshID mesh);

ME_EXTERN_C_END
#endif /* KARMA_MCDCONVEXMESH_H */
