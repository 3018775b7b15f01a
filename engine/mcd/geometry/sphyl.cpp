// sphyl.cpp: the sphyl (capsule): points within r of the z segment
// [-h/2, h/2]. With mc = pi r^2 h and ms = 4/3 pi r^3 (density 1):
//   V   = mc + ms
//   Izz = mc r^2/2 + ms 2r^2/5
//   Ixx = mc (h^2/12 + r^2/4) + ms (2r^2/5 + h^2/4 + 3hr/8)
// (each hemisphere's centre of mass is 3r/8 beyond the segment's end; the
// parallel-axis shifts of the two caps combine into the last two terms).
#include "shape_util.h"

using namespace karma::mcd;

namespace {

struct Sphyl {
  McdGeometry g;
  MeReal radius;
  MeReal height;
};

void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  auto *s = reinterpret_cast<const Sphyl *>(g);
  const MeVector3 half = {0, 0, s->height / 2};
  OrientedBoxAABB(tm, half, s->radius, mn, mx);
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  auto *s = reinterpret_cast<const Sphyl *>(g);
  const MeReal r = s->radius, h = s->height;
  const MeReal mc = ME_PI * r * r * h, ms = (MeReal)4 / 3 * ME_PI * r * r * r;
  *volume = mc + ms;
  MeVector3Set(com, 0, 0, 0);
  const MeReal side = mc * (h * h / 12 + r * r / 4) + ms * ((MeReal)0.4 * r * r + h * h / 4 + 3 * h * r / 8);
  Diagonal(I, side, side, mc * r * r / 2 + ms * (MeReal)0.4 * r * r);
  return true;
}

}  // namespace

const GeometryType karma::mcd::kSphylType = {"Sphyl", nullptr, Aabb, Mass};

extern "C" {

McdSphylID MEAPI McdSphylCreate(McdFrameworkID fw, MeReal radius, MeReal height) {
  static const char *fn = "McdSphylCreate";
  ME_REQUIRE_ARG_RET(PositiveFinite(radius) && PositiveFinite(height, true), nullptr, fn,
                     "radius must be positive and height >= 0, both finite; got %g and %g", (double)radius,
                     (double)height);
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeSphyl, sizeof(Sphyl), fn);
  if (g) {
    reinterpret_cast<Sphyl *>(g)->radius = radius;
    reinterpret_cast<Sphyl *>(g)->height = height;
  }
  return g;
}

MeReal MEAPI McdSphylGetRadius(McdSphylID g) {
  auto *s = As<Sphyl>(g, kMcdGeometryTypeSphyl, "McdSphylGetRadius");
  return s ? s->radius : 0;
}

MeReal MEAPI McdSphylGetHeight(McdSphylID g) {
  auto *s = As<Sphyl>(g, kMcdGeometryTypeSphyl, "McdSphylGetHeight");
  return s ? s->height : 0;
}

void MEAPI McdSphylSetRadius(McdSphylID g, MeReal radius) {
  static const char *fn = "McdSphylSetRadius";
  auto *s = As<Sphyl>(g, kMcdGeometryTypeSphyl, fn);
  if (!s) return;
  ME_REQUIRE_ARG(PositiveFinite(radius), fn, "radius must be positive and finite, got %g", (double)radius);
  s->radius = radius;
  ShapeChanged(g);
}

void MEAPI McdSphylSetHeight(McdSphylID g, MeReal height) {
  static const char *fn = "McdSphylSetHeight";
  auto *s = As<Sphyl>(g, kMcdGeometryTypeSphyl, fn);
  if (!s) return;
  ME_REQUIRE_ARG(PositiveFinite(height, true), fn, "height must be finite and >= 0, got %g", (double)height);
  s->height = height;
  ShapeChanged(g);
}

}  // extern "C"
