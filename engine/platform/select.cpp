/* select.cpp: which backends exist, which the CPU can run, and the choice
 * of one (kernels.h). */
#include "MeMessage.h"
#include "backends.h"

#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace karma::platform {
namespace {

constexpr std::array<const Kernels *, 4> kAll = {&kReferenceKernels, &kSse4Kernels, &kAvx2Kernels, &kAvx512Kernels};

/* The CPU feature a backend needs. __builtin_cpu_supports reads CPUID
 * and, for the AVX families, whether the operating system saves their
 * registers (XGETBV), so a "yes" means the instructions can run. */
bool CpuHas(const Kernels &k) {
  if (&k == &kReferenceKernels) return true;
  if (&k == &kSse4Kernels) return __builtin_cpu_supports("sse4.2");
  if (&k == &kAvx2Kernels) return __builtin_cpu_supports("avx2");
  if (&k == &kAvx512Kernels) return __builtin_cpu_supports("avx512f");
  return false;
}

/* Why `name` cannot be used, or nullptr when it can. */
const char *Refusal(const char *name) {
  const Kernels *k = FindKernels(name);
  if (!k) return "there is no backend by that name (reference, sse4, avx2, avx512)";
  if (!Supported(*k)) return "this CPU does not support it";
  return nullptr;
}

const Kernels &ChooseDefault() {
  const char *requested = std::getenv("KARMA_PLATFORM");
  if (!requested || !*requested) return BestSupported();
  return KernelsForRequest(requested, BestSupported());
}

}  // namespace

std::span<const Kernels *const> AllKernels() { return kAll; }

const Kernels *FindKernels(const char *name) {
  if (!name) return nullptr;
  for (const Kernels *k : kAll)
    if (std::strcmp(k->name, name) == 0) return k;
  return nullptr;
}

bool Supported(const Kernels &kernels) { return CpuHas(kernels); }

const Kernels &BestSupported() {
  const Kernels *best = &kReferenceKernels;
  for (const Kernels *k : kAll)
    if (Supported(*k)) best = k;
  return *best;
}

const Kernels &KernelsForRequest(const char *name, const Kernels &fallback) {
  if (const char *why = Refusal(name)) {
    MeWarning(0, "platform backend '%s' is not available (%s): using '%s'", name ? name : "(null)", why, fallback.name);
    return fallback;
  }
  return *FindKernels(name);
}

/* The process default: chosen from KARMA_PLATFORM the first time it is
 * needed (a function-local static, so the choice runs once even when two
 * threads ask first), replaced by SetDefaultKernels. Acquire/release pairs
 * the store of a table pointer with the loads of its entries. */
std::atomic<const Kernels *> &DefaultSlot() {
  static std::atomic<const Kernels *> slot{&ChooseDefault()};
  return slot;
}

const Kernels &DefaultKernels() { return *DefaultSlot().load(std::memory_order_acquire); }

void SetDefaultKernels(const Kernels &kernels) { DefaultSlot().store(&kernels, std::memory_order_release); }

}  // namespace karma::platform
