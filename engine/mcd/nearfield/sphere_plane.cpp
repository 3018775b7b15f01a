// sphere_plane.cpp: sphere (model1) against plane (model2).
//
// Plane normal n = row 2 of its TM, point o = row 3; sphere centre c,
// radius r. Height h = (c - o) . n, separation s = h - r, touching when
// s <= tolerance. One contact, normal +n (from the plane towards the
// sphere), at the midpoint of the sphere's lowest point c - r n and its
// projection on the plane c - h n: position c - (r + h)/2 n. The plane is
// solid below, so a sphere whose centre is under it reports s = h - r < -r.
#include "nearfield.h"
#include "feature_id.h"

using namespace karma::mcd;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const MeReal radius = McdSphereGetRadius(p->model1->instance.geometry);
  const MeReal *c = ModelTM(p->model1)[3];
  const MeMatrix4Ptr plane = ModelTM(p->model2);
  const MeReal *n = plane[2];
  MeVector3 d;
  MeVector3Subtract(d, c, plane[3]);
  const MeReal h = MeVector3Dot(d, n);
  const MeReal s = h - radius;
  if (s > ContactTolerance(p->model1->framework)) return 0;
  MeVector3 pos;
  MeVector3Copy(pos, c);
  MeVector3MultiplyAdd(pos, -(radius + h) / 2, n);
  Emit(r, pos, n, s, 2, 2, feature::Pack(feature::kSingle, feature::kSpherePlane));
  MeVector3Copy(r->normal, n);
  r->touch = 1;
  return 1;
}

}  // namespace

extern "C" void MEAPI McdSpherePlaneRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphere, kMcdGeometryTypePlane, fns);
}
