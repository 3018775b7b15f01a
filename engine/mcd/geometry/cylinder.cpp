// cylinder.cpp: the cylinder geometry, axis z, radius r, full height h.
// V = pi r^2 h; Izz = m r^2 / 2; Ixx = Iyy = m (3 r^2 + h^2) / 12.
// AABB: along world axis j the axis (row 2 of the TM) reaches |a_j| h/2 and
// the end discs reach r sqrt(1 - a_j^2), computed as r sqrt(a_k^2 + a_l^2)
// (k, l the other two axes; equal for a unit axis, and free of the
// cancellation that 1 - a_j^2 suffers when a_j is near 1).
#include "shape_util.h"

using namespace karma::mcd;

namespace {

struct Cylinder {
  McdGeometry g;
  MeReal radius;
  MeReal height;
};

void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  auto *c = reinterpret_cast<const Cylinder *>(g);
  for (int j = 0; j < 3; ++j) {
    const MeReal a = tm[2][j];
    const MeReal ak = tm[2][(j + 1) % 3], al = tm[2][(j + 2) % 3];
    const MeReal disc = std::sqrt(ak * ak + al * al);
    const MeReal e = std::fabs(a) * c->height / 2 + c->radius * disc;
    mn[j] = tm[3][j] - e;
    mx[j] = tm[3][j] + e;
  }
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  auto *c = reinterpret_cast<const Cylinder *>(g);
  const MeReal r = c->radius, h = c->height;
  *volume = ME_PI * r * r * h;
  MeVector3Set(com, 0, 0, 0);
  const MeReal side = *volume * (3 * r * r + h * h) / 12;
  Diagonal(I, side, side, *volume * r * r / 2);
  return true;
}

}  // namespace

const GeometryType karma::mcd::kCylinderType = {"Cylinder", nullptr, Aabb, Mass};

extern "C" {

McdCylinderID MEAPI McdCylinderCreate(McdFrameworkID fw, MeReal radius, MeReal height) {
  static const char *fn = "McdCylinderCreate";
  ME_REQUIRE_ARG_RET(PositiveFinite(radius) && PositiveFinite(height), nullptr, fn,
                     "radius and height must be positive and finite, got %g and %g", (double)radius, (double)height);
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeCylinder, sizeof(Cylinder), fn);
  if (g) {
    reinterpret_cast<Cylinder *>(g)->radius = radius;
    reinterpret_cast<Cylinder *>(g)->height = height;
  }
  return g;
}

MeReal MEAPI McdCylinderGetRadius(McdCylinderID g) {
  auto *c = As<Cylinder>(g, kMcdGeometryTypeCylinder, "McdCylinderGetRadius");
  return c ? c->radius : 0;
}

MeReal MEAPI McdCylinderGetHeight(McdCylinderID g) {
  auto *c = As<Cylinder>(g, kMcdGeometryTypeCylinder, "McdCylinderGetHeight");
  return c ? c->height : 0;
}

void MEAPI McdCylinderSetRadius(McdCylinderID g, MeReal radius) {
  static const char *fn = "McdCylinderSetRadius";
  auto *c = As<Cylinder>(g, kMcdGeometryTypeCylinder, fn);
  if (!c) return;
  ME_REQUIRE_ARG(PositiveFinite(radius), fn, "radius must be positive and finite, got %g", (double)radius);
  c->radius = radius;
  ShapeChanged(g);
}

void MEAPI McdCylinderSetHeight(McdCylinderID g, MeReal height) {
  static const char *fn = "McdCylinderSetHeight";
  auto *c = As<Cylinder>(g, kMcdGeometryTypeCylinder, fn);
  if (!c) return;
  ME_REQUIRE_ARG(PositiveFinite(height), fn, "height must be positive and finite, got %g", (double)height);
  c->height = height;
  ShapeChanged(g);
}

}  // extern "C"
