// manifold.cpp: several contacts from one normal.
//
// With n the normal (B towards A), u, v a basis of the plane normal to n
// and O a point, every world point is O + x u + y v + z n. The supporting
// features FA (of A along -n) and FB (of B along n) are projected to
// (x, y); their intersection (polygon clipping, segment overlap, or the
// point of a point feature) gives candidate (x, y). At each candidate the
// height of FA's surface zA (plane through a polygon, interpolation along a
// segment, the point's own z) and of FB's zB give the gap zA - zB along n;
// gaps <= tol become contacts at O + x u + y v + (zA + zB)/2 n. No gap is
// smaller than the shapes' separation sep0 (clamped).
//
// At most four contacts: more candidates (a face on a face) are reduced by
// ReduceToFour (nearfield/contact_reduce.h) in a frame fixed to the
// reference polygon (u along its first edge, v = n x u), so a resting pair
// keeps the same points; a buffer shorter still keeps the deepest, then
// each farthest from those already chosen.
//
// Feature ids: each candidate has a clip key naming it, from which
// ManifoldPoint::feature = Mix(Mix(Mix(kConvex, id of A's feature), id of
// B's feature), key) (feature ids of Feature(), shape.h):
//   0-1023     A's polygon clipped by B's: a vertex is where two lines
//              meet, key = in-line * 32 + out-line with A's edges 0-15 and
//              B's edges 16-31 (A's corner: two A edges; crossing: an A
//              edge and a B edge; B's corner inside A: two B edges); a
//              clipped segment's end is 24 + end, or 16 + e where B's edge
//              e cut it; a point is 26
//   1024-2047  the same with the roles of A and B exchanged (B's feature
//              clipped by A's polygon)
//   2048-2053  two segments overlapping: the common interval's ends (an end
//              of A's segment, or of B's); 2054 their crossing point
//   2055, 2056 A's point, B's point; 2057 the fallback point
#include "convex/shape.h"
#include "nearfield/contact_reduce.h"
#include "nearfield/feature_id.h"

#include <algorithm>

