// framework.cpp: creating and destroying a collision framework.
//
// McdInit takes all framework memory at once: the type table, the
// interaction table (typeMax^2 entries), the model pool and the child
// instance pool. Nothing else is allocated per frame.
#include "contact_reuse.h"
#include "mcd_internal.h"

#include <cmath>
#include <cstring>

using namespace karma::mcd;

namespace {

void *Zeroed(std::size_t bytes) { return MeMemoryAPI.createZeroed(bytes ? bytes : 1); }

}  // namespace

namespace karma::mcd {

MeReal ContactTolerance(const McdFramework *fw) { return fw ? fw->contactTolerance : 0; }

void ShapeChanged(McdGeometry *g) {
  if (g && g->m_framework) ++g->m_framework->shapeRevision;
}

bool PositiveFinite(MeReal x, bool zeroOk) { return std::isfinite((double)x) && (zeroOk ? x >= 0 : x > 0); }

bool IsFiniteTM(MECONSTMATRIX MeMatrix4 tm) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!std::isfinite((double)tm[i][j])) return false;
  return true;
}

}  // namespace karma::mcd

extern "C" {

McdFrameworkID MEAPI McdInit(int geoTypeMaxCount, int modelCount, int instanceCount, MeReal lengthScale) {
  static const char *fn = "McdInit";
  ME_REQUIRE_ARG_RET(geoTypeMaxCount >= 0 && modelCount >= 0 && instanceCount >= 0, nullptr, fn,
                     "counts must be >= 0 (got types %d, models %d, instances %d)", geoTypeMaxCount, modelCount,
                     instanceCount);
  ME_REQUIRE_ARG_RET(PositiveFinite(lengthScale), nullptr, fn, "lengthScale must be positive and finite, got %g",
                     (double)lengthScale);
  auto *fw = static_cast<McdFramework *>(Zeroed(sizeof(McdFramework)));
  if (!fw) return nullptr;
  fw->lengthScale = lengthScale;
  fw->contactTolerance = (MeReal)1e-5 * lengthScale;
  fw->contactReuseDistance = kDefaultContactReuse * lengthScale;
  fw->typeMax = kMcdGeometryBuiltInTypes + geoTypeMaxCount;
  const std::size_t cells = (std::size_t)fw->typeMax * (std::size_t)fw->typeMax;
  fw->types = static_cast<const GeometryType **>(Zeroed(sizeof(GeometryType *) * fw->typeMax));
  fw->table = static_cast<InteractionSlot **>(Zeroed(sizeof(InteractionSlot *) * cells));
  fw->explicitEntry = static_cast<unsigned char *>(Zeroed(cells));
  const bool pools = MePoolInit(&fw->models, modelCount, (int)sizeof(McdModel), 0) &&
                     MePoolInit(&fw->instances, instanceCount, (int)sizeof(McdGeometryInstance), 0);
  if (!fw->types || !fw->table || !fw->explicitEntry || !pools) {
    McdTerm(fw);
    return nullptr;
  }
  MePoolSetName(&fw->models, "McdFramework models");
  MePoolSetName(&fw->instances, "McdFramework geometry instances");
  return fw;
}

void MEAPI McdFrameworkDestroyAllModelsAndGeometries(McdFrameworkID fw) {
  static const char *fn = "McdFrameworkDestroyAllModelsAndGeometries";
  ME_REQUIRE_ARG(fw != nullptr, fn, "framework is NULL");
  // A model in a space cannot go (McdModelDestroy); nor then can its
  // geometry, so nothing goes.
  for (void *m = MePoolGetNextUsed(&fw->models, nullptr); m; m = MePoolGetNextUsed(&fw->models, m))
    ME_REQUIRE_ARG(static_cast<McdModel *>(m)->space == nullptr, fn,
                   "a model is still in a space; remove the models from their spaces (or destroy the "
                   "spaces) first: nothing destroyed");
  // Models first (they hold references), then every geometry: the
  // reference counts no longer matter since everything goes.
  // (MePool allows putting back the struct a pass has just returned.)
  for (void *m = MePoolGetNextUsed(&fw->models, nullptr); m; m = MePoolGetNextUsed(&fw->models, m))
    McdModelDestroy(static_cast<McdModel *>(m));
  for (McdGeometry *g = fw->geometries; g; g = g->m_next)
    if (g->m_type == kMcdGeometryTypeAggregate) AggregateDropElements(g);
  while (fw->geometries) FreeGeometry(fw->geometries);
}

void MEAPI McdTerm(McdFrameworkID fw) {
  if (!fw) return;
  // A space's pairs and proxies name the framework's models and
  // interactions, and McdSpaceDestroy says goodbye through them.
  ME_REQUIRE_ARG(fw->spaceCount == 0, "McdTerm",
                 "%d space(s) made on the framework still exist; destroy them first (McdSpaceDestroy): "
                 "the framework is not freed",
                 fw->spaceCount);
  if (fw->types) McdFrameworkDestroyAllModelsAndGeometries(fw);
  MePoolDestroy(&fw->models);
  MePoolDestroy(&fw->instances);
  FreeInteractionSlots(fw);
  MeMemoryAPI.destroy(fw->explicitEntry);
  MeMemoryAPI.destroy(fw->table);
  MeMemoryAPI.destroy(fw->types);
  MeMemoryAPI.destroy(fw);
}

MeReal MEAPI McdFrameworkGetLengthScale(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetLengthScale", "framework is NULL");
  return fw->lengthScale;
}

void MEAPI McdFrameworkSetContactTolerance(McdFrameworkID fw, MeReal tolerance) {
  static const char *fn = "McdFrameworkSetContactTolerance";
  ME_REQUIRE_ARG(fw != nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG(PositiveFinite(tolerance, true), fn, "tolerance must be finite and >= 0, got %g", (double)tolerance);
  fw->contactTolerance = tolerance;
}

void MEAPI McdFrameworkSetContactReuseDistance(McdFrameworkID fw, MeReal distance) {
  static const char *fn = "McdFrameworkSetContactReuseDistance";
  ME_REQUIRE_ARG(fw != nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG(PositiveFinite(distance, true), fn, "distance must be finite and >= 0, got %g", (double)distance);
  fw->contactReuseDistance = distance;
}

MeReal MEAPI McdFrameworkGetContactReuseDistance(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetContactReuseDistance", "framework is NULL");
  return fw->contactReuseDistance;
}

MeReal MEAPI McdFrameworkGetContactTolerance(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetContactTolerance", "framework is NULL");
  return fw->contactTolerance;
}

int MEAPI McdFrameworkGetModelCount(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetModelCount", "framework is NULL");
  return MePoolGetUsed(&fw->models);
}

int MEAPI McdFrameworkGetModelMaxCount(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetModelMaxCount", "framework is NULL");
  return MePoolGetMaxCount(&fw->models);
}

int MEAPI McdFrameworkGetGeometryCount(McdFrameworkID fw) {
  ME_REQUIRE_ARG_RET(fw != nullptr, 0, "McdFrameworkGetGeometryCount", "framework is NULL");
  return fw->geometryCount;
}

}  // extern "C"
