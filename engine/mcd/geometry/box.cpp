// box.cpp: the box geometry, stored as half edge lengths h.
// V = 8 hx hy hz; Ixx = m (dy^2 + dz^2) / 12 = m (hy^2 + hz^2) / 3 (cyclic).
#include "shape_util.h"

using namespace karma::mcd;

namespace {

struct Box {
  McdGeometry g;
  MeVector3 half;
};

void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  OrientedBoxAABB(tm, reinterpret_cast<const Box *>(g)->half, 0, mn, mx);
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  const MeReal *h = reinterpret_cast<const Box *>(g)->half;
  *volume = 8 * h[0] * h[1] * h[2];
  MeVector3Set(com, 0, 0, 0);
  const MeReal k = *volume / 3;
  Diagonal(I, k * (h[1] * h[1] + h[2] * h[2]), k * (h[0] * h[0] + h[2] * h[2]), k * (h[0] * h[0] + h[1] * h[1]));
  return true;
}

bool GoodSize(MeReal dx, MeReal dy, MeReal dz, const char *fn) {
  ME_REQUIRE_ARG_RET(PositiveFinite(dx) && PositiveFinite(dy) && PositiveFinite(dz), false, fn,
                     "dimensions must be positive and finite, got %g x %g x %g", (double)dx, (double)dy, (double)dz);
  return true;
}

}  // namespace

const GeometryType karma::mcd::kBoxType = {"Box", nullptr, Aabb, Mass};

extern "C" {

McdBoxID MEAPI McdBoxCreate(McdFrameworkID fw, MeReal dx, MeReal dy, MeReal dz) {
  static const char *fn = "McdBoxCreate";
  if (!GoodSize(dx, dy, dz, fn)) return nullptr;
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeBox, sizeof(Box), fn);
  if (g) MeVector3Set(reinterpret_cast<Box *>(g)->half, dx / 2, dy / 2, dz / 2);
  return g;
}

void MEAPI McdBoxGetDimensions(McdBoxID g, MeReal *dx, MeReal *dy, MeReal *dz) {
  auto *b = As<Box>(g, kMcdGeometryTypeBox, "McdBoxGetDimensions");
  if (dx) *dx = b ? 2 * b->half[0] : 0;
  if (dy) *dy = b ? 2 * b->half[1] : 0;
  if (dz) *dz = b ? 2 * b->half[2] : 0;
}

void MEAPI McdBoxGetRadii(McdBoxID g, MeVector3 radii) {
  auto *b = As<Box>(g, kMcdGeometryTypeBox, "McdBoxGetRadii");
  if (b)
    MeVector3Copy(radii, b->half);
  else
    MeVector3Set(radii, 0, 0, 0);
}

void MEAPI McdBoxSetDimensions(McdBoxID g, MeReal dx, MeReal dy, MeReal dz) {
  static const char *fn = "McdBoxSetDimensions";
  auto *b = As<Box>(g, kMcdGeometryTypeBox, fn);
  if (b && GoodSize(dx, dy, dz, fn)) {
    MeVector3Set(b->half, dx / 2, dy / 2, dz / 2);
    ShapeChanged(g);
  }
}

}  // extern "C"
