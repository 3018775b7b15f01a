// convex_internal.h: the convex mesh layout and the hull / mass helpers.
#pragma once

#include "mcd_internal.h"

#include <array>
#include <string>
#include <vector>

namespace karma::mcd {

// One block from MeMemoryAPI holds the struct and its arrays.
struct ConvexMesh {
  McdGeometry g;
  int vertexCount;
  int faceCount;
  MeVector3 *vertices;  // vertexCount
  MeVector3 *normals;   // faceCount, outward unit
  int *faceStart;       // faceCount + 1: face f has corners faceStart[f] .. faceStart[f+1]-1
  int *faceIndex;       // vertex index of each corner, counter-clockwise from outside
  MeReal fatness;
  MeReal volume;  // density 1 mass properties of the sharp hull
  MeVector3 com;
  MeMatrix3 inertia;  // about com
};

using Vec3d = std::array<double, 3>;

// A convex polyhedron: vertices (a subset of the input, input order), faces
// as counter-clockwise vertex loops seen from outside, outward normals.
struct Hull {
  std::vector<Vec3d> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<Vec3d> normals;
};

// Builds the hull of the points. False with the reason when the points are
// not finite or do not span a volume (relative tolerance on the cloud size).
bool BuildHull(const MeVector3 *points, int count, Hull &hull, std::string &why);

// Volume, centre of mass and inertia about it (density 1) of a closed hull,
// by summing signed tetrahedra from an interior point to each face's fan.
void PolyhedronMass(const Hull &hull, double &volume, Vec3d &com, double inertia[3][3]);

}  // namespace karma::mcd
