// bridge.cpp: creating bridges, the material table and its callbacks.
#include "mst_internal.h"

#include <new>

using namespace karma::mst;

namespace karma::mst {

MaterialEntry *Entry(MstBridge *b, MstMaterialID m1, MstMaterialID m2, const char *fn) {
  if (!b) {
    MeArgumentWarning(fn, "bridge is NULL");
    return nullptr;
  }
  if (m1 < 0 || m2 < 0 || m1 >= b->materialCount || m2 >= b->materialCount) {
    MeArgumentWarning(fn, "materials %d and %d: only 0 to %d are in use", m1, m2, b->materialCount - 1);
    return nullptr;
  }
  const int lo = m1 < m2 ? m1 : m2, hi = m1 < m2 ? m2 : m1;
  return &b->materials[lo * b->maxMaterials + hi];
}

}  // namespace karma::mst

extern "C" {

MstBridgeID MEAPI MstBridgeCreate(McdFrameworkID framework, const int maxMaterials) {
  static const char *fn = "MstBridgeCreate";
  ME_REQUIRE_ARG_RET(maxMaterials >= 1, nullptr, fn, "maxMaterials must be at least 1 (the default material), got %d",
                     maxMaterials);
  auto *b = static_cast<MstBridge *>(MeMemoryAPI.createZeroed(sizeof(MstBridge)));
  if (!b) return nullptr;
  const auto n = (std::size_t)maxMaterials * (std::size_t)maxMaterials;
  b->materials = static_cast<MaterialEntry *>(MeMemoryAPI.createZeroed(sizeof(MaterialEntry) * n));
  b->pairs = McdModelPairContainerCreate(kPairChunk);
  if (!b->materials || !b->pairs) {
    MstBridgeDestroy(b);
    return nullptr;
  }
  for (std::size_t i = 0; i < n; ++i) MdtContactParamsReset(&b->materials[i].params);
  b->framework = framework;
  b->maxMaterials = maxMaterials;
  b->materialCount = 1;
  return b;
}

void MEAPI MstBridgeDestroy(MstBridgeID b) {
  if (!b) return;
  McdModelPairContainerDestroy(b->pairs);
  MeMemoryAPI.destroy(b->materials);
  MeMemoryAPI.destroy(b);
}

MstMaterialID MEAPI MstBridgeGetNewMaterial(MstBridgeID b) {
  static const char *fn = "MstBridgeGetNewMaterial";
  ME_REQUIRE_ARG_RET(b != nullptr, -1, fn, "bridge is NULL");
  ME_REQUIRE_ARG_RET(b->materialCount < b->maxMaterials, -1, fn,
                     "all %d materials are in use (raise materialsMaxCount); returning -1", b->maxMaterials);
  return b->materialCount++;
}

int MEAPI MstBridgeGetMaterialCount(MstBridgeID b) { return b ? b->materialCount : 0; }

MdtContactParamsID MEAPI MstBridgeGetContactParams(MstBridgeID b, MstMaterialID m1, MstMaterialID m2) {
  MaterialEntry *e = Entry(b, m1, m2, "MstBridgeGetContactParams");
  return e ? &e->params : nullptr;
}

#define MST_CALLBACK_ACCESSORS(Name, Type, member)                                                \
  void MEAPI MstBridgeSet##Name##CB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2, Type cb) { \
    if (MaterialEntry *e = Entry(b, m1, m2, "MstBridgeSet" #Name "CB")) e->member = cb;           \
  }                                                                                               \
  Type MEAPI MstBridgeGet##Name##CB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2) {          \
    MaterialEntry *e = Entry(b, m1, m2, "MstBridgeGet" #Name "CB");                               \
    return e ? e->member : nullptr;                                                               \
  }

MST_CALLBACK_ACCESSORS(Intersect, MstIntersectCBPtr, intersectCB)
MST_CALLBACK_ACCESSORS(PerContact, MstPerContactCBPtr, perContactCB)
MST_CALLBACK_ACCESSORS(PerPair, MstPerPairCBPtr, perPairCB)

}  // extern "C"
