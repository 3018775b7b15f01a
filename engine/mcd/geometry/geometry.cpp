// geometry.cpp: what every geometry shares: creation bookkeeping, reference
// counts, destruction, type queries, mass properties and AABBs through the
// type record.
#include "mcd_internal.h"

#include <cstring>

using namespace karma::mcd;

namespace karma::mcd {

const GeometryType *TypeOf(const McdGeometry *g) {
  const McdFramework *fw = g->m_framework;
  if (g->m_type < 0 || g->m_type >= fw->typeMax) return nullptr;
  return fw->types[g->m_type];
}

McdGeometry *NewGeometry(McdFramework *fw, int type, std::size_t bytes, const char *fn) {
  ME_REQUIRE_ARG_RET(fw != nullptr, nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG_RET(type >= 0 && type < fw->typeMax && fw->types[type], nullptr, fn,
                     "geometry type %d is not registered in this framework "
                     "(call its Mcd*RegisterType or McdPrimitivesRegisterTypes first)",
                     type);
  auto *g = static_cast<McdGeometry *>(MeMemoryAPI.createZeroed(bytes));
  if (!g) return nullptr;
  g->m_type = type;
  g->m_framework = fw;
  g->m_next = fw->geometries;
  if (fw->geometries) fw->geometries->m_prev = g;
  fw->geometries = g;
  ++fw->geometryCount;
  return g;
}

void FreeGeometry(McdGeometry *g) {
  McdFramework *fw = g->m_framework;
  if (g->m_prev)
    g->m_prev->m_next = g->m_next;
  else
    fw->geometries = g->m_next;
  if (g->m_next) g->m_next->m_prev = g->m_prev;
  --fw->geometryCount;
  const GeometryType *t = TypeOf(g);
  if (t && t->release) t->release(g);
  MeMemoryAPI.destroy(g);
}

McdGeometry *CheckType(McdGeometry *g, int type, const char *fn) {
  ME_REQUIRE_ARG_RET(g != nullptr, nullptr, fn, "geometry is NULL");
  ME_REQUIRE_ARG_RET(g->m_type == type, nullptr, fn, "geometry is a %s, not the type this function takes",
                     McdGeometryGetTypeName(g));
  return g;
}

}  // namespace karma::mcd

extern "C" {

void MEAPI McdGeometryDestroy(McdGeometryID g) {
  if (!g) return;
  ME_REQUIRE_ARG(g->m_refCount == 0, "McdGeometryDestroy",
                 "the %s geometry is still used by %d model(s) or aggregate element(s); "
                 "destroy those first (the geometry was not destroyed)",
                 McdGeometryGetTypeName(g), g->m_refCount);
  FreeGeometry(g);
}

int MEAPI McdGeometryGetTypeId(McdGeometryID g) { return g ? g->m_type : kMcdGeometryTypeNull; }
int MEAPI McdGeometryGetType(McdGeometryID g) { return McdGeometryGetTypeId(g); }

const char *MEAPI McdGeometryGetTypeName(McdGeometryID g) {
  if (!g) return "(null)";
  const GeometryType *t = TypeOf(g);
  return t ? t->name : "(unregistered type)";
}

int MEAPI McdGeometryGetReferenceCount(McdGeometryID g) { return g ? g->m_refCount : 0; }

McdFrameworkID MEAPI McdGeometryGetFramework(McdGeometryID g) { return g ? g->m_framework : nullptr; }

void MEAPI McdGeometrySetUserData(McdGeometryID g, void *data) {
  ME_REQUIRE_ARG(g != nullptr, "McdGeometrySetUserData", "geometry is NULL");
  g->m_userData = data;
}

void *MEAPI McdGeometryGetUserData(McdGeometryID g) { return g ? g->m_userData : nullptr; }

MeBool MEAPI McdGeometryGetMassProperties(McdGeometryID g, MeReal density, MeReal *mass, MeMatrix3 inertia,
                                          MeVector3 com) {
  static const char *fn = "McdGeometryGetMassProperties";
  if (mass) *mass = 0;
  if (inertia) std::memset(inertia, 0, sizeof(MeMatrix3));
  if (com) MeVector3Set(com, 0, 0, 0);
  ME_REQUIRE_ARG_RET(g != nullptr, 0, fn, "geometry is NULL");
  ME_REQUIRE_ARG_RET(PositiveFinite(density), 0, fn, "density must be positive and finite, got %g", (double)density);
  const GeometryType *t = TypeOf(g);
  MeReal volume = 0;
  MeVector3 c;
  MeMatrix3 I;
  ME_REQUIRE_ARG_RET(t && t->mass && t->mass(g, &volume, c, I), 0, fn,
                     "a %s has no finite volume, so no mass properties", McdGeometryGetTypeName(g));
  if (mass) *mass = density * volume;
  if (com) MeVector3Copy(com, c);
  if (inertia)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inertia[i][j] = density * I[i][j];
  return 1;
}

MeReal MEAPI McdGeometryGetVolume(McdGeometryID g) {
  if (!g) return 0;
  const GeometryType *t = TypeOf(g);
  MeReal volume = 0;
  MeVector3 c;
  MeMatrix3 I;
  if (!t || !t->mass || !t->mass(g, &volume, c, I)) return 0;
  return volume;
}

void MEAPI McdGeometryGetAABB(McdGeometryID g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  static const char *fn = "McdGeometryGetAABB";
  MeVector3Set(mn, 0, 0, 0);
  MeVector3Set(mx, 0, 0, 0);
  ME_REQUIRE_ARG(g != nullptr && tm != nullptr, fn, "geometry or transform is NULL");
  const GeometryType *t = TypeOf(g);
  ME_REQUIRE_ARG(t != nullptr, fn, "geometry type is not registered");
  t->aabb(g, tm, mn, mx);
}

}  // extern "C"
