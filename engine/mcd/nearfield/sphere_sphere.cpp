// sphere_sphere.cpp: sphere (model1) against sphere (model2).
//
// Centres c1, c2, radii r1, r2, d = c1 - c2:
//   separation s = |d| - r1 - r2, touching when s <= tolerance;
//   normal n = d / |d| (from model2 towards model1; +z when the centres
//   coincide); one contact midway between the surface points c2 + r2 n and
//   c1 - r1 n, i.e. at c2 + (r2 + s/2) n. Both features are faces (dims 2).
#include "nearfield.h"
#include "feature_id.h"

#include <cmath>

using namespace karma::mcd;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const MeReal r1 = McdSphereGetRadius(p->model1->instance.geometry);
  const MeReal r2 = McdSphereGetRadius(p->model2->instance.geometry);
  const MeReal *c1 = ModelTM(p->model1)[3], *c2 = ModelTM(p->model2)[3];
  MeVector3 n;
  MeVector3Subtract(n, c1, c2);
  const MeReal dist = MeVector3Magnitude(n);
  const MeReal s = dist - r1 - r2;
  if (s > ContactTolerance(p->model1->framework)) return 0;
  if (dist > 0)
    MeVector3Scale(n, 1 / dist);
  else
    MeVector3Set(n, 0, 0, 1);
  MeVector3 pos;
  MeVector3Copy(pos, c2);
  MeVector3MultiplyAdd(pos, r2 + s / 2, n);
  Emit(r, pos, n, s, 2, 2, feature::Pack(feature::kSingle, feature::kSphereSphere));
  MeVector3Copy(r->normal, n);
  r->touch = 1;
  return 1;
}

}  // namespace

extern "C" void MEAPI McdSphereSphereRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeSphere, fns);
}
