// sphere_sphyl.cpp: sphere (model1) against sphyl (model2).
//
// The sphyl is the set of points within R of the segment from e0 = o - H a
// to e1 = o + H a (a = its z axis, H = height/2). The closest segment point
// to the sphere centre c is k = e0 + t (e1 - e0), t = clamp((c - e0).(e1 -
// e0) / |e1 - e0|^2, 0, 1); then it is sphere against sphere: d = |c - k|,
// n = (c - k)/d (when c lies on the segment: the sphyl's x axis, normal to
// it), s = d - r - R, one contact midway between c - r n and k + R n.
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const MeReal r1 = McdSphereGetRadius(p->model1->instance.geometry);
  McdGeometry *g = p->model2->instance.geometry;
  const MeReal R = McdSphylGetRadius(g), H = McdSphylGetHeight(g) / 2;
  const Frame sphyl(p->model2);
  const V3 c(ModelTM(p->model1)[3]);
  const V3 e0 = sphyl.o - H * sphyl.axis[2], e1 = sphyl.o + H * sphyl.axis[2];
  const V3 k = e0 + ClosestOnSegment(e0, e1, c) * (e1 - e0);
  V3 n = c - k;
  const MeReal dist = Norm(n);
  const MeReal s = dist - r1 - R;
  if (s > ContactTolerance(p->model1->framework)) return 0;
  n = dist > 0 ? (1 / dist) * n : sphyl.axis[0];
  EmitV(r, (MeReal)0.5 * ((c - r1 * n) + (k + R * n)), n, s, 2, 2,
        feature::Pack(feature::kSingle, feature::kSphereSphyl));
  return Finish(r, n);
}

}  // namespace

extern "C" void MEAPI McdSphereSphylRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeSphyl, fns);
}
