// PoolInternal.h: helpers shared by the MePool source files.
#ifndef KARMA_ME_MEMORY_POOLINTERNAL_H
#define KARMA_ME_MEMORY_POOLINTERNAL_H

#include <cstddef>

#include "MePool.h"

namespace karma::me {

// Address of struct `index` (0 <= index < maxCount).
inline void *poolStructAt(const MePool &pool, int index) noexcept {
  return static_cast<char *>(pool.memory) + static_cast<std::size_t>(index) * static_cast<std::size_t>(pool.stride);
}

// Index of the struct at `address`, or -1 if `address` is not the start of
// one of the pool's structs.
int poolIndexOf(const MePool &pool, const void *address) noexcept;

// Marks every struct free; struct 0 is handed out first, then 1, 2, ...
void poolResetFreeStack(MePool &pool) noexcept;

// Name used in messages.
inline const char *poolName(const MePool &pool) noexcept { return pool.name != nullptr ? pool.name : "(unnamed)"; }

}  // namespace karma::me

#endif
