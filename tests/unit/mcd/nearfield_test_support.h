// nearfield_test_support.h: models at poses, one-call nearfield queries and
// a brute-force signed separation (support functions sampled over
// directions) for the primitive interaction tests.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "mcd_test_support.h"

// In their own namespace: the convex tests' nearfield_support.h has other
// Placed / Hit types in mcd_test, and both link into mcd_test.
namespace mcd_test::prim {

// A model of geometry g at (x, y, z), optionally rotated by `angle` about
// `axis`; destroyed with the object.
struct Placed {
  McdModelID model;
  TM tm;
  Placed(McdGeometryID g, MeReal x, MeReal y, MeReal z) : model(McdModelCreate(g)), tm(x, y, z) {
    McdModelSetTransformPtr(model, tm);
    McdModelUpdate(model);
  }
  Placed(McdGeometryID g, MeReal x, MeReal y, MeReal z, std::array<MeReal, 3> axis, MeReal angle) : Placed(g, x, y, z) {
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
  const D3 c = row(m, 3);
  D3 az = row(m, 2);
  const double alen = std::sqrt(dot(az, az));  // unit to double precision
  for (double &v : az) v /= alen;
  const double along = std::fabs(dot(az, d));
  // |d - (d.a) a|, free of the cancellation in sqrt(1 - along^2)
  const D3 perp = {d[0] - dot(d, az) * az[0], d[1] - dot(d, az) * az[1], d[2] - dot(d, az) * az[2]};
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
      return dot(c, d) + McdCylinderGetHeight(g) / 2 * along + McdCylinderGetRadius(g) * std::sqrt(dot(perp, perp));
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

inline D3 cross(const D3 &a, const D3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline D3 unit(D3 v) {
  const double len = std::sqrt(dot(v, v));
  for (double &x : v) x /= len;
  return v;
}

// The directions where a model's support function has a kink: n.k = 0
// for its box axes or its cylinder/sphyl axis.
inline void kinkAxes(McdModelID m, std::vector<D3> &out) {
  switch (McdGeometryGetTypeId(McdModelGetGeometry(m))) {
    case kMcdGeometryTypeBox:
      for (int i = 0; i < 3; ++i) out.push_back(unit(row(m, i)));
      break;
    case kMcdGeometryTypeCylinder:
    case kMcdGeometryTypeSphyl:
      out.push_back(unit(row(m, 2)));
      break;
    default:
      break;
  }
}

// The signed separation of two convex models (distance when apart, minus the
// penetration depth when overlapping) = max over unit n of sepAlong. The
// maximum lies where the support functions' kinks meet, on a kink circle or
// in a smooth region, so the search covers: the points k_i x k_j and the
// cylinder axes, each kink circle n.k = 0 (sampled, then refined by golden
// section), and the sphere (Fibonacci sampling plus a random search with a
// shrinking step), and the hint.
inline double bruteSeparation(McdModelID m1, McdModelID m2, D3 hint = {0, 0, 0}) {
  double bestS = -1e30;
  D3 best = {0, 0, 1};
  auto tryDir = [&](const D3 &n) {
    if (dot(n, n) < 1e-20) return;
    const double s = sepAlong(m1, m2, n);
    if (s > bestS) {
      bestS = s;
      best = unit(n);
    }
  };
  tryDir(hint);
  std::vector<D3> k;
  kinkAxes(m1, k);
  kinkAxes(m2, k);
  for (const D3 &a : k) {
    tryDir(a);
    tryDir({-a[0], -a[1], -a[2]});
    for (const D3 &b : k) {
      const D3 c = cross(a, b);
      tryDir(c);
      tryDir({-c[0], -c[1], -c[2]});
    }
    // The circle n.a = 0: n = cos t u + sin t v.
    const D3 u = unit(std::fabs(a[0]) < 0.6 ? cross(a, {1, 0, 0}) : cross(a, {0, 1, 0}));
    const D3 v = cross(a, u);
    auto at = [&](double t) {
      return D3{std::cos(t) * u[0] + std::sin(t) * v[0], std::cos(t) * u[1] + std::sin(t) * v[1],
                std::cos(t) * u[2] + std::sin(t) * v[2]};
    };
    const int M = 720;
    double bt = 0, bs = -1e30;
    for (int i = 0; i < M; ++i) {
      const double s = sepAlong(m1, m2, at(2 * M_PI * i / M));
      if (s > bs) {
        bs = s;
        bt = 2 * M_PI * i / M;
      }
    }
    double lo = bt - 2 * M_PI / M, hi = bt + 2 * M_PI / M;
    for (int it = 0; it < 80; ++it) {
      const double m1t = lo + (hi - lo) * 0.381966, m2t = hi - (hi - lo) * 0.381966;
      if (sepAlong(m1, m2, at(m1t)) < sepAlong(m1, m2, at(m2t)))
        lo = m1t;
      else
        hi = m2t;
    }
    tryDir(at((lo + hi) / 2));
  }
  const int N = 3000;
  for (int i = 0; i < N; ++i) {
    const double z = 1 - (2 * i + 1.0) / N, rr = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    tryDir({rr * std::cos(phi), rr * std::sin(phi), z});
  }
  // Random search with a shrinking step: 48 fixed random directions per step.
  static const std::vector<D3> dirs = [] {
    std::vector<D3> d;
    unsigned seed = 7;
    while (d.size() < 48) {
      D3 x;
      for (double &c : x) {
        seed = seed * 1664525u + 1013904223u;
        c = (seed >> 8) / 8388608.0 - 1;
      }
      const double len = std::sqrt(dot(x, x));
      if (len > 0.1 && len <= 1) d.push_back({x[0] / len, x[1] / len, x[2] / len});
    }
    return d;
  }();
  for (double step = 0.05; step > 1e-10;) {
    const D3 from = best;
    const double before = bestS;
    for (const D3 &e : dirs) tryDir({from[0] + step * e[0], from[1] + step * e[1], from[2] + step * e[2]});
    if (!(bestS > before)) step /= 2;
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

}  // namespace mcd_test::prim
