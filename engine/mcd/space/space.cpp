// space.cpp: creating and destroying spaces, change blocks, Build, the
// model iterator and user data.
#include "space_internal.h"

#include <new>

using namespace karma::mcd;

#define SPACE_OR_RETURN(s, fn) ME_REQUIRE_ARG((s) != nullptr, fn, "space is NULL")
#define SPACE_OR_RETURN_VALUE(s, v, fn) ME_REQUIRE_ARG_RET((s) != nullptr, v, fn, "space is NULL")

namespace karma::mcd {

McdSpace *SpaceOf(McdModelID model, const char *fn) {
  if (!model) {
    MeArgumentWarning(fn, "model is NULL");
    return nullptr;
  }
  if (!model->space) {
    MeArgumentWarning(fn, "the model is not in a space");
    return nullptr;
  }
  return static_cast<McdSpace *>(model->space);
}

// Adds McdModelPairs until there is one per pair record.
void GrowPairs(McdSpace *s) {
  while ((int)s->pairs.size() < s->core->PairCapacity()) {
    s->pairs.emplace_back();
    s->pairs.back().m_spaceIndex = -1;
  }
}

void InitHelloPairs(McdSpace *s) {
  GrowPairs(s);
  for (PairRecord *r : s->core->Hellos()) {
    McdModelPair *p = &s->pairs[(std::size_t)r->index];
    if (p->m_helloed) McdGoodbye(p);  // the last user never said goodbye
    *p = McdModelPair{};
    p->model1 = static_cast<McdModelID>(r->userA);
    p->model2 = static_cast<McdModelID>(r->userB);
    p->m_spaceData = s;
    p->m_spaceIndex = r->index;
  }
}

}  // namespace karma::mcd

extern "C" {

McdSpaceID MEAPI McdSpaceAxisSortCreate(McdFrameworkID fw, int axes, int objectCount, int pairCount) {
  static const char *fn = "McdSpaceAxisSortCreate";
  ME_REQUIRE_ARG_RET(fw != nullptr, nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG_RET(objectCount >= 1 && pairCount >= 1, nullptr, fn,
                     "objectCount (%d) and pairCount (%d) must be at least 1", objectCount, pairCount);
  ME_REQUIRE_ARG_RET(axes >= 1 && axes <= McdAllAxes, nullptr, fn,
                     "axes (%d) must be a non-empty combination of McdXAxis, McdYAxis, "
                     "McdZAxis",
                     axes);
  void *mem = MeMemoryAPI.createZeroed(sizeof(McdSpace));
  if (!mem) return nullptr;
  auto *s = new (mem) McdSpace{};
  s->framework = fw;
  ++fw->spaceCount;
  s->pairCount = pairCount;
  s->core = AxisSortSpace::Create(axes, objectCount, pairCount);
  if (!s->core) {
    McdSpaceDestroy(s);
    return nullptr;
  }
  GrowPairs(s);
  s->core->SetKeepFrozenPairs(true);
  // The AABB callback can only be set outside a block; the new space is
  // empty, so leaving and re-entering its first block changes nothing.
  s->core->EndChanges();
  s->core->SetAabbFn(UpdateAndReadAabb, s);
  s->core->BeginChanges();
  return s;
}

void MEAPI McdSpaceDestroy(McdSpaceID s) {
  if (!s) return;
  if (s->core) {
    for (ProxyId id = s->core->NextProxy(kNoProxy); id != kNoProxy; id = s->core->NextProxy(id))
      McdModelSetSpaceData(static_cast<McdModelID>(s->core->ProxyUser(id)), nullptr, -1);
    AxisSortSpace::Destroy(s->core);
  }
  for (McdModelPair &p : s->pairs)
    if (p.m_helloed) McdGoodbye(&p);
  if (s->framework) --s->framework->spaceCount;
  s->~McdSpace();
  MeMemoryAPI.destroy(s);
}

McdFrameworkID MEAPI McdSpaceGetFramework(McdSpaceID s) { return s ? s->framework : nullptr; }

void MEAPI McdSpaceBeginChanges(McdSpaceID s) {
  SPACE_OR_RETURN(s, "McdSpaceBeginChanges");
  s->core->BeginChanges();
}

void MEAPI McdSpaceEndChanges(McdSpaceID s) {
  SPACE_OR_RETURN(s, "McdSpaceEndChanges");
  if (!s->core->RequireInside("McdSpaceEndChanges")) return;
  s->core->EndChanges();
  InitHelloPairs(s);
}

int MEAPI McdSpaceIsChanging(McdSpaceID s) {
  SPACE_OR_RETURN_VALUE(s, 0, "McdSpaceIsChanging");
  return s->core->IsChanging() ? 1 : 0;
}

void MEAPI McdSpaceBuild(McdSpaceID s) {
  SPACE_OR_RETURN(s, "McdSpaceBuild");
  s->core->Build();
}

void MEAPI McdSpaceSetKeepFrozenPairs(McdSpaceID s, MeBool keep) {
  SPACE_OR_RETURN(s, "McdSpaceSetKeepFrozenPairs");
  s->core->SetKeepFrozenPairs(keep != 0);
}

int MEAPI McdSpaceGetModelCount(McdSpaceID s) {
  SPACE_OR_RETURN_VALUE(s, 0, "McdSpaceGetModelCount");
  return s->core->ProxyCount();
}

void MEAPI McdSpaceModelIteratorBegin(McdSpaceID s, McdSpaceModelIterator *iter) {
  static const char *fn = "McdSpaceModelIteratorBegin";
  SPACE_OR_RETURN(s, fn);
  ME_REQUIRE_ARG(iter != nullptr, fn, "iterator is NULL");
  iter->cursor = kNoProxy;
}

MeBool MEAPI McdSpaceGetModel(McdSpaceID s, McdSpaceModelIterator *iter, McdModelID *model) {
  static const char *fn = "McdSpaceGetModel";
  if (model) *model = nullptr;
  SPACE_OR_RETURN_VALUE(s, 0, fn);
  ME_REQUIRE_ARG_RET(iter != nullptr && model != nullptr, 0, fn, "iterator or model is NULL");
  const ProxyId next = s->core->NextProxy(iter->cursor);
  if (next == kNoProxy) return 0;
  iter->cursor = next;
  *model = static_cast<McdModelID>(s->core->ProxyUser(next));
  return 1;
}

void MEAPI McdSpaceSetUserData(McdSpaceID s, void *data) {
  SPACE_OR_RETURN(s, "McdSpaceSetUserData");
  s->core->SetUserData(data);
}

void *MEAPI McdSpaceGetUserData(McdSpaceID s) { return s ? s->core->UserData() : nullptr; }

}  // extern "C"
