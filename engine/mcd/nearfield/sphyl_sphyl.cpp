// sphyl_sphyl.cpp: sphyl (model1) against sphyl (model2).
//
// Each sphyl is its core segment (centre o, z axis a, half length H) swept
// by its radius. The closest points P on segment 1 and Q on segment 2
// (ClosestSegmentSegment) give d = |P - Q|, n = (P - Q)/d, s = d - r1 - r2
// and one contact midway between P - r1 n and Q + r2 n. When P and Q are
// both interior, n is taken as a1 x a2 (P - Q is parallel to it) turned
// towards P - Q, and d = |(o1 - o2).n|, which lose no digits when the cores
// nearly touch. When the segments cross (d ~ 0) n is a1 x a2 turned towards
// o1 - o2 (or, for one line, perpendicular to it). Parallel axes: the part
// of segment 1 that projects
// onto segment 2 is the interval [t0, t1] along a1; when it has length,
// both of its ends give a contact (same n and s: the lines' distance).
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

struct Seg {
  V3 o, a, e0, e1;
  MeReal r, h;
  explicit Seg(const McdModel *m) {
    const Frame f(m);
    r = McdSphylGetRadius(m->instance.geometry);
    h = McdSphylGetHeight(m->instance.geometry) / 2;
    o = f.o;
    a = f.axis[2];
    e0 = o - h * a;
    e1 = o + h * a;
  }
};

// The unit normal from Q to P, with fallbacks for touching core segments
// (d below 1e-5 of the sizes is rounding noise, not a direction).
V3 NormalBetween(const Seg &s1, const Seg &s2, V3 d) {
  const MeReal dist = Norm(d);
  if (dist > (MeReal)1e-5 * (s1.h + s2.h + s1.r + s2.r)) return (1 / dist) * d;
  V3 n = Cross(s1.a, s2.a);
  const MeReal len = Norm(n);
  if (len > (MeReal)1e-6) {
    n = (1 / len) * n;
    return Dot(n, s1.o - s2.o) < 0 ? -n : n;
  }
  return AnyPerpendicular(s1.a);
}

int Test(const McdModel *m1, const McdModel *m2, McdIntersectResult *r) {
  const Seg s1(m1), s2(m2);
  const MeReal tol = ContactTolerance(m1->framework);
  MeReal u, v;
  bool parallel = false;
  ClosestSegmentSegment(s1.e0, s1.e1, s2.e0, s2.e1, u, v, &parallel);
  const V3 P = s1.e0 + u * (s1.e1 - s1.e0), Q = s2.e0 + v * (s2.e1 - s2.e0);
  V3 n = NormalBetween(s1, s2, P - Q);
  MeReal dist = Norm(P - Q);
  if (!parallel && u > 0 && u < 1 && v > 0 && v < 1) {
    // Both interior: P - Q is along a1 x a2, and that cross product and
    // the lines' distance |(o1 - o2).n| are free of the cancellation in
    // P - Q when the cores nearly touch.
    const V3 c = Cross(s1.a, s2.a);
    const MeReal len = Norm(c);
    if (len > (MeReal)1e-6) {
      n = (1 / len) * c;
      if (Dot(n, dist > 0 ? P - Q : s1.o - s2.o) < 0) n = -n;
      dist = std::fabs(Dot(s1.o - s2.o, n));
    }
  }
  const MeReal s = dist - s1.r - s2.r;
  if (s > tol) return 0;
  if (parallel && s1.h > 0 && s2.h > 0) {
    // Segment 2's ends projected on line 1 (coordinates along a1 from o1).
    const MeReal c0 = Dot(s2.e0 - s1.o, s1.a), c1 = Dot(s2.e1 - s1.o, s1.a);
    const MeReal t0 = std::fmax(-s1.h, std::fmin(c0, c1));
    const MeReal t1 = std::fmin(s1.h, std::fmax(c0, c1));
    if (t1 - t0 > tol) {
      for (int end = 0; end < 2; ++end) {
        const MeReal t = end == 0 ? t0 : t1;
        const V3 pt = s1.o + t * s1.a;
        const V3 q = s2.e0 + ClosestOnSegment(s2.e0, s2.e1, pt) * (s2.e1 - s2.e0);
        const MeReal d = Dot(pt - q, n) - s1.r - s2.r;
        EmitV(r, (MeReal)0.5 * ((pt - s1.r * n) + (q + s2.r * n)), n, d, 2, 2,
              feature::Pack(feature::kSphylPair, 1 + end));
      }
      return Finish(r, n);
    }
  }
  EmitV(r, (MeReal)0.5 * ((P - s1.r * n) + (Q + s2.r * n)), n, s, 2, 2,
        feature::Pack(feature::kSingle, feature::kSphylSphyl));
  return Finish(r, n);
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) { return OrderedSameType(p, r, Test); }

}  // namespace

extern "C" void MEAPI McdSphylSphylRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphyl, kMcdGeometryTypeSphyl, fns);
}
