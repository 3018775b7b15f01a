// segment_shapes.h: where a directed segment first enters a solid shape,
// in the shape's own frame.
//
// The segment is p(t) = a + t (b - a), 0 <= t <= 1. Each function returns
// true when the segment enters the solid (or starts inside it) and sets
//   t       the entry parameter (0 when a is inside or on the surface),
//   normal  the outward unit normal of the surface at the entry point
//           (zero when a is inside: the guide leaves it undefined).
// Only the first entry counts; leaving or re-entering is not reported.
// Solids: sphere |p| <= r; box |p_i| <= h_i; cylinder x^2 + y^2 <= r^2 and
// |z| <= h/2; sphyl: within r of the segment z in [-h/2, h/2]; plane: the
// half space z <= 0; convex: n_i . p <= d_i for every face i.
#pragma once

#include "MePrecision.h"
#include "MeMath.h"

namespace karma::mcd::query {

struct SegmentHit {
  MeReal t = 0;
  MeVector3 normal = {0, 0, 0};
};

bool SegmentSphere(const MeVector3 a, const MeVector3 b, MeReal r, SegmentHit &hit);
bool SegmentBox(const MeVector3 a, const MeVector3 b, const MeVector3 half, SegmentHit &hit);
bool SegmentCylinder(const MeVector3 a, const MeVector3 b, MeReal r, MeReal height, SegmentHit &hit);
bool SegmentSphyl(const MeVector3 a, const MeVector3 b, MeReal r, MeReal height, SegmentHit &hit);
bool SegmentPlane(const MeVector3 a, const MeVector3 b, SegmentHit &hit);

// A convex solid given by `count` faces, face i being n_i . p <= d_i with
// n_i a unit outward normal (Cyrus-Beck clipping).
bool SegmentHalfSpaces(const MeVector3 a, const MeVector3 b, const MeVector3 *normals, const MeReal *offsets, int count,
                       SegmentHit &hit);

}  // namespace karma::mcd::query
