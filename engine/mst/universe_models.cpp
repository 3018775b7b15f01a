// universe_models.cpp: models with bodies and fixed models in a universe,
// and removing a model together with its contact groups.
#include "mst_internal.h"
#include "space/space_internal.h"

namespace karma::mst {

void DropContactGroup(McdModelPair *pair) {
  if (!pair->responseData) return;
  MdtContactGroupDestroy(static_cast<MdtContactGroupID>(pair->responseData));
  pair->responseData = nullptr;
}

bool RemoveModelAndItsContacts(McdModelID model, const char *fn) {
  auto *space = static_cast<McdSpace *>(McdModelGetSpace(model));
  if (!space) return true;
  if (!McdSpaceIsChanging(space)) {
    MeArgumentWarning(fn,
                      "the space is not in a change block (between steps it is); the "
                      "model stays, nothing is destroyed");
    return false;
  }
  for (McdModelPair &pair : space->pairs) {
    McdModelPair *p = &pair;
    if (p->model1 != model && p->model2 != model) continue;
    DropContactGroup(p);
    McdGoodbye(p);
  }
  return McdSpaceRemoveModel(model) != 0;
}

void DropModelContactGroups(McdModelID model) {
  auto *space = static_cast<McdSpace *>(McdModelGetSpace(model));
  if (!space || !McdSpaceIsChanging(space)) return;
  for (McdModelPair &pair : space->pairs)
    if (pair.model1 == model || pair.model2 == model) DropContactGroup(&pair);
}

}  // namespace karma::mst

using namespace karma::mst;

extern "C" {

McdModelID MEAPI MstModelAndBodyCreate(MstUniverseID u, McdGeometryID g, MeReal density) {
  static const char *fn = "MstModelAndBodyCreate";
  ME_REQUIRE_ARG_RET(u != nullptr && g != nullptr, nullptr, fn, "universe or geometry is NULL");
  McdModelID model = McdModelCreate(g);
  if (!model) return nullptr;
  MdtBodyID body = MdtBodyCreate(u->world);
  if (!body) {
    McdModelDestroy(model);
    return nullptr;
  }
  MstAutoSetMassProperties(body, g, density);
  McdModelSetBody(model, body);
  MdtBodyEnable(body);
  if (!McdSpaceInsertModel(u->space, model)) {
    MdtBodyDestroy(body);
    McdModelDestroy(model);
    return nullptr;
  }
  return model;
}

void MEAPI MstModelAndBodyDestroy(McdModelID model) {
  static const char *fn = "MstModelAndBodyDestroy";
  if (!model) return;
  if (!RemoveModelAndItsContacts(model, fn)) return;
  MdtBodyID body = McdModelGetBody(model);
  McdModelSetBody(model, nullptr);
  MdtBodyDestroy(body);
  McdModelDestroy(model);
}

McdModelID MEAPI MstFixedModelCreate(MstUniverseID u, McdGeometryID g, MeMatrix4Ptr tm) {
  static const char *fn = "MstFixedModelCreate";
  ME_REQUIRE_ARG_RET(u != nullptr && g != nullptr && tm != nullptr, nullptr, fn,
                     "universe, geometry or transform is NULL");
  McdModelID model = McdModelCreate(g);
  if (!model) return nullptr;
  McdModelSetTransformPtr(model, tm);
  if (!McdSpaceInsertModel(u->space, model)) {
    McdModelDestroy(model);
    return nullptr;
  }
  McdSpaceUpdateModel(model);
  McdSpaceFreezeModel(model);
  return model;
}

void MEAPI MstFixedModelDestroy(McdModelID model) {
  if (!model) return;
  if (!RemoveModelAndItsContacts(model, "MstFixedModelDestroy")) return;
  McdModelDestroy(model);
}

}  // extern "C"
