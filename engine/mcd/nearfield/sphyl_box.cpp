// sphyl_box.cpp: sphyl (model1) against box (model2).
//
// Everything is done in the box frame (half extents h): the sphyl is its
// core segment S = [e0, e1] swept by radius r.
//  - S misses the box (slab test): the closest points of S and the box are
//    either an end of S and its clamp into the box, or a point of S and a
//    point of one of the 12 box edges (segment-segment); the nearest pair
//    (P on S, K on the box) gives d, n = (P - K)/d, s = d - r. For interior
//    points of S and of an edge n is taken as +-(a x edge), which P - K is
//    parallel to (and which does not lose digits when d is small).
//  - S enters the box: the minimum translation is along one of the 6 axes
//    of the segment/box Minkowski sum (a zonotope), the box axes x_i and
//    the cross products a x x_i (a = direction of S). On axis L the overlap
//    is o_L = hb + H |a.L| - |m.L| with hb = sum h_i |x_i.L|, H the half
//    length, m the segment midpoint; the least overlap gives n (turned away
//    from the box centre) and s = -o_L - r; P is the end of S deepest along
//    -n. An edge axis must beat the faces by a rounding margin.
// Face case (P beyond exactly one face's slab, or a face axis won): S is
// clipped to that face's rectangle (the other two slabs) and each clipped end
// E at height g = E.f - h_face over it (f the face normal) gives a contact at
// E - (r + g)/2 f with separation g - r when that is <= tolerance: a sphyl
// lying flat on a face has 2 contacts, standing on its end 1. Otherwise one
// contact midway between P - r n and the box point P - (r + s) n.
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

