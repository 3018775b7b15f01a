// world_platform.cpp: MdtWorldSetPlatform / MdtWorldGetPlatformName, a
// world's choice of platform backend (the kernel tables of kernels.h; the
// process default is engine/platform/platform_api.cpp).
#include "MeMessage.h"
#include "kernels.h"
#include "mdt_internal.h"

namespace platform = karma::platform;

extern "C" {

void MEAPI MdtWorldSetPlatform(const MdtWorldID world, const char *name) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetPlatform", "world is NULL");
  world->priv->kernels = &platform::KernelsForRequest(name, platform::BestSupported());
}

const char *MEAPI MdtWorldGetPlatformName(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, nullptr, "MdtWorldGetPlatformName", "world is NULL");
  return world->priv->kernels->name;
}

}  // extern "C"
