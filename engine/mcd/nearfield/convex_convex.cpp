// convex_convex.cpp: the general convex pairs, through libccd and the
// manifold builder (engine/mcd/convex/): convex mesh against sphere, box,
// cylinder, sphyl and convex mesh; box-cylinder, cylinder-cylinder and
// cylinder-sphyl.
//
// Model1 is A, model2 is B. Penetration() gives the normal n from B towards
// A with the least penetration (or, within the tolerance, the gap) and the
// separation s along it; Manifold() turns the supporting features of A
// (along -n) and B (along +n) into up to 4 contacts with gaps <= tol: a
// convex box resting on a box gives its 4 corners, a cylinder standing on
// a box 4 of its 8 rim samples, a hull edge on a face 2, a curved pair 1.
// Feature ids: Manifold's (feature_id.h, convex/manifold.cpp).
#include "convex_common.h"
#include "feature_id.h"

#include <algorithm>

using namespace karma::mcd;
using namespace karma::mcd::convex;

namespace karma::mcd {

// Shared with the aggregate and triangle list files: A against B as above.
int ConvexIntersect(const Shape &a, const Shape &b, double tol, McdIntersectResult *r) {
  V n;
  double s;
  if (!Penetration(a, b, tol, &n, &s)) return 0;
  ManifoldPoint pts[16];
  const int count = Manifold(a, b, n, s, tol, ~0u, pts, std::max(r->contactMaxCount, 1));
  MeVector3 normal;
  ToMe(normal, n);
  const int first = r->contactCount;
  for (int i = 0; i < count; ++i) {
    MeVector3 pos;
    ToMe(pos, pts[i].position);
    if (!Emit(r, pos, normal, (MeReal)pts[i].separation, pts[i].dims1, pts[i].dims2, pts[i].feature)) break;
  }
  feature::MakeDistinct(r->contacts, first, r->contactCount);
  MeVector3Copy(r->normal, normal);
  r->touch = 1;
  return 1;
}

}  // namespace karma::mcd

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  Shape a, b;
  if (!MakeShape(p->model1->instance.geometry, ModelTM(p->model1), a)) return 0;
  if (!MakeShape(p->model2->instance.geometry, ModelTM(p->model2), b)) return 0;
  const double tol = ContactTolerance(p->model1->framework);
  // Two shapes of one type: always computed in one fixed order
  // (ComputedFirst, nearfield.h), so that both argument orders give
  // mirrored contacts, and the order, the reference face and so the
  // feature ids do not change while the models move.
  if (a.kind != b.kind || ComputedFirst(p->model1, p->model2)) return ConvexIntersect(a, b, tol, r);
  const int first = r->contactCount;
  if (!ConvexIntersect(b, a, tol, r)) return 0;
  for (int i = first; i < r->contactCount; ++i) {
    McdContact &c = r->contacts[i];
    MeVector3Negate(c.normal);
    const unsigned d = (unsigned)(unsigned short)c.dims;
    c.dims = (MeI16)(((d & 0xFFu) << 8) | (d >> 8));
  }
  MeVector3Negate(r->normal);
  return 1;
}

void Register(McdFrameworkID fw, int a, int b) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, a, b, fns);
}

}  // namespace

extern "C" {

void MEAPI McdConvexMeshSphereRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypeSphere);
}
void MEAPI McdConvexMeshBoxRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypeBox);
}
void MEAPI McdConvexMeshCylinderRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypeCylinder);
}
void MEAPI McdConvexMeshSphylRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypeSphyl);
}
void MEAPI McdConvexMeshConvexMeshRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypeConvexMesh);
}
void MEAPI McdBoxCylinderRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder);
}
void MEAPI McdCylinderCylinderRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeCylinder);
}
void MEAPI McdCylinderSphylRegisterInteraction(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl);
}

}  // extern "C"
