// cylinder_plane.cpp: cylinder (model1) against plane (model2).
//
// The cylinder (axis a, radius R, half height H) touches a plane (normal n,
// point o) with its rims: the circles e +- R (cos phi u + sin phi v) around
// the cap centres e = c +- H a, where u is the unit direction of -(n - (n.a)
// a) (the way down the plane within the cap) and v = a x u. When the caps
// are within 2 degrees of the plane (|n - (n.a) a| < 0.035) u is instead the
// cylinder's own x axis, so a cylinder standing on the plane keeps the same
// eight rim points (fixed in the body) however it rocks; the lowest of them
// is then above the true lowest rim point by at most R sin(2 deg)
// (1 - cos 22.5 deg) = 0.0027 R. A rim point p has height
// h = (p - o) . n. Eight points on each rim, starting at phi = 0, are
// candidates; each with h <= tolerance is a contact at p - h/2 n,
// normal +n, separation h (rim edge on plane face). So a cylinder standing
// on its end gives 8, lying on its side 2 (the lowest point of each rim) and
// tilted 1 or 2 (more when deep). The deepest are kept when the buffer is
// short. Feature id: (cap, rim sample index).
#include "prim_math.h"
#include "stable_order.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

constexpr int kRimPoints = 8;

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  McdGeometry *g = p->model1->instance.geometry;
  const MeReal R = McdCylinderGetRadius(g), H = McdCylinderGetHeight(g) / 2;
  const Frame cyl(p->model1), plane(p->model2);
  const V3 n = plane.axis[2], a = cyl.axis[2];
  const MeReal tol = ContactTolerance(p->model1->framework);
  V3 u = Dot(n, a) * a - n;
  const MeReal ulen = Norm(u);
  u = ulen >= (MeReal)0.035 ? (1 / ulen) * u : cyl.axis[0];
  const V3 v = Cross(a, u);
  V3 pts[2 * kRimPoints];
  MeReal h[2 * kRimPoints];
  int order[2 * kRimPoints], count = 0;
  const MeReal cap[2] = {-H, H};
  for (int e = 0; e < 2; ++e) {
    const V3 centre = cyl.o + cap[e] * a;
    for (int k = 0; k < kRimPoints; ++k) {
      const MeReal phi = (MeReal)(2 * ME_PI) * (MeReal)k / kRimPoints;
      const int i = e * kRimPoints + k;
      pts[i] = centre + R * (std::cos(phi) * u + std::sin(phi) * v);
      h[i] = Dot(pts[i] - plane.o, n);
      if (h[i] <= tol) order[count++] = i;
    }
  }
  StableOrderByKey(order, count, h);
  for (int j = 0; j < count; ++j) {
    const int i = order[j];
    const MeU32 id = feature::Pack(feature::kCylinderPlane, (MeU32)(i / kRimPoints), (MeU32)(i % kRimPoints));
    if (!EmitV(r, pts[i] - (MeReal)0.5 * h[i] * n, n, h[i], 1, 2, id)) break;
  }
  return Finish(r, n);
}

}  // namespace

extern "C" void MEAPI McdCylinderPlaneRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypePlane, fns);
}
