// feature_id.h: the value every interaction writes to McdContact::feature.
//
// A feature id names the pair of features (face, edge, vertex of each
// shape) that made a contact, so that the bridge can recognise the same
// contact in the next step. Two rules hold for every interaction:
//  - distinct: no two contacts of one intersection share an id
//    (MakeDistinct() enforces it after any merge);
//  - stable: the id depends only on which features touch (indices fixed in
//    each shape's own frame, never on depth order, positions or the order
//    of a buffer), so it stays the same while those features keep touching.
// 0 means "no identity" and is never produced here.
//
// Layout. Pack(kind, a, b, c) = kind << 24 | a << 16 | b << 8 | c, each field
// one byte; Pack24(kind, v) = kind << 24 | v (v < 2^24). Values that can be
// large or nested (hull faces, triangles, aggregate children) are combined
// with Mix(), a 32-bit avalanche hash, and then cannot be decoded.
//
//   interaction            kind            fields
//   single-contact pairs   kSingle         a = the pair's SingleTag (a constant:
//     (sphere-anything,                    the one contact of a pair keeps its
//      sphyl-sphyl crossing,               id whatever feature it moves to;
//      sphyl-box, box-box                  box-box's fallback point when
//      fallback)                           clipping leaves nothing)
//   box-box, face          kBoxFace1/2     a = reference face (axis k, side):
//                                          2k + (outward normal along -axis);
//                                          b = incident face, same encoding;
//                                          c = the clipped vertex: in-line*8 +
//                                          out-line, lines 0-3 the incident
//                                          face's edges, 4-7 the reference
//                                          face's side planes (so an incident
//                                          corner is (edge, next edge), a clip
//                                          point (edge, plane), a reference
//                                          corner (plane, plane)). kBoxFace1
//                                          when box 1 (the one ComputedFirst,
//                                          nearfield.h, puts first) holds the
//                                          reference face, kBoxFace2 box 2.
//   box-box, edge-edge     kBoxEdge        a = 3i + j (edge directions A_i, B_j),
//                                          b = which of the 4 parallel edges of
//                                          each box (2 sign bits each)
//   box-plane              kBoxPlane       a = corner k (bit i: +h_i along axis i)
//   cylinder-plane         kCylinderPlane  a = cap (0: -H, 1: +H), b = rim sample
//   sphyl-plane            kSphylPlane     a = core end (0: -H, 1: +H)
//   sphyl-sphyl parallel   kSphylPair      a = 1 + end of the common interval
//   sphyl-box, face        kSphylBoxFace   a = box face (2k + side), b = end of
//                                          the clipped core (0 lower t, 1 upper)
//   convex-plane           kConvexPlane    v = hull vertex index (Pack24)
//   convex-convex          Mix(kConvex, feature of A, feature of B, point):
//                          the features as convex::Feature numbers them, the
//                          point as convex::Manifold's clip key
//   triangle list          Mix(triangle key, id against the triangle), the
//                          triangle key a hash of its three local corners
//   aggregate              Mix(child index + 1, id against the child)
#pragma once

#include "nearfield.h"

namespace karma::mcd::feature {

enum Kind : MeU32 {
  kSingle = 1,
  kBoxFace1,
  kBoxFace2,
  kBoxEdge,
  kBoxPlane,
  kCylinderPlane,
  kSphylPlane,
  kSphylPair,
  kSphylBoxFace,
  kConvexPlane,
  kConvex,
};

// Tags of the single-contact pairs (field a of kSingle).
enum SingleTag : MeU32 {
  kSphereSphere = 1,
  kSpherePlane,
  kSphereBox,
  kSphereCylinder,
  kSphereSphyl,
  kSphylSphyl,
  kSphylBox,
  kBoxBoxFallback,
  kSphereTriangle,
};

inline constexpr MeU32 Pack(MeU32 kind, MeU32 a, MeU32 b = 0, MeU32 c = 0) {
  return kind << 24 | (a & 0xFFu) << 16 | (b & 0xFFu) << 8 | (c & 0xFFu);
}
inline constexpr MeU32 Pack24(MeU32 kind, MeU32 v) { return kind << 24 | (v & 0xFFFFFFu); }

// A 32-bit mix of two values (the murmur3 finaliser applied to a
// combination); never 0.
inline constexpr MeU32 Mix(MeU32 x, MeU32 y) {
  MeU32 h = x * 0x9E3779B1u ^ (y + 0x7F4A7C15u + (x << 6) + (x >> 2));
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h ? h : 1u;
}

// Makes the ids of contacts[first, end) distinct and nonzero: a repeated
// id (a hash collision) is re-mixed until it is new. Deterministic: the
// earlier contact keeps its id.
inline void MakeDistinct(McdContact *contacts, int first, int end) {
  for (int i = first; i < end; ++i) {
    MeU32 &f = contacts[i].feature;
    if (f == 0) f = 1;
    for (bool clash = true; clash;) {
      clash = false;
      for (int j = first; j < i && !clash; ++j) clash = contacts[j].feature == f;
      if (clash) f = Mix(f, 0x5BD1E995u);
    }
  }
}

}  // namespace karma::mcd::feature
