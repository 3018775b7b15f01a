// sphere_cylinder.cpp: sphere (model1) against cylinder (model2).
//
// In the cylinder frame (axis z, radius R, half height H = height/2) the
// sphere centre is q = (x, y, z), radial distance rho = sqrt(x^2 + y^2).
// Outside the solid cylinder the closest point is k = (min(rho, R) x/rho,
// ..., clamp(z, -H, H)); n = (q - k)/|q - k|, s = |q - k| - r. The feature
// is the rim circle (edge) when both the radius and z were clamped, else the
// side or a cap (face). Centre inside: the side is R - rho away (normal
// radial; +x when rho = 0), the nearer cap H - |z| (normal +-z); the nearer
// of the two gives n and s = -gap - r. One contact midway between the
// sphere's deepest point c - r n and the cylinder point.
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const MeReal radius = McdSphereGetRadius(p->model1->instance.geometry);
  McdGeometry *g = p->model2->instance.geometry;
  const MeReal R = McdCylinderGetRadius(g), H = McdCylinderGetHeight(g) / 2;
  const Frame cyl(p->model2);
  const V3 c(ModelTM(p->model1)[3]);
  const V3 q = cyl.ToLocal(c);
  const MeReal rho = std::sqrt(q.x * q.x + q.y * q.y);
  const V3 radial = rho > 0 ? V3(q.x / rho, q.y / rho, 0) : V3(1, 0, 0);
  const bool outRadial = rho > R, outAxial = std::fabs(q.z) > H;
  V3 n, k;
  MeReal s;
  int dims = 2;
  if (outRadial || outAxial) {
    k = outRadial ? R * radial : V3(q.x, q.y, 0);
    k.z = Clamp(q.z, -H, H);
    const V3 d = q - k;
    const MeReal dist = Norm(d);
    s = dist - radius;
    if (s > ContactTolerance(p->model1->framework)) return 0;
    n = cyl.Dir((1 / dist) * d);
    if (outRadial && outAxial) dims = 1;
  } else {
    const MeReal side = R - rho, cap = H - std::fabs(q.z);
    const MeReal sign = q.z < 0 ? -1 : 1;
    if (side < cap) {
      n = cyl.Dir(radial);
      k = V3(R * radial.x, R * radial.y, q.z);
      s = -side - radius;
    } else {
      n = sign * cyl.axis[2];
      k = V3(q.x, q.y, sign * H);
      s = -cap - radius;
    }
  }
  EmitV(r, (MeReal)0.5 * ((c - radius * n) + cyl.ToWorld(k)), n, s, 2, dims,
        feature::Pack(feature::kSingle, feature::kSphereCylinder));
  return Finish(r, n);
}

}  // namespace

extern "C" void MEAPI McdSphereCylinderRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeCylinder, fns);
}
