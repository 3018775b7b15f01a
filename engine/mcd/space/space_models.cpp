// space_models.cpp: models in a space: insert (with culling), remove,
// update (one, all), the AABB function, freezing.
//
// The AABB a space keeps for a model is taken after McdModelUpdate: the
// space's AABB function when set (McdSpaceSetAABBFn), else the model's
// cached world AABB, grown on every side by the framework's contact
// tolerance plus the model's bounds padding (McdModelSetBoundsPadding):
//   min - (tolerance + padding) <= box <= max + (tolerance + padding).
// Two models whose shapes are within the contact tolerance of each other
// therefore always overlap in the space (their AABBs are within it too), so
// the pair the nearfield needs to report a touching contact exists.
// McdSpaceUpdateAll runs the core's UpdateAll, whose per-proxy callback does
// exactly that for every unfrozen model.
//
// Sort keys: the proxy's key is the model's EffectiveSortKey, handed over at
// insertion and whenever the model's key changes (RefreshSpaceSortKey).
#include "space_internal.h"

using namespace karma::mcd;

namespace karma::mcd {

void SpaceAabb(const McdSpace *s, McdModelID m, MeReal min[3], MeReal max[3]) {
  if (s->aabbFn) {
    s->aabbFn(m, min, max);
  } else {
    for (int k = 0; k < 3; ++k) {
      min[k] = m->instance.aabbMin[k];
      max[k] = m->instance.aabbMax[k];
    }
  }
  const MeReal pad = ContactTolerance(s->framework) + m->boundsPadding;
  for (int k = 0; k < 3; ++k) {
    min[k] -= pad;
    max[k] += pad;
  }
}

void RefreshSpaceSortKey(McdModel *m) {
  if (!m->space) return;
  static_cast<McdSpace *>(m->space)->core->SetKey(m->spaceIndex, static_cast<std::uint32_t>(EffectiveSortKey(m)));
}

void UpdateAndReadAabb(void *user, void *data, MeReal min[3], MeReal max[3]) {
  auto *m = static_cast<McdModelID>(user);
  McdModelUpdate(m);
  SpaceAabb(static_cast<const McdSpace *>(data), m, min, max);
}

}  // namespace karma::mcd

namespace {

MeBool Insert(McdSpaceID s, McdModelID m, McdCullingTable *table, int index, int id, bool culling, const char *fn) {
  ME_REQUIRE_ARG_RET(s != nullptr && m != nullptr, 0, fn, "space or model is NULL");
  if (m->space) {
    MeArgumentWarning(fn,
                      "the model is already in a space (%s); a model can be in one "
                      "space only: not inserted",
                      m->space == s ? "this one" : "another one");
    return 0;
  }
  ME_REQUIRE_ARG_RET(m->framework == s->framework, 0, fn, "the model belongs to another framework; not inserted");
  if (!s->core->RequireInside(fn)) return 0;
  if (!m->updated && m->instance.tm) McdModelUpdate(m);
  // Without an AABB function the space needs the model's own bounds: a
  // model never placed (no transform, or only non-finite ones) has none.
  if (!s->aabbFn && !m->updated) {
    MeArgumentWarning(fn,
                      "the model has no bounds yet (no transform, or a non-finite one; "
                      "see McdModelSetTransformPtr and McdModelUpdate): not inserted");
    return 0;
  }
  MeReal min[3], max[3];
  SpaceAabb(s, m, min, max);
  auto *t = reinterpret_cast<CullingTable *>(table);
  const ProxyId p = culling ? s->core->InsertWithCulling(m, min, max, t, index, id) : s->core->Insert(m, min, max);
  if (p == kNoProxy) return 0;
  McdModelSetSpaceData(m, s, p);
  RefreshSpaceSortKey(m);
  return 1;
}

}  // namespace

extern "C" {

MeBool MEAPI McdSpaceInsertModel(McdSpaceID s, McdModelID m) {
  return Insert(s, m, nullptr, 0, 0, false, "McdSpaceInsertModel");
}

MeBool MEAPI McdSpaceInsertModelWithCulling(McdSpaceID s, McdModelID m, McdCullingTable *table, int cullingIndex,
                                            int cullingID) {
  return Insert(s, m, table, cullingIndex, cullingID, true, "McdSpaceInsertModelWithCulling");
}

MeBool MEAPI McdSpaceRemoveModel(McdModelID m) {
  McdSpace *s = SpaceOf(m, "McdSpaceRemoveModel");
  if (!s || !s->core->Remove(m->spaceIndex)) return 0;
  McdModelSetSpaceData(m, nullptr, -1);
  return 1;
}

void MEAPI McdSpaceUpdateModel(McdModelID m) {
  static const char *fn = "McdSpaceUpdateModel";
  McdSpace *s = SpaceOf(m, fn);
  if (!s || !s->core->RequireInside(fn)) return;
  if (s->core->IsFrozen(m->spaceIndex)) {
    MeArgumentWarning(fn, "the model is frozen (unfreeze it before updating); ignored");
    return;
  }
  MeReal min[3], max[3];
  UpdateAndReadAabb(m, s, min, max);
  s->core->Update(m->spaceIndex, min, max);
}

void MEAPI McdSpaceUpdateAll(McdSpaceID s) {
  ME_REQUIRE_ARG(s != nullptr, "McdSpaceUpdateAll", "space is NULL");
  s->core->UpdateAll();
}

void MEAPI McdSpaceUpdateModels(McdSpaceID s) {
  ME_REQUIRE_ARG(s != nullptr, "McdSpaceUpdateModels", "space is NULL");
  if (!s->core->RequireInside("McdSpaceUpdateModels")) return;
  s->core->UpdateAll();
}

void MEAPI McdSpaceSetAABBFn(McdSpaceID s, McdSpaceAABBFnPtr fn) {
  ME_REQUIRE_ARG(s != nullptr, "McdSpaceSetAABBFn", "space is NULL");
  if (!s->core->RequireOutside("McdSpaceSetAABBFn")) return;
  s->aabbFn = fn;
}

MeBool MEAPI McdSpaceFreezeModel(McdModelID m) {
  McdSpace *s = SpaceOf(m, "McdSpaceFreezeModel");
  return s && s->core->Freeze(m->spaceIndex) ? 1 : 0;
}

MeBool MEAPI McdSpaceUnfreezeModel(McdModelID m) {
  McdSpace *s = SpaceOf(m, "McdSpaceUnfreezeModel");
  return s && s->core->Unfreeze(m->spaceIndex) ? 1 : 0;
}

MeBool MEAPI McdSpaceModelIsFrozen(McdModelID m) {
  if (!m || !m->space) return 0;  // a model in no space is not frozen (quietly)
  return static_cast<McdSpace *>(m->space)->core->IsFrozen(m->spaceIndex) ? 1 : 0;
}

}  // extern "C"