// Clips segment [p, q] to |x_k| <= h_k for the slabs k in `mask`; returns false
// when nothing is left, else the parameters [t0, t1].
bool ClipSlabs(V3 p, V3 q, const MeReal *h, int mask, MeReal &t0, MeReal &t1) {
  t0 = 0;
  t1 = 1;
  const V3 d = q - p;
  for (int k = 0; k < 3; ++k) {
    if (!(mask & (1 << k))) continue;
    if (d[k] == 0) {
      if (std::fabs(p[k]) > h[k]) return false;
      continue;
    }
    MeReal ta = (-h[k] - p[k]) / d[k], tb = (h[k] - p[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::fmax(t0, ta);
    t1 = std::fmin(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

V3 ClampToBox(V3 p, const MeReal *h) {
  return {Clamp(p.x, -h[0], h[0]), Clamp(p.y, -h[1], h[1]), Clamp(p.z, -h[2], h[2])};
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  McdGeometry *g = p->model1->instance.geometry;
  const MeReal radius = McdSphylGetRadius(g), H = McdSphylGetHeight(g) / 2;
  MeVector3 h;
  McdBoxGetRadii(p->model2->instance.geometry, h);
  const Frame sphyl(p->model1), box(p->model2);
  const MeReal tol = ContactTolerance(p->model1->framework);
  const V3 a = box.ToLocal(sphyl.o + sphyl.axis[2]) - box.ToLocal(sphyl.o);
  const V3 m = box.ToLocal(sphyl.o), e0 = m - H * a, e1 = m + H * a;
  V3 n, P;
  MeReal s, t0, t1;
  int face = -1;  // the box face (axis index) n is the normal of, if any
  if (!ClipSlabs(e0, e1, h, 7, t0, t1)) {
    // Separated cores: nearest of the ends' clamps and the 12 edges.
    MeReal best = MEINFINITY;
    V3 K, across;  // across: a x edge when both closest points are interior
    auto consider = [&](V3 sp, V3 bp, V3 x) {
      const MeReal d2 = Dot(sp - bp, sp - bp);
      if (d2 < best) {
        best = d2;
        P = sp;
        K = bp;
        across = x;
      }
    };
    consider(e0, ClampToBox(e0, h), V3());
    consider(e1, ClampToBox(e1, h), V3());
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 4; ++c) {
        V3 q0, q1;
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        q0[k1] = q1[k1] = (c & 1) ? h[k1] : -h[k1];
        q0[k2] = q1[k2] = (c & 2) ? h[k2] : -h[k2];
        q0[k] = -h[k];
        q1[k] = h[k];
        MeReal u, v;
        bool par;
        ClosestSegmentSegment(e0, e1, q0, q1, u, v, &par);
        const bool interior = !par && u > 0 && u < 1 && v > 0 && v < 1;
        consider(e0 + u * (e1 - e0), q0 + v * (q1 - q0), interior ? Cross(a, q1 - q0) : V3());
      }
    const MeReal dist = std::sqrt(best);
    s = dist - radius;
    if (s > tol) return 0;
    n = (1 / dist) * (P - K);
    const MeReal alen = Norm(across);
    if (alen > 0) {
      // Interior of S against the interior of an edge: n is along
      // a x edge exactly (no cancellation in P - K for small gaps).
      n = (Dot(across, P - K) < 0 ? -1 / alen : 1 / alen) * across;
      s = std::fabs(Dot(P - K, n)) - radius;
    }
    // P outside exactly one slab: the box point is on that face, and the
    // normal is the face's (set exactly, free of rounding in P - K).
    int outside = 0;
    for (int k = 0; k < 3; ++k)
      if (std::fabs(P[k]) > h[k]) {
        ++outside;
        face = k;
      }
    if (outside != 1) face = -1;
  } else {
    // Penetrating cores: least overlap over the Minkowski-difference axes;
    // an edge axis must beat the faces by a rounding margin (so a sphyl
    // lying along a face keeps that face).
    const MeReal margin = (MeReal)1e-5 * (H + h[0] + h[1] + h[2]);
    MeReal least = MEINFINITY;
    auto axisTest = [&](V3 L, int k) {
      const MeReal len = Norm(L);
      if (len < (MeReal)1e-4) return;
      L = (1 / len) * L;
      const MeReal hb = h[0] * std::fabs(L.x) + h[1] * std::fabs(L.y) + h[2] * std::fabs(L.z);
      const MeReal o = hb + H * std::fabs(Dot(a, L)) - std::fabs(Dot(m, L));
      if (o < least - (k < 0 && face >= 0 ? margin : 0)) {
        least = o;
        n = Dot(m, L) < 0 ? -L : L;
        face = k;
      }
    };
    for (int k = 0; k < 3; ++k) {
      V3 x;
      x[k] = 1;
      axisTest(x, k);
    }
    for (int k = 0; k < 3; ++k) {
      V3 x;
      x[k] = 1;
      axisTest(Cross(a, x), -1);
    }
    s = -least - radius;
    P = Dot(e0, n) < Dot(e1, n) ? e0 : e1;
  }
  // A face normal: clip the segment to that face's rectangle.
  if (face >= 0) {
    const int k = face;
    V3 f;
    f[k] = n[k] > 0 ? 1 : -1;
    const V3 nw = box.Dir(f);
    if (ClipSlabs(e0, e1, h, 7 & ~(1 << k), t0, t1)) {
      for (int end = 0; end < 2; ++end) {
        const MeReal t = end == 0 ? t0 : t1;
        const V3 E = e0 + t * (e1 - e0);
        const MeReal gap = Dot(E, f) - h[k];
        if (gap - radius <= tol) {
          const V3 at = box.ToWorld(E - (MeReal)0.5 * (radius + gap) * f);
          EmitV(r, at, nw, gap - radius, 2, 2, feature::Pack(feature::kSphylBoxFace, 2 * k + (f[k] < 0), end));
        }
        if ((t1 - t0) * 2 * H <= tol) break;  // one point
      }
    }
    if (r->contactCount > 0) return Finish(r, nw);
    n = f;
  }
  const V3 nw = box.Dir(n);
  EmitV(r, box.ToWorld(P - (radius + (MeReal)0.5 * s) * n), nw, s, 2, 1,
        feature::Pack(feature::kSingle, feature::kSphylBox));
  return Finish(r, nw);
}

}  // namespace

extern "C" void MEAPI McdSphylBoxRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphyl, kMcdGeometryTypeBox, fns);
}
