// triangle_list.cpp: the triangle list: a bounding box in its own frame and
// a user callback producing the triangles near another model. The scratch
// list follows triangleMaxCount, which programs may write directly.
#include "shape_util.h"

using namespace karma::mcd;

namespace {

void Release(McdGeometry *g) { MeMemoryAPI.destroy(reinterpret_cast<McdTriangleList *>(g)->list); }

// The local box (centre c, half extents e) placed at tm: centre c*R + t.
void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  auto *t = reinterpret_cast<const McdTriangleList *>(g);
  MeVector3 c, e;
  for (int i = 0; i < 3; ++i) {
    c[i] = (t->boxMin[i] + t->boxMax[i]) / 2;
    e[i] = (t->boxMax[i] - t->boxMin[i]) / 2;
  }
  MeMatrix4 centred;
  MeMatrix4Copy(centred, tm);
  MeMatrix4TMTransform(centred[3], tm, c);
  OrientedBoxAABB(centred, e, 0, mn, mx);
}

bool Mass(const McdGeometry *, MeReal *, MeVector3, MeMatrix3) { return false; }

bool GoodBox(const MeVector3 mn, const MeVector3 mx, const char *fn) {
  ME_REQUIRE_ARG_RET(mn && mx && MeVector3AllFinite(mn) && MeVector3AllFinite(mx), false, fn,
                     "the bounding box must be given and finite");
  ME_REQUIRE_ARG_RET(mn[0] <= mx[0] && mn[1] <= mx[1] && mn[2] <= mx[2], false, fn,
                     "the bounding box min (%g %g %g) exceeds max (%g %g %g)", (double)mn[0], (double)mn[1],
                     (double)mn[2], (double)mx[0], (double)mx[1], (double)mx[2]);
  return true;
}

McdTriangleList *Get(McdGeometry *g, const char *fn) {
  return As<McdTriangleList>(g, kMcdGeometryTypeTriangleList, fn);
}

}  // namespace

const GeometryType karma::mcd::kTriangleListType = {"TriangleList", Release, Aabb, Mass};

extern "C" {

McdTriangleListID MEAPI McdTriangleListCreate(McdFrameworkID fw, MeVector3 min, MeVector3 max, int triangleMaxCount,
                                              McdTriangleListFnPtr f) {
  static const char *fn = "McdTriangleListCreate";
  if (!GoodBox(min, max, fn)) return nullptr;
  ME_REQUIRE_ARG_RET(triangleMaxCount > 0, nullptr, fn, "triangleMaxCount must be positive, got %d", triangleMaxCount);
  ME_REQUIRE_ARG_RET(f != nullptr, nullptr, fn, "the triangle generator callback is NULL");
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeTriangleList, sizeof(McdTriangleList), fn);
  if (!g) return nullptr;
  auto *t = reinterpret_cast<McdTriangleList *>(g);
  MeVector3Copy(t->boxMin, min);
  MeVector3Copy(t->boxMax, max);
  t->triangleMaxCount = triangleMaxCount;
  t->triangleListGenerator = f;
  return g;
}

void MEAPI McdTriangleListSetMaxTriangles(McdTriangleListID g, int max) {
  static const char *fn = "McdTriangleListSetMaxTriangles";
  McdTriangleList *t = Get(g, fn);
  if (!t) return;
  ME_REQUIRE_ARG(max > 0, fn, "the maximum must be positive, got %d", max);
  t->triangleMaxCount = max;
}

int MEAPI McdTriangleListGetMaxTriangles(McdTriangleListID g) {
  McdTriangleList *t = Get(g, "McdTriangleListGetMaxTriangles");
  return t ? t->triangleMaxCount : 0;
}

void MEAPI McdTriangleListSetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max) {
  static const char *fn = "McdTriangleListSetBoundingBox";
  McdTriangleList *t = Get(g, fn);
  if (!t || !GoodBox(min, max, fn)) return;
  MeVector3Copy(t->boxMin, min);
  MeVector3Copy(t->boxMax, max);
}

void MEAPI McdTriangleListGetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max) {
  McdTriangleList *t = Get(g, "McdTriangleListGetBoundingBox");
  if (!t) return;
  MeVector3Copy(min, t->boxMin);
  MeVector3Copy(max, t->boxMax);
}

void MEAPI McdTriangleListSetGenerator(McdTriangleListID g, McdTriangleListFnPtr f) {
  static const char *fn = "McdTriangleListSetGenerator";
  McdTriangleList *t = Get(g, fn);
  if (!t) return;
  ME_REQUIRE_ARG(f != nullptr, fn, "the triangle generator callback is NULL");
  t->triangleListGenerator = f;
}

McdTriangleListFnPtr MEAPI McdTriangleListGetGenerator(McdTriangleListID g) {
  McdTriangleList *t = Get(g, "McdTriangleListGetGenerator");
  return t ? t->triangleListGenerator : nullptr;
}

void MEAPI McdTriangleListSetUserData(McdTriangleListID g, void *data) {
  McdTriangleList *t = Get(g, "McdTriangleListSetUserData");
  if (t) t->userData = data;
}

void *MEAPI McdTriangleListGetUserData(McdTriangleListID g) {
  McdTriangleList *t = Get(g, "McdTriangleListGetUserData");
  return t ? t->userData : nullptr;
}

int MEAPI McdTriangleListGetTriangles(McdTriangleListID g, struct McdModelPair *pair, MeVector3 pos, MeReal radius,
                                      McdUserTriangle **triangles) {
  static const char *fn = "McdTriangleListGetTriangles";
  if (triangles) *triangles = nullptr;
  McdTriangleList *t = Get(g, fn);
  if (!t) return 0;
  ME_REQUIRE_ARG_RET(triangles != nullptr && pos != nullptr, 0, fn, "triangles or pos is NULL");
  ME_REQUIRE_ARG_RET(t->triangleMaxCount > 0, 0, fn, "triangleMaxCount is %d; it must be positive",
                     t->triangleMaxCount);
  ME_REQUIRE_ARG_RET(t->triangleListGenerator != nullptr, 0, fn, "no generator callback");
  if (t->m_listCapacity < t->triangleMaxCount) {
    void *grown = MeMemoryAPI.resize(t->list, sizeof(McdUserTriangle) * (std::size_t)t->triangleMaxCount);
    if (!grown) return 0;
    t->list = static_cast<McdUserTriangle *>(grown);
    t->m_listCapacity = t->triangleMaxCount;
  }
  std::memset(t->list, 0, sizeof(McdUserTriangle) * (std::size_t)t->triangleMaxCount);
  int n = t->triangleListGenerator(pair, t->list, pos, radius, t->triangleMaxCount);
  if (n > t->triangleMaxCount) {
    MeArgumentWarning(fn,
                      "the triangle list callback returned %d triangles but "
                      "triangleMaxCount is %d; only the first %d are used",
                      n, t->triangleMaxCount, t->triangleMaxCount);
    n = t->triangleMaxCount;
  } else if (n < 0) {
    MeArgumentWarning(fn, "the triangle list callback returned %d; no triangles are used", n);
    n = 0;
  }
  *triangles = t->list;
  return n;
}

}  // extern "C"
