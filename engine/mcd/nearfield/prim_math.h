// prim_math.h: small value-type vector algebra and the closest-point
// routines shared by the analytic primitive interactions (sphere, box,
// cylinder, sphyl, plane). Everything is inline and header-only.
#pragma once

#include "nearfield.h"
#include "feature_id.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <utility>

namespace karma::mcd::prim {

struct V3 {
  MeReal x = 0, y = 0, z = 0;
  V3() = default;
  V3(MeReal a, MeReal b, MeReal c) : x(a), y(b), z(c) {}
  explicit V3(const MeReal *p) : x(p[0]), y(p[1]), z(p[2]) {}
  MeReal operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  MeReal &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(V3 a) { return {-a.x, -a.y, -a.z}; }
inline V3 operator*(MeReal s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline MeReal Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 Cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline MeReal Norm(V3 a) { return std::sqrt(Dot(a, a)); }
inline MeReal Clamp(MeReal v, MeReal lo, MeReal hi) { return v < lo ? lo : (v > hi ? hi : v); }

// A unit vector perpendicular to unit n (the axis least aligned with n,
// crossed with n).
inline V3 AnyPerpendicular(V3 n) {
  const V3 e =
      std::fabs(n.x) < (MeReal)0.57 ? V3(1, 0, 0) : (std::fabs(n.y) < (MeReal)0.57 ? V3(0, 1, 0) : V3(0, 0, 1));
  const V3 p = Cross(n, e);
  return (1 / Norm(p)) * p;
}

// A rigid frame read from a model TM: rows 0-2 are the axes, row 3 the
// origin, so world = o + sum_i local_i axis_i.
struct Frame {
  V3 axis[3], o;
  explicit Frame(const McdModel *m) {
    const MeMatrix4Ptr tm = ModelTM(m);
    for (int i = 0; i < 3; ++i) axis[i] = V3(tm[i]);
    o = V3(tm[3]);
  }
  V3 ToLocal(V3 p) const {
    const V3 d = p - o;
    return {Dot(d, axis[0]), Dot(d, axis[1]), Dot(d, axis[2])};
  }
  V3 Dir(V3 l) const { return l.x * axis[0] + l.y * axis[1] + l.z * axis[2]; }
  V3 ToWorld(V3 l) const { return o + Dir(l); }
};

// Emit() for V3 values.
inline bool EmitV(McdIntersectResult *r, V3 pos, V3 n, MeReal sep, int dims1, int dims2, MeU32 feature) {
  const MeVector3 p = {pos.x, pos.y, pos.z}, nn = {n.x, n.y, n.z};
  return Emit(r, p, nn, sep, dims1, dims2, feature);
}

// Sets the representative normal and touch when contacts were emitted.
inline int Finish(McdIntersectResult *r, V3 n) {
  if (r->contactCount == 0) return 0;
  MeVector3Set(r->normal, n.x, n.y, n.z);
  r->touch = 1;
  return 1;
}

// Closest point of segment [a, b] to p, as the parameter t in [0, 1].
inline MeReal ClosestOnSegment(V3 a, V3 b, V3 p) {
  const V3 d = b - a;
  const MeReal dd = Dot(d, d);
  return dd > 0 ? Clamp(Dot(p - a, d) / dd, 0, 1) : 0;
}

// Closest points of segments P(s) = p0 + s (p1 - p0), Q(t) = q0 + t (q1 - q0),
// s, t in [0, 1]. Minimising |P(s) - Q(t)|^2 gives the 2x2 system
//   a s - b t = -c,  b s - e t = -f   (a = d1.d1, b = d1.d2, e = d2.d2,
//   c = d1.r, f = d2.r, r = p0 - q0), solved with s clamped, t recomputed and
// clamped, s recomputed (the standard clamped-projection order). Parallel
// segments (denominator ~ 0) take s = 0; `parallel` reports that case.
inline void ClosestSegmentSegment(V3 p0, V3 p1, V3 q0, V3 q1, MeReal &s, MeReal &t, bool *parallel = nullptr) {
  const V3 d1 = p1 - p0, d2 = q1 - q0, rr = p0 - q0;
  const MeReal a = Dot(d1, d1), e = Dot(d2, d2), f = Dot(d2, rr);
  if (parallel) *parallel = false;
  if (a <= 0 && e <= 0) {
    s = t = 0;
    return;
  }
  if (a <= 0) {
    s = 0;
    t = Clamp(f / e, 0, 1);
    return;
  }
  const MeReal c = Dot(d1, rr);
  if (e <= 0) {
    t = 0;
    s = Clamp(-c / a, 0, 1);
    return;
  }
  const MeReal b = Dot(d1, d2), denom = a * e - b * b;
  const bool par = denom <= (MeReal)1e-6 * a * e;
  if (parallel) *parallel = par;
  s = par ? 0 : Clamp((b * f - c * e) / denom, 0, 1);
  t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = Clamp(-c / a, 0, 1);
  } else if (t > 1) {
    t = 1;
    s = Clamp((b - c) / a, 0, 1);
  }
}

}  // namespace karma::mcd::prim

namespace karma::mcd::prim {

// Same-type pairs (box-box, sphyl-sphyl) are called with the caller's order,
// so to give exactly mirrored results for (a, b) and (b, a) the test runs
// with the models in one fixed order (ComputedFirst, nearfield.h) and, when
// that is not the caller's, negates the normals and swaps the dims bytes
// afterwards (feature ids are the same either way).
template <class F>
int OrderedSameType(McdModelPair *p, McdIntersectResult *r, F test) {
  if (ComputedFirst(p->model1, p->model2)) return test(p->model1, p->model2, r);
  const int first = r->contactCount;
  const int touch = test(p->model2, p->model1, r);
  for (int i = first; i < r->contactCount; ++i) {
    McdContact &c = r->contacts[i];
    MeVector3Scale(c.normal, -1);
    c.dims = (MeI16)(((c.dims & 0xFF) << 8) | ((c.dims >> 8) & 0xFF));
  }
  if (touch) MeVector3Scale(r->normal, -1);
  return touch;
}

}  // namespace karma::mcd::prim