namespace karma::mcd::convex {

namespace {

struct P2 {
  double x, y;
};
double Cross2(P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

struct Flat {  // a feature projected on the contact plane
  V world[16];
  P2 p[16];
  double z[16];
  int count = 0, dims = 0;
  V planeN;  // polygon normal (Newell), for heights
};

void Project(Flat &f, V o, V u, V v, V n) {
  for (int i = 0; i < f.count; ++i) {
    const V d = f.world[i] - o;
    f.p[i] = {Dot(d, u), Dot(d, v)};
    f.z[i] = Dot(d, n);
  }
  V m;
  for (int i = 0; i < f.count; ++i) {
    const V a = f.world[i], b = f.world[(i + 1) % f.count];
    m = m + V{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  f.planeN = m;
}

// Height along n of the feature's surface above (x, y).
double Height(const Flat &f, P2 q, V o, V u, V v, V n) {
  if (f.count == 1) return f.z[0];
  if (f.count == 2) {
    const double dx = f.p[1].x - f.p[0].x, dy = f.p[1].y - f.p[0].y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((q.x - f.p[0].x) * dx + (q.y - f.p[0].y) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return f.z[0] + t * (f.z[1] - f.z[0]);
  }
  const double nm = Dot(n, f.planeN);
  if (std::fabs(nm) < 1e-6 * Len(f.planeN)) {
    double s = 0;
    for (int i = 0; i < f.count; ++i) s += f.z[i];
    return s / f.count;
  }
  const V q3 = o + q.x * u + q.y * v;
  return Dot(f.world[0] - q3, f.planeN) / nm;
}

// Sutherland-Hodgman: the points of `in` (a polygon, segment or point)
// inside the convex polygon `clip`, using the edges selected by mask; each
// output point gets its clip key (see the top of the file) in keys[].
int Clip(const P2 *in, int count, const Flat &clip, unsigned mask, double eps, P2 *out, int *keys) {
  struct CP {
    P2 p;
    int line;  // polygon: the line the edge leaving p lies on; else the point's key
  };
  double area = 0;
  for (int i = 0; i < clip.count; ++i) area += Cross2({0, 0}, clip.p[i], clip.p[(i + 1) % clip.count]);
  const double sign = area < 0 ? -1 : 1;
  const bool polygon = count >= 3;
  CP buf[2][40];
  int n = std::min(count, 40);
  for (int i = 0; i < n; ++i) buf[0][i] = {in[i], polygon ? i : (count == 2 ? 24 + i : 26)};
  int cur = 0;
  for (int e = 0; e < clip.count && n > 0; ++e) {
    if (!(mask & (1u << e))) continue;
    const P2 a = clip.p[e], b = clip.p[(e + 1) % clip.count];
    const double el = std::hypot(b.x - a.x, b.y - a.y);
    if (!(el > 0)) continue;
    auto side = [&](P2 p) { return sign * Cross2(a, b, p) / el + eps; };
    const CP *src = buf[cur];
    CP *dst = buf[1 - cur];
    int m = 0;
    if (n == 1) {
      if (side(src[0].p) >= 0) dst[m++] = src[0];
    } else {
      for (int i = 0; i < n && m < 38; ++i) {
        const CP p = src[i], q = src[(i + 1) % n];
        const double sp = side(p.p), sq = side(q.p);
        if (sp >= 0) dst[m++] = p;
        if ((sp >= 0) != (sq >= 0)) {
          const double t = sp / (sp - sq);
          const int line = n == 2 || sp >= 0 ? 16 + e : p.line;
          dst[m++] = {{p.p.x + t * (q.p.x - p.p.x), p.p.y + t * (q.p.y - p.p.y)}, line};
        }
        if (n == 2) break;  // a segment has one edge
      }
      if (n == 2 && side(src[1].p) >= 0 && m < 38) dst[m++] = src[1];
    }
    n = m;
    cur = 1 - cur;
  }
  for (int i = 0; i < n; ++i) {
    out[i] = buf[cur][i].p;
    keys[i] = polygon && n >= 3 ? buf[cur][(i + n - 1) % n].line * 32 + buf[cur][i].line : buf[cur][i].line;
  }
  return n;
}

// Overlap of two segments (or their crossing point).
int SegmentSegment(const Flat &a, const Flat &b, double eps, P2 *out, int *keys) {
  const P2 a0 = a.p[0], a1 = a.p[1], b0 = b.p[0], b1 = b.p[1];
  const double dx = a1.x - a0.x, dy = a1.y - a0.y, ex = b1.x - b0.x, ey = b1.y - b0.y;
  const double la = std::hypot(dx, dy), lb = std::hypot(ex, ey);
  if (!(la > eps) || !(lb > eps)) return 0;
  const double den = dx * ey - dy * ex;
  if (std::fabs(den) < 1e-3 * la * lb) {  // parallel: the common interval
    if (std::fabs(Cross2(a0, a1, b0)) / la > eps) return 0;
    double t0 = ((b0.x - a0.x) * dx + (b0.y - a0.y) * dy) / (la * la);
    double t1 = ((b1.x - a0.x) * dx + (b1.y - a0.y) * dy) / (la * la);
    int k0 = 2049, k1 = 2050;  // B's ends 0 and 1
    if (t0 > t1) std::swap(t0, t1), std::swap(k0, k1);
    if (t0 < 0) t0 = 0, k0 = 2048;  // A's end 0
    if (t1 > 1) t1 = 1, k1 = 2051;  // A's end 1
    if (t0 > t1) return 0;
    out[0] = {a0.x + t0 * dx, a0.y + t0 * dy};
    out[1] = {a0.x + t1 * dx, a0.y + t1 * dy};
    keys[0] = k0;
    keys[1] = k1 == 2051 ? k1 : k1 + 3;  // B's ends at t1: 2052, 2053
    return 2;
  }
  const double t = ((b0.x - a0.x) * ey - (b0.y - a0.y) * ex) / den;
  const double s = ((b0.x - a0.x) * dy - (b0.y - a0.y) * dx) / den;
  const double ta = eps / la, tb = eps / lb;
  if (t < -ta || t > 1 + ta || s < -tb || s > 1 + tb) return 0;
  out[0] = {a0.x + t * dx, a0.y + t * dy};
  keys[0] = 2054;
  return 1;
}

// The reference polygon's frame for ReduceToFour: u along its first edge
// (made normal to n), v = n x u; world axes when neither feature is one.
void ReferenceFrame(const Flat &fa, const Flat &fb, V n, V *u, V *v) {
  const Flat *ref = fb.count >= 3 ? &fb : (fa.count >= 3 ? &fa : nullptr);
  V e = ref ? ref->world[1] - ref->world[0] : V{};
  e = e - Dot(e, n) * n;
  if (!(Len(e) > 0)) e = std::fabs(n.x) < 0.6 ? Cross(n, V{1, 0, 0}) : Cross(n, V{0, 1, 0});
  *u = Unit(e);
  *v = Cross(n, *u);
}

// The deepest, then each farthest from those already chosen: `max` of
// all[0, na) (sorted deepest first) to out.
int DeepestThenFarthest(const ManifoldPoint *all, int na, ManifoldPoint *out, int max) {
  bool used[40] = {};
  out[0] = all[0], used[0] = true;
  for (int k = 1; k < max; ++k) {
    int pick = -1;
    double far = -1;
    for (int i = 0; i < na; ++i) {
      if (used[i]) continue;
      double d = INFINITY;
      for (int j = 0; j < k; ++j) d = std::min(d, Len(all[i].position - out[j].position));
      if (d > far) far = d, pick = i;
    }
    used[pick] = true;
    out[k] = all[pick];
  }
  std::stable_sort(out, out + max,
                   [](const ManifoldPoint &x, const ManifoldPoint &y) { return x.separation < y.separation; });
  return max;
}

}  // namespace

int Manifold(const Shape &a, const Shape &b, V n, double sep0, double tol, unsigned clipMaskB, ManifoldPoint out[],
             int max) {
  Flat fa, fb;
  int ida = 0, idb = 0;
  fa.count = Feature(a, -n, fa.world, &fa.dims, &ida);
  fb.count = Feature(b, n, fb.world, &fb.dims, &idb);
  const MeU32 pairId = feature::Mix(feature::Mix(feature::kConvex, (MeU32)ida), (MeU32)idb);
  const V u = Unit(std::fabs(n.x) < 0.6 ? Cross(n, V{1, 0, 0}) : Cross(n, V{0, 1, 0}));
  const V v = Cross(n, u);
  const V o = fb.world[0];
  Project(fa, o, u, v, n);
  Project(fb, o, u, v, n);
  const double eps = 1e-7 * std::fmax(a.scale, b.scale) + tol;
  P2 cand[40];
  int keys[40];
  int nc = 0;
  if (fb.count >= 3) {
    nc = Clip(fa.p, fa.count, fb, clipMaskB, eps, cand, keys);
  } else if (fa.count >= 3) {
    nc = Clip(fb.p, fb.count, fa, ~0u, eps, cand, keys);
    for (int i = 0; i < nc; ++i) keys[i] += 1024;
  } else if (fa.count == 2 && fb.count == 2) {
    nc = SegmentSegment(fa, fb, eps, cand, keys);
  } else if (fa.count == 1) {
    cand[nc] = fa.p[0], keys[nc++] = 2055;
  } else {
    cand[nc] = fb.p[0], keys[nc++] = 2056;
  }

  ManifoldPoint all[40];
  int na = 0;
  for (int i = 0; i < nc; ++i) {
    const double za = Height(fa, cand[i], o, u, v, n), zb = Height(fb, cand[i], o, u, v, n);
    const double gap = za - zb;
    if (!(gap <= tol)) continue;
    ManifoldPoint m;
    m.position = o + cand[i].x * u + cand[i].y * v + (0.5 * (za + zb)) * n;
    m.separation = std::max(gap, sep0);
    m.dims1 = fa.dims, m.dims2 = fb.dims;
    m.feature = feature::Mix(pairId, (MeU32)keys[i]);
    bool dup = false;  // clipping repeats corners
    for (int k = 0; k < na && !dup; ++k) dup = Len(all[k].position - m.position) <= eps;
    if (!dup && Finite(m.position)) all[na++] = m;
  }
  if (na == 0) {  // the intersection missed (round-off): one contact between the supports
    const V pa = Support(a, -n), pb = Support(b, n);
    all[0].position = 0.5 * (pa + pb);
    all[0].separation = sep0;
    all[0].dims1 = fa.dims, all[0].dims2 = fb.dims;
    all[0].feature = feature::Mix(pairId, 2057);
    na = 1;
  }
  if (na > 4) {  // a face-face touch: four spread over the reference face
    V ru, rv;
    ReferenceFrame(fa, fb, n, &ru, &rv);
    ReducePoint rp[40];
    for (int i = 0; i < na; ++i) {
      const V d = all[i].position - o;
      rp[i] = {Dot(d, ru), Dot(d, rv), -all[i].separation};
    }
    int keep[4];
    const double slack = std::fmax(tol, 1e-3 * std::fmin(a.scale, b.scale));
    const int kept = ReduceToFour(rp, na, slack, keep);
    for (int i = 0; i < kept; ++i) all[i] = all[keep[i]];
    na = kept;
  }
  std::stable_sort(all, all + na,
                   [](const ManifoldPoint &x, const ManifoldPoint &y) { return x.separation < y.separation; });
  max = std::max(1, std::min(max, 4));
  if (na <= max) {
    std::copy(all, all + na, out);
    return na;
  }
  return DeepestThenFarthest(all, na, out, max);
}

}  // namespace karma::mcd::convex
