/* platform_api.cpp: the process-wide part of MdtPlatform.h over the kernel
 * tables (kernels.h). It lives in the platform layer, below Mdt, so that
 * MeViewer can set the default from `-platform` without knowing Mdt. The
 * per-world part is engine/mdt/world_platform.cpp. */
#include "MdtPlatform.h"

#include "MeAssert.h"
#include "kernels.h"

namespace platform = karma::platform;

extern "C" {

void MEAPI MdtPlatformSetDefault(const char *name) {
  platform::SetDefaultKernels(platform::KernelsForRequest(name, platform::BestSupported()));
}

const char *MEAPI MdtPlatformGetDefaultName(void) { return platform::DefaultKernels().name; }

const char *MEAPI MdtPlatformGetBestName(void) { return platform::BestSupported().name; }

MeBool MEAPI MdtPlatformIsSupported(const char *name) {
  const platform::Kernels *k = platform::FindKernels(name);
  return k && platform::Supported(*k) ? TRUE : FALSE;
}

int MEAPI MdtPlatformCount(void) { return static_cast<int>(platform::AllKernels().size()); }

const char *MEAPI MdtPlatformName(const int i) {
  ME_REQUIRE_ARG_RET(i >= 0 && i < MdtPlatformCount(), nullptr, "MdtPlatformName",
                     "backend %d does not exist (there are %d)", i, MdtPlatformCount());
  return platform::AllKernels()[static_cast<std::size_t>(i)]->name;
}

}  // extern "C"
