// model_body.cpp: joining models and bodies (McdModelSetBody,
// McdModelDynamicsReset, MstAutoSetMassProperties) and the world handlers
// that freeze and unfreeze a body's model (MstSetWorldHandlers).
#include "mdt_bridge.h"
#include "mst_internal.h"

namespace {

void MEAPI BodyEnableHandler(MdtBodyID body, MeBool enabled, void *) {
  auto model = static_cast<McdModelID>(MdtBodyGetCollisionModel(body));
  // The slot may be stale (the model was given another body or none).
  if (!model || McdModelGetBody(model) != body) return;
  auto space = static_cast<McdSpaceID>(McdModelGetSpace(model));
  if (!space) return;
  if (enabled) {
    // Frozen models are not visited before a step (step_bounds.cpp): the
    // body's sort key reaches its model here.
    McdModelSetInheritedSortKey(model, MdtBodyGetSortKey(body));
    McdSpaceUnfreezeModel(model);
  } else if (!McdSpaceModelIsFrozen(model)) {
    // Freeze it where the body came to rest (the space's AABB is from
    // before this step's integration) when the space allows an update;
    // a model at rest needs no bounds padding beyond the tolerance.
    McdModelSetBoundsPadding(model, 0);
    if (McdSpaceIsChanging(space)) McdSpaceUpdateModel(model);
    McdSpaceFreezeModel(model);
  }
}

// MdtBodyDestroy of a body that still has a model (the program destroyed
// the body alone): the model loses its contacts, leaves its space and is
// left without a body, so it neither collides with a dead pose nor drives
// the body that takes the freed slot next.
void MEAPI BodyDestroyHandler(MdtBodyID body, void *slot) {
  auto model = static_cast<McdModelID>(slot);
  if (!model || McdModelGetBody(model) != body) return;
  MeWarning(0,
            "MdtBodyDestroy: body %p was still the body of collision model %p; the model "
            "was taken out of its space and left without a body (MstModelAndBodyDestroy "
            "destroys both)",
            (void *)body, (void *)model);
  // Between steps the universe's space is in a change block; outside one
  // the removal warns and the model stays in the space, bodiless.
  if (McdModelGetSpace(model)) karma::mst::RemoveModelAndItsContacts(model, "MdtBodyDestroy");
  McdModelSetBody(model, nullptr);
}

}  // namespace

extern "C" {

void MEAPI McdModelSetBody(McdModelID model, MdtBodyID body) {
  ME_REQUIRE_ARG(model != nullptr, "McdModelSetBody", "model is NULL");
  MdtBodyID old = McdModelGetBody(model);
  if (old && MdtBodyGetCollisionModel(old) == model) MdtBodySetCollisionModel(old, nullptr);
  if (body != old) karma::mst::DropModelContactGroups(model);
  McdModelStoreBody(model, body);
  if (!body) {  // a fixed model keeps its transform pointer
    McdModelSetLinearVelocityPtr(model, nullptr);
    McdModelSetAngularVelocityPtr(model, nullptr);
    return;
  }
  McdModelSetTransformPtr(model, MdtBodyGetTransformPtr(body));
  McdModelSetLinearVelocityPtr(model, MdtBodyGetLinearVelocityPtr(body));
  McdModelSetAngularVelocityPtr(model, MdtBodyGetAngularVelocityPtr(body));
  MdtBodySetCollisionModel(body, model);
  // A frozen model (a fixed one) given an enabled body collides from now
  // on, as when the body of a model is enabled.
  if (body != old && MdtBodyIsEnabled(body) && McdSpaceModelIsFrozen(model)) BodyEnableHandler(body, TRUE, nullptr);
}

void MEAPI McdModelDynamicsReset(McdModelID model) {
  static const char *fn = "McdModelDynamicsReset";
  ME_REQUIRE_ARG(model != nullptr, fn, "model is NULL");
  MdtBodyID body = McdModelGetBody(model);
  ME_REQUIRE_ARG(body != nullptr, fn, "the model has no body");
  MdtBodySetPosition(body, 0, 0, 0);
  MdtBodySetQuaternion(body, 1, 0, 0, 0);
  MdtBodySetLinearVelocity(body, 0, 0, 0);
  MdtBodySetAngularVelocity(body, 0, 0, 0);
}

void MEAPI MstAutoSetMassProperties(MdtBodyID body, McdGeometryID geometry, MeReal density) {
  static const char *fn = "MstAutoSetMassProperties";
  ME_REQUIRE_ARG(body != nullptr && geometry != nullptr, fn, "body or geometry is NULL");
  MeReal mass = 0;
  MeMatrix3 inertia;
  MeVector3 com;
  if (!McdGeometryGetMassProperties(geometry, density, &mass, inertia, com)) {
    MeArgumentWarning(fn,
                      "the geometry has no finite volume (or the density %g is not "
                      "positive); the body's mass properties are unchanged",
                      (double)density);
    return;
  }
  MdtBodySetMass(body, mass);
  MdtBodySetInertiaTensor(body, inertia);
  MdtBodySetCenterOfMassRelativePosition(body, com);
}

void MEAPI MstSetWorldHandlers(MdtWorldID world) {
  ME_REQUIRE_ARG(world != nullptr, "MstSetWorldHandlers", "world is NULL");
  MdtWorldSetBodyEnableCallback(world, BodyEnableHandler, nullptr);
  MdtWorldSetBodyDestroyCallback(world, BodyDestroyHandler);
}

}  // extern "C"
