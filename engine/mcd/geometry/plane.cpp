// plane.cpp: the plane z = 0 of its frame, solid below. Unbounded AABB,
// except that when the normal (row 2 of the TM) lies along world axis j the
// solid side ends at the plane: max[j] = t[j] (normal +j) or min[j] = t[j]
// (normal -j). No volume.
#include "shape_util.h"

using namespace karma::mcd;

namespace {

void Aabb(const McdGeometry *, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  for (int j = 0; j < 3; ++j) {
    mn[j] = -MEINFINITY;
    mx[j] = MEINFINITY;
  }
  for (int j = 0; j < 3; ++j) {
    if (tm[2][j] == 1) mx[j] = tm[3][j];
    if (tm[2][j] == -1) mn[j] = tm[3][j];
  }
}

bool Mass(const McdGeometry *, MeReal *, MeVector3, MeMatrix3) { return false; }

}  // namespace

const GeometryType karma::mcd::kPlaneType = {"Plane", nullptr, Aabb, Mass};

extern "C" McdPlaneID MEAPI McdPlaneCreate(McdFrameworkID fw) {
  return NewGeometry(fw, kMcdGeometryTypePlane, sizeof(McdGeometry), "McdPlaneCreate");
}
