// shape.h: convex shapes in world coordinates (double precision) for the
// general convex nearfield: support functions for libccd, supporting
// features for manifolds, and the contact-manifold builder.
//
// A shape is a sharp core grown by a margin (every point within `margin` of
// the core): sphere = point + r, sphyl = segment (0,0,+-h/2) + r, convex
// mesh = hull + fatness; box, cylinder (axis = local z) and triangle have
// no margin. Local axes are the rows of the TM (world = local * R + t).
#pragma once

#include "mcd_internal.h"

#include <cmath>

namespace karma::mcd {
struct ConvexMesh;  // geometry/convex_internal.h
}

namespace karma::mcd::convex {

struct V {
  double x = 0, y = 0, z = 0;
  double &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator-(V a) { return {-a.x, -a.y, -a.z}; }
inline V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
inline double Dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V Cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double Len(V a) { return std::sqrt(Dot(a, a)); }
inline V Unit(V a) {
  const double l = Len(a);
  return l > 0 ? (1 / l) * a : V{0, 0, 1};
}
inline bool Finite(V a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
inline V FromMe(const MeReal *p) { return {(double)p[0], (double)p[1], (double)p[2]}; }
inline void ToMe(MeReal *p, V a) { p[0] = (MeReal)a.x, p[1] = (MeReal)a.y, p[2] = (MeReal)a.z; }

enum class Kind { Sphere, Box, Cylinder, Sphyl, Hull, Triangle };

struct Shape {
  Kind kind = Kind::Sphere;
  V axis[3];      // local axes in world (TM rows 0-2)
  V t;            // world position of the local origin
  V half;         // box half extents
  double r = 0;   // cylinder radius
  double hh = 0;  // cylinder / sphyl half height
  double margin = 0;
  double scale = 1;  // a size for relative tolerances
  const ConvexMesh *mesh = nullptr;
  V tri[3];  // triangle corners (world)
  V triN;    // triangle unit normal (world)
  V Local(V d) const { return {Dot(d, axis[0]), Dot(d, axis[1]), Dot(d, axis[2])}; }
  V World(V p) const { return t + p.x * axis[0] + p.y * axis[1] + p.z * axis[2]; }
};

// The shape of a geometry placed at tm; false for types that are not convex
// solids (plane, triangle list, aggregate) or degenerate input.
bool MakeShape(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, Shape &s);
// A triangle (world corners, normal from the right-hand rule).
void MakeTriangle(V a, V b, V c, Shape &s);

// The farthest point of the shape (margin included) along d (d != 0).
V Support(const Shape &s, V d);
inline double SupportValue(const Shape &s, V d) { return Dot(Support(s, d), d); }
// A point inside the shape.
V Centre(const Shape &s);

// The supporting feature along unit d: a convex polygon (3+ points, in
// order round its edge: a box or hull face, a cylinder cap sampled at 8 rim
// points, a triangle), a segment (a cylinder or sphyl side line, a hull
// edge) or a point, on the shape's surface (margin included). Returns the
// count (<= 16); *dims gets the feature's dimension (0, 1, 2) and *id
// (when not NULL) which feature of the shape it is, a number fixed in the
// shape's own frame: box face 2i + (outward along -axis i); hull face f as
// 2f + 1, hull vertex v as 2v; cylinder cap 1 (-z) or 2 (+z), side line 3;
// sphyl end 1 (-z) or 2 (+z), side line 0; triangle face 8, else the bit
// mask of its corners on the feature; sphere 0.
int Feature(const Shape &s, V d, V out[16], int *dims, int *id = nullptr);

// Candidate face normals of a shape (outward, unit): box faces, hull faces,
// cylinder caps, triangle faces. Returns the count (<= max).
int FaceNormals(const Shape &s, V out[], int max);
int FaceCount(const Shape &s);

// Separation of A above B along unit n (n from B towards A): the gap
// between the lowest point of A and the highest of B, negative in overlap.
inline double SeparationAlong(const Shape &a, const Shape &b, V n) { return -SupportValue(a, -n) - SupportValue(b, n); }

// The least-penetration (or, when apart, separating) normal from B towards
// A and the separation along it; false when the shapes are farther apart
// than tol. Uses libccd's GJK+EPA (MPR as a fallback) on the shapes grown
// by tol, then keeps the best of that direction and the face normals.
bool Penetration(const Shape &a, const Shape &b, double tol, V *n, double *sep);

struct ManifoldPoint {
  V position;
  double separation;
  int dims1, dims2;
  MeU32 feature;  // Mix of A's and B's feature ids and the point's clip key
};
// Contacts between A and B for the normal n (B towards A) of separation
// sep0: the supporting features of A (along -n) and B (along n) are
// projected on the plane normal to n and intersected (Sutherland-Hodgman
// against the polygon, segment overlap, or the point); each point of the
// intersection whose gap along n is <= tol becomes a contact midway between
// the surfaces. clipMaskB selects which edges of B's polygon clip (bit i:
// edge i -> i+1; a triangle list clears smooth edges). At most four points
// (and at most `max`), spread over the contact area and the deepest first
// (manifold.cpp); a fallback single point when the intersection is empty.
int Manifold(const Shape &a, const Shape &b, V n, double sep0, double tol, unsigned clipMaskB, ManifoldPoint out[],
             int max);

}  // namespace karma::mcd::convex
