// instance.cpp: geometry instances: building a model's instance tree,
// releasing it, placing it in the world, and the public instance functions.
//
// A child's world TM = its element's relTM composed with the parent's world
// TM ("apply relTM, then the parent's"); it is written to the child's user
// TM pointer when one is set, else to its own storage.
#include "shape_util.h"

using namespace karma::mcd;

namespace karma::mcd {

bool BuildInstance(McdFramework *fw, McdGeometryInstance *inst, McdGeometry *g, McdModel *model,
                   McdGeometryInstance *parent) {
  std::memset(inst, 0, sizeof *inst);
  inst->geometry = g;
  inst->model = model;
  inst->parent = parent;
  inst->material = parent ? parent->material : 0;
  if (g->m_type != kMcdGeometryTypeAggregate) return true;
  auto *a = reinterpret_cast<McdAggregateData *>(g);
  if (a->count == 0) return true;
  inst->children = static_cast<McdGeometryInstance **>(
      MeMemoryAPI.createZeroed(sizeof(McdGeometryInstance *) * (std::size_t)a->count));
  if (!inst->children) return false;
  for (int i = 0; i < a->count; ++i) {
    auto *child = static_cast<McdGeometryInstance *>(MePoolGetStruct(&fw->instances));
    if (!child) {
      ReleaseInstance(fw, inst);
      return false;
    }
    inst->children[inst->childCount++] = child;
    if (!BuildInstance(fw, child, a->elements[i], model, inst)) {
      ReleaseInstance(fw, inst);
      return false;
    }
    child->tm = child->ownTM;
    MeMatrix4TMMakeIdentity(child->ownTM);
  }
  return true;
}

void ReleaseInstance(McdFramework *fw, McdGeometryInstance *inst) {
  for (int i = 0; i < inst->childCount; ++i) {
    ReleaseInstance(fw, inst->children[i]);
    MePoolPutStruct(&fw->instances, inst->children[i]);
  }
  MeMemoryAPI.destroy(inst->children);
  inst->children = nullptr;
  inst->childCount = 0;
}

void PlaceInstance(McdGeometryInstance *inst, MECONSTMATRIX MeMatrix4 tm) {
  if (inst->parent && inst->tm != tm) MeMatrix4Copy(inst->tm, tm);
  if (inst->childCount == 0) {
    TypeOf(inst->geometry)->aabb(inst->geometry, tm, inst->aabbMin, inst->aabbMax);
    return;
  }
  auto *a = reinterpret_cast<McdAggregateData *>(inst->geometry);
  MeVector3Set(inst->aabbMin, MEINFINITY, MEINFINITY, MEINFINITY);
  MeVector3Set(inst->aabbMax, -MEINFINITY, -MEINFINITY, -MEINFINITY);
  for (int i = 0; i < inst->childCount; ++i) {
    McdGeometryInstance *child = inst->children[i];
    MeMatrix4 world;
    MeMatrix4TMCompose(world, a->relTMs[i], tm);
    PlaceInstance(child, world);
    for (int j = 0; j < 3; ++j) {
      inst->aabbMin[j] = std::fmin(inst->aabbMin[j], child->aabbMin[j]);
      inst->aabbMax[j] = std::fmax(inst->aabbMax[j], child->aabbMax[j]);
    }
  }
}

}  // namespace karma::mcd

extern "C" {

McdGeometryID MEAPI McdGeometryInstanceGetGeometry(McdGeometryInstanceID inst) {
  return inst ? inst->geometry : nullptr;
}

int MEAPI McdGeometryInstanceGetChildCount(McdGeometryInstanceID inst) { return inst ? inst->childCount : 0; }

McdGeometryInstanceID MEAPI McdGeometryInstanceGetChild(McdGeometryInstanceID inst, int i) {
  static const char *fn = "McdGeometryInstanceGetChild";
  ME_REQUIRE_ARG_RET(inst != nullptr, nullptr, fn, "instance is NULL");
  ME_REQUIRE_ARG_RET(i >= 0 && i < inst->childCount, nullptr, fn, "child %d out of range [0, %d)", i, inst->childCount);
  return inst->children[i];
}

void MEAPI McdGeometryInstanceSetTransformPtr(McdGeometryInstanceID inst, MeMatrix4Ptr tm) {
  static const char *fn = "McdGeometryInstanceSetTransformPtr";
  ME_REQUIRE_ARG(inst != nullptr, fn, "instance is NULL");
  if (!inst->parent) {  // a model's top instance: the model's TM pointer
    McdModelSetTransformPtr(inst->model, tm);
    return;
  }
  ME_REQUIRE_ARG(tm != nullptr, fn, "a child instance needs a transform pointer");
  MeMatrix4Copy(tm, inst->tm);
  inst->tm = tm;
}

MeMatrix4Ptr MEAPI McdGeometryInstanceGetTransformPtr(McdGeometryInstanceID inst) { return inst ? inst->tm : nullptr; }

void MEAPI McdGeometryInstanceGetAABB(McdGeometryInstanceID inst, MeVector3 mn, MeVector3 mx) {
  ME_REQUIRE_ARG(inst != nullptr, "McdGeometryInstanceGetAABB", "instance is NULL");
  MeVector3Copy(mn, inst->aabbMin);
  MeVector3Copy(mx, inst->aabbMax);
}

void MEAPI McdGeometryInstanceSetMaterial(McdGeometryInstanceID inst, int material) {
  ME_REQUIRE_ARG(inst != nullptr, "McdGeometryInstanceSetMaterial", "instance is NULL");
  inst->material = material;
}

int MEAPI McdGeometryInstanceGetMaterial(McdGeometryInstanceID inst) { return inst ? inst->material : 0; }

}  // extern "C"
