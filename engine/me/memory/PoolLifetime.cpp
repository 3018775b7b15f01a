// PoolLifetime.cpp: creating, naming, resetting and destroying a pool.
//
// A pool owns one block from MeMemoryAPI.createAligned laid out as
//   [maxCount structs of `stride` bytes][maxCount ints: freeStack][maxCount bytes: inUse]
// so initialisation is a single allocation and destruction a single free.
#include <cstdint>
#include <cstring>

#include "MeMemory.h"
#include "MeMessage.h"
#include "MemoryDefaults.h"
#include "PoolInternal.h"

namespace karma::me {

void poolResetFreeStack(MePool &pool) noexcept {
  // Stack top is the last element: store indices in descending order so
  // that index 0 is popped first.
  for (int k = 0; k < pool.maxCount; ++k) pool.freeStack[k] = pool.maxCount - 1 - k;
  if (pool.maxCount > 0) std::memset(pool.inUse, 0, static_cast<std::size_t>(pool.maxCount));
  pool.freeCount = pool.maxCount;
  pool.usedCount = 0;
  pool.warnedFull = FALSE;
}

namespace {

// Rounds `value` up to a multiple of the power of two `align`.
constexpr std::size_t roundUp(std::size_t value, std::size_t align) noexcept {
  return (value + align - 1) & ~(align - 1);
}

}  // namespace
}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC MeBool MEAPI MePoolInit(MePool *pool, int maxCount, int structSize, int alignment) {
  ME_REQUIRE_ARG_RET(pool != nullptr, FALSE, "MePoolInit", "pool is NULL");
  *pool = MePool{};
  ME_REQUIRE_ARG_RET(maxCount >= 0, FALSE, "MePoolInit", "maxCount is %d, must be >= 0", maxCount);
  ME_REQUIRE_ARG_RET(structSize > 0, FALSE, "MePoolInit", "structSize is %d, must be > 0", structSize);
  if (alignment == 0) alignment = static_cast<int>(alignof(std::max_align_t));
  ME_REQUIRE_ARG_RET(alignment > 0 && isPowerOfTwo(static_cast<unsigned>(alignment)), FALSE, "MePoolInit",
                     "alignment %d is not a power of two", alignment);

  const std::size_t stride = roundUp(static_cast<std::size_t>(structSize), static_cast<std::size_t>(alignment));
  const std::size_t count = static_cast<std::size_t>(maxCount);
  // Total = count * (stride + sizeof(int) + 1) + padding before the ints.
  const std::size_t perStruct = stride + sizeof(int) + 1;
  ME_REQUIRE_ARG_RET(stride <= INT32_MAX && (count == 0 || perStruct <= (SIZE_MAX - alignof(int)) / count), FALSE,
                     "MePoolInit", "%d structs of %d bytes do not fit in memory", maxCount, structSize);
  const std::size_t stackOffset = roundUp(count * stride, alignof(int));
  const std::size_t flagsOffset = stackOffset + count * sizeof(int);
  const std::size_t totalBytes = flagsOffset + count;

  if (maxCount > 0) {
    char *block = static_cast<char *>(MeMemoryAPI.createAligned(totalBytes, static_cast<unsigned>(alignment)));
    if (block == nullptr) {
      MeWarning(0, "MePoolInit: could not allocate %zu bytes for %d structs of %d bytes", totalBytes, maxCount,
                structSize);
      return FALSE;
    }
    pool->memory = block;
    pool->freeStack = reinterpret_cast<int *>(block + stackOffset);
    pool->inUse = reinterpret_cast<unsigned char *>(block + flagsOffset);
  }
  pool->maxCount = maxCount;
  pool->structSize = structSize;
  pool->stride = static_cast<int>(stride);
  pool->alignment = alignment;
  poolResetFreeStack(*pool);
  return TRUE;
}

MEPUBLIC void MEAPI MePoolDestroy(MePool *pool) {
  if (pool == nullptr) return;
  if (pool->memory != nullptr) MeMemoryAPI.destroyAligned(pool->memory);
  *pool = MePool{};
}

MEPUBLIC void MEAPI MePoolSetName(MePool *pool, const char *name) {
  ME_REQUIRE_ARG(pool != nullptr, "MePoolSetName", "pool is NULL");
  pool->name = name;
}

MEPUBLIC void MEAPI MePoolReset(MePool *pool) {
  ME_REQUIRE_ARG(pool != nullptr, "MePoolReset", "pool is NULL");
  poolResetFreeStack(*pool);
}

}  // extern "C"
