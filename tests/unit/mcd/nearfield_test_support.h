// nearfield_test_support.h: models at poses, one-call nearfield queries and
// a brute-force signed separation (support functions sampled over
// directions) for the primitive interaction tests.
#pragma once

#include <array>
#include <cmath>

#include "mcd_test_support.h"

namespace mcd_test {

// A model of geometry g at (x, y, z), optionally rotated by `angle` about
// `axis`; destroyed with the object.
struct Placed {
  McdModelID model;
  TM tm;
  Placed(McdGeometryID g, MeReal x, MeReal y, MeReal z) : model(McdModelCreate(g)), tm(x, y, z) {
    McdModelSetTransformPtr(model, tm);
    McdModelUpdate(model);
  }
  Placed(McdGeometryID g, MeReal x, MeReal y, MeReal z, std::array<MeReal, 3> axis, MeReal angle)
      : Placed(g, x, y, z) {
    const MeVector3 a = {axis[0], axis[1], axis[2]};
    tm.rotate(a, angle);
    McdModelUpdate(model);
  }
  ~Placed() { McdModelDestroy(model); }
  Placed(const Placed &) = delete;
  Placed &operator=(const Placed &) = delete;
  void move(MeReal x, MeReal y, MeReal z) {
    MeMatrix4TMSetPosition(tm.m, x, y, z);
    McdModelUpdate(model);
  }
  void turn(std::array<MeReal, 3> axis, MeReal angle) {
    const MeVector3 a = {axis[0], axis[1], axis[2]};
    tm.rotate(a, angle);
    McdModelUpdate(model);
  }
};

// McdHello + McdIntersect + McdGoodbye on (a, b) with a buffer of `max`.
struct Hit {
  McdContact c[16];
  McdIntersectResult r{};
  int touch = 0;
  Hit(McdModelID a, McdModelID b, int max = 16) {
    McdModelPair *pair = McdModelPairCreate(a, b);
    McdHello(pair);
    r.contacts = c;
    r.contactMaxCount = max;
    touch = McdIntersect(pair, &r);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
  }
  int count() const { return r.contactCount; }
  double minSep() const {
    double s = 1e30;
    for (int i = 0; i < r.contactCount; ++i) s = std::fmin(s, (double)c[i].separation);
    return s;
  }
};

using D3 = std::array<double, 3>;
inline double dot(const D3 &a, const D3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline D3 row(McdModelID m, int i) {
  const MeMatrix4Ptr t = McdModelGetTransformPtr(m);
  return {(double)t[i][0], (double)t[i][1], (double)t[i][2]};
}

// max over the model's points of x.d (d unit), for the solid primitives.
inline double support(McdModelID m, const D3 &d) {
  McdGeometryID g = McdModelGetGeometry(m);
  const D3 c = row(m, 3), az = row(m, 2);
  const double along = std::fabs(dot(az, d));
  switch (McdGeometryGetTypeId(g)) {
    case kMcdGeometryTypeSphere:
      return dot(c, d) + McdSphereGetRadius(g);
    case kMcdGeometryTypeBox: {
      MeVector3 h;
      McdBoxGetRadii(g, h);
      double s = dot(c, d);
      for (int i = 0; i < 3; ++i) s += h[i] * std::fabs(dot(row(m, i), d));
      return s;
    }
    case kMcdGeometryTypeCylinder:
      return dot(c, d) + McdCylinderGetHeight(g) / 2 * along +
             McdCylinderGetRadius(g) * std::sqrt(std::fmax(0.0, 1 - along * along));
    case kMcdGeometryTypeSphyl:
      return dot(c, d) + McdSphylGetHeight(g) / 2 * along + McdSphylGetRadius(g);
    default:
      return 0;
  }
}

// Separation of m1 from m2 along n (n from m2 towards m1): min over m1 of
// x.n minus max over m2 of x.n.
inline double sepAlong(McdModelID m1, McdModelID m2, D3 n) {
  const double len = std::sqrt(dot(n, n));
  for (double &v : n) v /= len;
  return -support(m1, {-n[0], -n[1], -n[2]}) - support(m2, n);
}

// The signed separation of two convex models (distance when apart, minus the
// penetration depth when overlapping) = max over unit n of sepAlong: sampled
// on a Fibonacci sphere (plus `hint`) and refined by hill climbing.
inline double bruteSeparation(McdModelID m1, McdModelID m2, D3 hint = {0, 0, 0}) {
  D3 best = {0, 0, 1};
  double bestS = sepAlong(m1, m2, best);
  if (dot(hint, hint) > 0 && sepAlong(m1, m2, hint) > bestS) {
    best = hint;
    bestS = sepAlong(m1, m2, hint);
  }
  const int N = 3000;
  for (int i = 0; i < N; ++i) {
    const double z = 1 - (2 * i + 1.0) / N, rr = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    const D3 n = {rr * std::cos(phi), rr * std::sin(phi), z};
    const double s = sepAlong(m1, m2, n);
    if (s > bestS) { bestS = s; best = n; }
  }
  for (double step = 0.05; step > 1e-9;) {
    bool improved = false;
    for (int k = 0; k < 6; ++k) {
      D3 n = best;
      n[k / 2] += (k & 1) ? -step : step;
      const double len = std::sqrt(dot(n, n));
      for (double &v : n) v /= len;
      const double s = sepAlong(m1, m2, n);
      if (s > bestS) { bestS = s; best = n; improved = true; }
    }
    if (!improved) step /= 2;
  }
  return bestS;
}

// A deterministic uniform generator.
struct Lcg {
  unsigned seed;
  explicit Lcg(unsigned s) : seed(s) {}
  MeReal operator()(double lo, double hi) {
    seed = seed * 1664525u + 1013904223u;
    return (MeReal)(lo + (hi - lo) * (seed >> 8) / 16777216.0);
  }
};

}  // namespace mcd_test
