// universe.cpp: MstUniverseSizes and their defaults (Appendix A), creating,
// stepping and destroying a universe, the getters.
//
// A step: the models take their bodies' sort keys and their bounds padding
// for the step (PrepareModelsForStep, step_bounds.cpp), the space updates
// every unfrozen model's box, the bridge turns the pairs into contacts, and
// the world steps.
#include <cmath>

#include "mst_internal.h"

extern "C" {

const MstUniverseSizes MstUniverseDefaultSizes = {
    100,  // dynamicBodiesMaxCount
    500,  // dynamicConstraintsMaxCount
    0,    // collisionUserGeometryTypesMaxCount
    100,  // collisionModelsMaxCount
    500,  // collisionPairsMaxCount
    100,  // collisionGeometryInstancesMaxCount
    10,   // materialsMaxCount
    1,    // lengthScale
    1,    // massScale
};

MstUniverseID MEAPI MstUniverseCreate(const MstUniverseSizes *sizes) {
  static const char *fn = "MstUniverseCreate";
  ME_REQUIRE_ARG_RET(sizes != nullptr, nullptr, fn, "sizes is NULL");
  const MstUniverseSizes &s = *sizes;
  ME_REQUIRE_ARG_RET(s.dynamicBodiesMaxCount >= 1 && s.dynamicConstraintsMaxCount >= 0 &&
                         s.collisionUserGeometryTypesMaxCount >= 0 && s.collisionModelsMaxCount >= 1 &&
                         s.collisionPairsMaxCount >= 1 && s.collisionGeometryInstancesMaxCount >= 0 &&
                         s.materialsMaxCount >= 1,
                     nullptr, fn,
                     "bad sizes: bodies, models, pairs and materials must be at least 1, the "
                     "other counts at least 0");
  ME_REQUIRE_ARG_RET(s.lengthScale > 0 && s.massScale > 0, nullptr, fn,
                     "lengthScale (%g) and massScale (%g) must be positive", (double)s.lengthScale,
                     (double)s.massScale);
  auto *u = static_cast<MstUniverse *>(MeMemoryAPI.createZeroed(sizeof(MstUniverse)));
  if (!u) return nullptr;
  u->sizes = s;
  u->frame = McdInit(s.collisionUserGeometryTypesMaxCount, s.collisionModelsMaxCount,
                     s.collisionGeometryInstancesMaxCount, s.lengthScale);
  if (u->frame) {
    McdPrimitivesRegisterTypes(u->frame);
    McdPrimitivesRegisterInteractions(u->frame);
    u->space = McdSpaceAxisSortCreate(u->frame, McdAllAxes, s.collisionModelsMaxCount, s.collisionPairsMaxCount);
  }
  u->world = MdtWorldCreate((unsigned)s.dynamicBodiesMaxCount, (unsigned)s.dynamicConstraintsMaxCount, s.lengthScale,
                            s.massScale);
  u->bridge = MstBridgeCreate(u->frame, s.materialsMaxCount);
  if (!u->frame || !u->space || !u->world || !u->bridge) {
    MstUniverseDestroy(u);
    return nullptr;
  }
  MstSetWorldHandlers(u->world);
  return u;
}

void MEAPI MstUniverseDestroy(MstUniverseID u) {
  if (!u) return;
  // The world first (bodies and contact groups), then the space (its
  // pairs say goodbye while the models still exist), then the models and
  // geometries with the framework.
  MdtWorldDestroy(u->world);
  McdSpaceDestroy(u->space);
  if (u->frame) McdTerm(u->frame);
  MstBridgeDestroy(u->bridge);
  MeMemoryAPI.destroy(u);
}

void MEAPI MstUniverseStep(MstUniverseID u, MeReal stepSize) {
  ME_REQUIRE_ARG(u != nullptr, "MstUniverseStep", "universe is NULL");
  karma::mst::PrepareModelsForStep(u, stepSize);
  McdSpaceUpdateAll(u->space);
  MstBridgeUpdateContacts(u->bridge, u->space, u->world);
  MdtWorldStep(u->world, stepSize);
}

void MEAPI MstUniversePrepareStep(MstUniverseID u, MeReal stepSize) {
  static const char *fn = "MstUniversePrepareStep";
  ME_REQUIRE_ARG(u != nullptr, fn, "universe is NULL");
  ME_REQUIRE_ARG(std::isfinite(stepSize) && stepSize > 0, fn, "stepSize must be positive and finite, got %g; ignored",
                 (double)stepSize);
  karma::mst::PrepareModelsForStep(u, stepSize);
}

MdtWorldID MEAPI MstUniverseGetWorld(MstUniverseID u) { return u ? u->world : nullptr; }
McdSpaceID MEAPI MstUniverseGetSpace(MstUniverseID u) { return u ? u->space : nullptr; }
MstBridgeID MEAPI MstUniverseGetBridge(MstUniverseID u) { return u ? u->bridge : nullptr; }
McdFrameworkID MEAPI MstUniverseGetFramework(MstUniverseID u) { return u ? u->frame : nullptr; }

}  // extern "C"
