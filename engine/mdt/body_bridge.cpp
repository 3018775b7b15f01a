// body_bridge.cpp: the bridge's accessors (bridge/mdt_bridge.h) and the
// world's body-enable callback.
#include "bridge/mdt_bridge.h"
#include "MeMessage.h"
#include "mdt_internal.h"

using karma::mdt::liveBody;

extern "C" {

MeReal *MEAPI MdtBodyGetLinearVelocityPtr(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetLinearVelocityPtr")) return nullptr;
  return body->velocity;
}

MeReal *MEAPI MdtBodyGetAngularVelocityPtr(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetAngularVelocityPtr")) return nullptr;
  return body->angularVelocity;
}

void MEAPI MdtBodySetCollisionModel(const MdtBodyID body, void *model) {
  if (!liveBody(body, "MdtBodySetCollisionModel")) return;
  body->collisionModel = model;
}

void *MEAPI MdtBodyGetCollisionModel(const MdtBodyID body) { return body ? body->collisionModel : nullptr; }

void MEAPI MdtWorldSetBodyEnableCallback(const MdtWorldID world, MdtBodyEnableCallbackPtr cb, void *data) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetBodyEnableCallback", "world is NULL");
  world->priv->bodyEnableCB = cb;
  world->priv->bodyEnableData = data;
}

void MEAPI MdtWorldSetBodyDestroyCallback(MdtWorldID world, MdtBodyDestroyCallbackPtr cb) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetBodyDestroyCallback", "world is NULL");
  world->priv->bodyDestroyCB = cb;
}

MdtBodyEnableCallbackPtr MEAPI MdtWorldGetBodyEnableCallback(const MdtWorldID world, void **data) {
  ME_REQUIRE_ARG_RET(world != nullptr, nullptr, "MdtWorldGetBodyEnableCallback", "world is NULL");
  if (data) *data = world->priv->bodyEnableData;
  return world->priv->bodyEnableCB;
}

}  // extern "C"
