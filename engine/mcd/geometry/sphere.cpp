// sphere.cpp: the sphere geometry. V = 4/3 pi r^3, I = 2/5 m r^2.
#include "shape_util.h"

using namespace karma::mcd;

namespace {

struct Sphere {
  McdGeometry g;
  MeReal radius;
};

void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  const MeReal r = reinterpret_cast<const Sphere *>(g)->radius;
  const MeVector3 zero = {0, 0, 0};
  OrientedBoxAABB(tm, zero, r, mn, mx);
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  const MeReal r = reinterpret_cast<const Sphere *>(g)->radius;
  *volume = (MeReal)4 / 3 * ME_PI * r * r * r;
  MeVector3Set(com, 0, 0, 0);
  const MeReal i = (MeReal)0.4 * *volume * r * r;
  Diagonal(I, i, i, i);
  return true;
}

}  // namespace

const GeometryType karma::mcd::kSphereType = {"Sphere", nullptr, Aabb, Mass};

extern "C" {

McdSphereID MEAPI McdSphereCreate(McdFrameworkID fw, MeReal radius) {
  static const char *fn = "McdSphereCreate";
  ME_REQUIRE_ARG_RET(PositiveFinite(radius), nullptr, fn, "radius must be positive and finite, got %g", (double)radius);
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeSphere, sizeof(Sphere), fn);
  if (g) reinterpret_cast<Sphere *>(g)->radius = radius;
  return g;
}

MeReal MEAPI McdSphereGetRadius(McdSphereID g) {
  auto *s = As<Sphere>(g, kMcdGeometryTypeSphere, "McdSphereGetRadius");
  return s ? s->radius : 0;
}

void MEAPI McdSphereSetRadius(McdSphereID g, MeReal radius) {
  static const char *fn = "McdSphereSetRadius";
  auto *s = As<Sphere>(g, kMcdGeometryTypeSphere, fn);
  if (!s) return;
  ME_REQUIRE_ARG(PositiveFinite(radius), fn, "radius must be positive and finite, got %g", (double)radius);
  s->radius = radius;
  ShapeChanged(g);
}

}  // extern "C"
