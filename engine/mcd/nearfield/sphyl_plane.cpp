// sphyl_plane.cpp: sphyl (model1) against plane (model2).
//
// The sphyl's lowest points over the plane (normal n = row 2 of the plane
// TM, point o = row 3) lie on its end spheres, centres e = c +- H a. Each
// end with height h_e = (e - o) . n has separation s_e = h_e - r and, when
// s_e <= tolerance, a contact at e - (r + h_e)/2 n (midway between the
// sphyl's point e - r n and the plane point e - h_e n), normal +n. A sphyl
// lying flat gives 2 contacts, a tilted one 1 (the lower end) or 2, and a
// zero-length sphyl (a sphere) 1. The deeper end comes first; each
// contact's feature id names its core end (feature_id.h).
#include "prim_math.h"

#include <utility>

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  McdGeometry *g = p->model1->instance.geometry;
  const MeReal radius = McdSphylGetRadius(g), H = McdSphylGetHeight(g) / 2;
  const Frame sphyl(p->model1), plane(p->model2);
  const V3 n = plane.axis[2];
  const MeReal tol = ContactTolerance(p->model1->framework);
  V3 e[2] = {sphyl.o - H * sphyl.axis[2], sphyl.o + H * sphyl.axis[2]};
  MeReal h[2] = {Dot(e[0] - plane.o, n), Dot(e[1] - plane.o, n)};
  MeU32 end[2] = {0, 1};  // the core end each entry is (its feature id)
  if (h[1] < h[0]) {
    std::swap(e[0], e[1]);
    std::swap(h[0], h[1]);
    std::swap(end[0], end[1]);
  }
  const int ends = H > 0 ? 2 : 1;
  for (int i = 0; i < ends; ++i) {
    const MeReal s = h[i] - radius;
    if (s > tol) break;
    if (!EmitV(r, e[i] - (MeReal)0.5 * (radius + h[i]) * n, n, s, 2, 2, feature::Pack(feature::kSphylPlane, end[i])))
      break;
  }
  return Finish(r, n);
}

}  // namespace

extern "C" void MEAPI McdSphylPlaneRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphyl, kMcdGeometryTypePlane, fns);
}
