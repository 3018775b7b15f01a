// segment_shapes.cpp: first entry of a segment into each solid (see the
// header for the solids and the conventions).
#include "segment_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace karma::mcd::query {

namespace {

constexpr MeReal kInf = std::numeric_limits<MeReal>::infinity();

void SetInside(SegmentHit &hit) {
  hit.t = 0;
  MeVector3Set(hit.normal, 0, 0, 0);
}

// Interval of t where x^2 + y^2 <= r^2 for the line a + t d (unbounded
// t). False when the line misses the infinite cylinder.
bool RadialInterval(const MeVector3 a, const MeVector3 d, MeReal r, MeReal &in, MeReal &out) {
  const MeReal A = d[0] * d[0] + d[1] * d[1];
  const MeReal C = a[0] * a[0] + a[1] * a[1] - r * r;
  if (A <= 0) {  // parallel to the axis: inside for every t or never
    in = -kInf;
    out = kInf;
    return C <= 0;
  }
  const MeReal B = a[0] * d[0] + a[1] * d[1];
  const MeReal disc = B * B - A * C;
  if (disc < 0) return false;
  const MeReal s = std::sqrt(disc);
  in = (-B - s) / A;
  out = (-B + s) / A;
  return true;
}

// Interval of t where |z| <= hz.
bool SlabInterval(MeReal az, MeReal dz, MeReal hz, MeReal &in, MeReal &out) {
  if (dz == 0) {
    in = -kInf;
    out = kInf;
    return std::fabs(az) <= hz;
  }
  const MeReal t1 = (-hz - az) / dz, t2 = (hz - az) / dz;
  in = std::min(t1, t2);
  out = std::max(t1, t2);
  return true;
}

}  // namespace

bool SegmentSphere(const MeVector3 a, const MeVector3 b, MeReal r, SegmentHit &hit) {
  MeVector3 d;
  MeVector3Subtract(d, b, a);
  const MeReal C = MeVector3Dot(a, a) - r * r;
  if (C <= 0) {
    SetInside(hit);
    return true;
  }
  const MeReal A = MeVector3Dot(d, d);
  if (A <= 0) return false;
  const MeReal B = MeVector3Dot(a, d);
  const MeReal disc = B * B - A * C;
  if (disc < 0) return false;
  const MeReal t = (-B - std::sqrt(disc)) / A;  // the smaller root: entry
  if (t < 0 || t > 1) return false;
  hit.t = t;
  for (int i = 0; i < 3; ++i) hit.normal[i] = a[i] + t * d[i];
  MeVector3Normalize(hit.normal);
  return true;
}

bool SegmentBox(const MeVector3 a, const MeVector3 b, const MeVector3 half, SegmentHit &hit) {
  if (std::fabs(a[0]) <= half[0] && std::fabs(a[1]) <= half[1] && std::fabs(a[2]) <= half[2]) {
    SetInside(hit);
    return true;
  }
  MeVector3 d;
  MeVector3Subtract(d, b, a);
  // Slabs: the entry is the latest slab entry; a starts outside, so some
  // slab entry is positive and names the face crossed.
  MeReal enter = 0, leave = 1;
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    MeReal in, out;
    if (!SlabInterval(a[i], d[i], half[i], in, out)) return false;
    if (in > enter) {
      enter = in;
      axis = i;
    }
    leave = std::min(leave, out);
    if (enter > leave) return false;
  }
  if (axis < 0) return false;
  hit.t = enter;
  MeVector3Set(hit.normal, 0, 0, 0);
  hit.normal[axis] = d[axis] > 0 ? -1 : 1;  // the face that looks at the start
  return true;
}

bool SegmentCylinder(const MeVector3 a, const MeVector3 b, MeReal r, MeReal height, SegmentHit &hit) {
  const MeReal hz = height / 2;
  if (a[0] * a[0] + a[1] * a[1] <= r * r && std::fabs(a[2]) <= hz) {
    SetInside(hit);
    return true;
  }
  MeVector3 d;
  MeVector3Subtract(d, b, a);
  MeReal cIn, cOut, zIn, zOut;
  if (!RadialInterval(a, d, r, cIn, cOut) || !SlabInterval(a[2], d[2], hz, zIn, zOut)) return false;
  const MeReal enter = std::max(std::max(cIn, zIn), (MeReal)0);
  const MeReal leave = std::min(std::min(cOut, zOut), (MeReal)1);
  if (enter > leave) return false;
  hit.t = enter;
  if (cIn >= zIn) {  // through the curved side: radial normal
    MeVector3Set(hit.normal, a[0] + enter * d[0], a[1] + enter * d[1], 0);
    MeVector3Normalize(hit.normal);
  } else {  // through a flat end
    MeVector3Set(hit.normal, 0, 0, d[2] > 0 ? -1 : 1);
  }
  return true;
}

bool SegmentSphyl(const MeVector3 a, const MeVector3 b, MeReal r, MeReal height, SegmentHit &hit) {
  // The capsule is the union of the finite cylinder and the two end balls;
  // the first entry into a union is the earliest entry into any part.
  const MeReal hz = height / 2;
  bool any = false;
  SegmentHit best;
  best.t = 2;
  auto consider = [&](bool ok, const SegmentHit &h) {
    if (ok && h.t < best.t) {
      best = h;
      any = true;
    }
  };
  SegmentHit h;
  if (height > 0) consider(SegmentCylinder(a, b, r, height, h), h);
  for (int end = -1; end <= 1; end += 2) {
    MeVector3 as = {a[0], a[1], a[2] - end * hz}, bs = {b[0], b[1], b[2] - end * hz};
    consider(SegmentSphere(as, bs, r, h), h);
  }
  if (!any) return false;
  if (best.t == 0) SetInside(best);
  hit = best;
  return true;
}

bool SegmentPlane(const MeVector3 a, const MeVector3 b, SegmentHit &hit) {
  if (a[2] <= 0) {
    SetInside(hit);
    return true;
  }
  if (b[2] > 0) return false;
  hit.t = a[2] / (a[2] - b[2]);
  MeVector3Set(hit.normal, 0, 0, 1);
  return true;
}

bool SegmentHalfSpaces(const MeVector3 a, const MeVector3 b, const MeVector3 *normals, const MeReal *offsets, int count,
                       SegmentHit &hit) {
  MeVector3 d;
  MeVector3Subtract(d, b, a);
  MeReal enter = 0, leave = 1;
  int face = -1;
  for (int i = 0; i < count; ++i) {
    const MeReal gap = offsets[i] - MeVector3Dot(normals[i], a);  // >= 0: a inside face i
    const MeReal rate = MeVector3Dot(normals[i], d);
    if (rate == 0) {
      if (gap < 0) return false;  // parallel and outside
      continue;
    }
    const MeReal t = gap / rate;
    if (rate < 0) {  // moving inwards through face i
      if (gap < 0 && t > enter) {
        enter = t;
        face = i;
      }
    } else {
      leave = std::min(leave, t);
    }
    if (enter > leave) return false;
  }
  if (face < 0) {  // inside every face at the start
    SetInside(hit);
    return true;
  }
  hit.t = enter;
  MeVector3Copy(hit.normal, normals[face]);
  return true;
}

}  // namespace karma::mcd::query
