// PoolStructs.cpp: handing structs out, taking them back, counting and
// iterating. Invariants (for an initialised pool):
//   usedCount + freeCount == maxCount;
//   freeStack[0 .. freeCount-1] are exactly the indices i with inUse[i] == 0.
#include <cstdint>

#include "MeMessage.h"
#include "PoolInternal.h"

namespace karma::me {

int poolIndexOf(const MePool &pool, const void *address) noexcept {
  if (pool.memory == nullptr || address == nullptr) return -1;
  // Compare as integers: the address may belong to another object.
  const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(pool.memory);
  const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(address);
  const std::uintptr_t stride = static_cast<std::uintptr_t>(pool.stride);
  if (at < base) return -1;
  const std::uintptr_t offset = at - base;
  if (offset % stride != 0 || offset / stride >= static_cast<std::uintptr_t>(pool.maxCount)) return -1;
  return static_cast<int>(offset / stride);
}

}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC void *MEAPI MePoolGetStruct(MePool *pool) {
  ME_REQUIRE_ARG_RET(pool != nullptr, nullptr, "MePoolGetStruct", "pool is NULL");
  if (pool->freeCount == 0) {
    if (!pool->warnedFull) {
      MeWarning(0,
                "MePoolGetStruct: pool \"%s\" is exhausted: all %d of its structs are in "
                "use; returning NULL (make the pool bigger)",
                poolName(*pool), pool->maxCount);
      pool->warnedFull = TRUE;
    }
    return nullptr;
  }
  const int index = pool->freeStack[--pool->freeCount];
  pool->inUse[index] = 1;
  ++pool->usedCount;
  return poolStructAt(*pool, index);
}

MEPUBLIC void MEAPI MePoolPutStruct(MePool *pool, void *s) {
  ME_REQUIRE_ARG(pool != nullptr, "MePoolPutStruct", "pool is NULL");
  if (s == nullptr) return;
  // Bad pointers are always rejected (they would corrupt the free stack);
  // only the check build explains why.
  const int index = poolIndexOf(*pool, s);
  if (index < 0) {
#if KARMA_CHECK
    MeWarning(0, "MePoolPutStruct: %p is not a struct of pool \"%s\"; ignored", s, poolName(*pool));
#endif
    return;
  }
  if (pool->inUse[index] == 0) {
#if KARMA_CHECK
    MeWarning(0,
              "MePoolPutStruct: struct %d of pool \"%s\" is already free (put twice?); "
              "ignored",
              index, poolName(*pool));
#endif
    return;
  }
  pool->inUse[index] = 0;
  pool->freeStack[pool->freeCount++] = index;
  --pool->usedCount;
  pool->warnedFull = FALSE;
}

MEPUBLIC int MEAPI MePoolGetUsed(const MePool *pool) { return pool != nullptr ? pool->usedCount : 0; }

MEPUBLIC int MEAPI MePoolGetUnused(const MePool *pool) { return pool != nullptr ? pool->freeCount : 0; }

MEPUBLIC int MEAPI MePoolGetMaxCount(const MePool *pool) { return pool != nullptr ? pool->maxCount : 0; }

MEPUBLIC void *MEAPI MePoolGetNextUsed(const MePool *pool, const void *previous) {
  if (pool == nullptr || pool->memory == nullptr) return nullptr;
  int start = 0;
  if (previous != nullptr) {
    const int index = poolIndexOf(*pool, previous);
    ME_REQUIRE_ARG_RET(index >= 0, nullptr, "MePoolGetNextUsed", "%p is not a struct of pool \"%s\"", previous,
                       poolName(*pool));
    start = index + 1;
  }
  for (int i = start; i < pool->maxCount; ++i)
    if (pool->inUse[i] != 0) return poolStructAt(*pool, i);
  return nullptr;
}

}  // extern "C"
