// model.cpp: creating and destroying models, and their plain properties
// (geometry, transform pointers, material, user data, sort keys, bounds
// padding, body handle, velocity pointers, space slots).
//
// Invariants: a live model is a used struct of its framework's model pool;
// it holds one reference to its geometry; instance.parent == NULL and
// instance.model == the model.
#include "mcd_internal.h"

#include <cstring>

using namespace karma::mcd;

namespace karma::mcd {

MeI32 EffectiveSortKey(const McdModel *m) { return m->sortKeySet ? m->sortKey : m->inheritedSortKey; }

}  // namespace karma::mcd

#define MODEL_OR_RETURN(m, fn) ME_REQUIRE_ARG((m) != nullptr, fn, "model is NULL")
#define MODEL_OR_RETURN_VALUE(m, v, fn) ME_REQUIRE_ARG_RET((m) != nullptr, v, fn, "model is NULL")

extern "C" {

McdModelID MEAPI McdModelCreate(McdGeometryID g) {
  static const char *fn = "McdModelCreate";
  ME_REQUIRE_ARG_RET(g != nullptr, nullptr, fn, "geometry is NULL");
  McdFramework *fw = g->m_framework;
  auto *m = static_cast<McdModel *>(MePoolGetStruct(&fw->models));
  if (!m) return nullptr;
  std::memset(m, 0, sizeof *m);
  m->framework = fw;
  m->spaceIndex = -1;
  if (!BuildInstance(fw, &m->instance, g, m, nullptr)) {
    MeArgumentWarning(fn,
                      "the framework's geometry instance pool (%d) is too small for this "
                      "aggregate; raise McdInit's instanceCount",
                      MePoolGetMaxCount(&fw->instances));
    MePoolPutStruct(&fw->models, m);
    return nullptr;
  }
  ++g->m_refCount;
  return m;
}

void MEAPI McdModelDestroy(McdModelID m) {
  if (!m) return;
  McdFramework *fw = m->framework;
  // The space holds the model (its pairs and proxy name it): destroying it
  // there would leave them pointing at freed memory.
  if (m->space) {
    MeArgumentWarning("McdModelDestroy",
                      "the model is still in a space; remove it from the space (McdSpaceRemoveModel) "
                      "first: not destroyed");
    return;
  }
  --m->instance.geometry->m_refCount;
  ReleaseInstance(fw, &m->instance);
  MePoolPutStruct(&fw->models, m);
}

McdGeometryID MEAPI McdModelGetGeometry(McdModelID m) { return m ? m->instance.geometry : nullptr; }

McdGeometryInstanceID MEAPI McdModelGetGeometryInstance(McdModelID m) { return m ? &m->instance : nullptr; }

McdFrameworkID MEAPI McdModelGetFramework(McdModelID m) { return m ? m->framework : nullptr; }

void MEAPI McdModelSetTransformPtr(McdModelID m, MeMatrix4Ptr tm) {
  MODEL_OR_RETURN(m, "McdModelSetTransformPtr");
  m->instance.tm = tm;
  m->relTM = nullptr;
  m->linkTM = nullptr;
}

MeMatrix4Ptr MEAPI McdModelGetTransformPtr(McdModelID m) { return m ? m->instance.tm : nullptr; }

void MEAPI McdModelSetRelativeTransformPtrs(McdModelID m, MeMatrix4Ptr relTM, MeMatrix4Ptr linkTM,
                                            MeMatrix4Ptr globalTM) {
  static const char *fn = "McdModelSetRelativeTransformPtrs";
  MODEL_OR_RETURN(m, fn);
  if (!relTM) {
    m->relTM = nullptr;
    m->linkTM = nullptr;
    if (globalTM) m->instance.tm = globalTM;
    return;
  }
  ME_REQUIRE_ARG(linkTM != nullptr && globalTM != nullptr, fn, "linkTM or globalTM is NULL");
  ME_REQUIRE_ARG(globalTM != relTM && globalTM != linkTM, fn, "globalTM must be distinct from relTM and linkTM");
  m->relTM = relTM;
  m->linkTM = linkTM;
  m->instance.tm = globalTM;
}

MeMatrix4Ptr MEAPI McdModelGetRelativeTransformPtr(McdModelID m) { return m ? m->relTM : nullptr; }

void MEAPI McdModelSetUpdateCallback(McdModelID m, McdModelUpdateCallback callback) {
  MODEL_OR_RETURN(m, "McdModelSetUpdateCallback");
  m->callback = callback;
}

McdModelUpdateCallback MEAPI McdModelGetUpdateCallback(McdModelID m) { return m ? m->callback : nullptr; }

void MEAPI McdModelSetMaterial(McdModelID m, int material) {
  MODEL_OR_RETURN(m, "McdModelSetMaterial");
  m->instance.material = material;
}

int MEAPI McdModelGetMaterial(McdModelID m) { return m ? m->instance.material : 0; }

void MEAPI McdModelSetUserData(McdModelID m, void *data) {
  MODEL_OR_RETURN(m, "McdModelSetUserData");
  m->userData = data;
}

void *MEAPI McdModelGetUserData(McdModelID m) { return m ? m->userData : nullptr; }

void MEAPI McdModelSetSortKey(McdModelID m, int key) {
  static const char *fn = "McdModelSetSortKey";
  MODEL_OR_RETURN(m, fn);
  ME_REQUIRE_ARG(key >= 0 && key <= 32767, fn, "sort key %d outside [0, 32767]", key);
  m->sortKey = key;
  m->sortKeySet = 1;
  RefreshSpaceSortKey(m);
}

int MEAPI McdModelGetSortKey(McdModelID m) { return m ? m->sortKey : 0; }

void MEAPI McdModelSetInheritedSortKey(McdModelID m, MeI32 key) {
  static const char *fn = "McdModelSetInheritedSortKey";
  MODEL_OR_RETURN(m, fn);
  ME_REQUIRE_ARG(key >= 0, fn, "sort key %ld is negative", (long)key);
  if (m->inheritedSortKey == key) return;
  m->inheritedSortKey = key;
  if (!m->sortKeySet) RefreshSpaceSortKey(m);
}

MeI32 MEAPI McdModelGetInheritedSortKey(McdModelID m) { return m ? m->inheritedSortKey : 0; }

void MEAPI McdModelSetBoundsPadding(McdModelID m, MeReal margin) {
  static const char *fn = "McdModelSetBoundsPadding";
  MODEL_OR_RETURN(m, fn);
  ME_REQUIRE_ARG(PositiveFinite(margin, true), fn, "margin %g is negative or not finite; unchanged", (double)margin);
  m->boundsPadding = margin;
}

MeReal MEAPI McdModelGetBoundsPadding(McdModelID m) { return m ? m->boundsPadding : 0; }

// McdModelSetBody is defined by Mst (it also points the TM and velocity
// pointers at the body's); Mcd only stores the handle.
void MEAPI McdModelStoreBody(McdModelID m, MdtBodyID body) {
  MODEL_OR_RETURN(m, "McdModelStoreBody");
  m->body = body;
}

MdtBodyID MEAPI McdModelGetBody(McdModelID m) { return m ? m->body : nullptr; }

void MEAPI McdModelSetLinearVelocityPtr(McdModelID m, MeReal *v) {
  MODEL_OR_RETURN(m, "McdModelSetLinearVelocityPtr");
  m->linearVelocity = v;
}

void MEAPI McdModelSetAngularVelocityPtr(McdModelID m, MeReal *w) {
  MODEL_OR_RETURN(m, "McdModelSetAngularVelocityPtr");
  m->angularVelocity = w;
}

MeReal *MEAPI McdModelGetLinearVelocityPtr(McdModelID m) { return m ? m->linearVelocity : nullptr; }

MeReal *MEAPI McdModelGetAngularVelocityPtr(McdModelID m) { return m ? m->angularVelocity : nullptr; }

void MEAPI McdModelSetSpaceData(McdModelID m, void *space, int index) {
  MODEL_OR_RETURN(m, "McdModelSetSpaceData");
  m->space = space;
  m->spaceIndex = space ? index : -1;
}

void *MEAPI McdModelGetSpace(McdModelID m) { return m ? m->space : nullptr; }

int MEAPI McdModelGetSpaceIndex(McdModelID m) { return m ? m->spaceIndex : -1; }

}  // extern "C"
