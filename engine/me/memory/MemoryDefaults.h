// MemoryDefaults.h: the functions MeMemoryAPI holds until a user replaces
// them (and that MeMemoryAPIReset puts back).
#ifndef KARMA_ME_MEMORY_MEMORYDEFAULTS_H
#define KARMA_ME_MEMORY_MEMORYDEFAULTS_H

#include <cstddef>

#include "MeMemory.h"

namespace karma::me {

// malloc / free / realloc wrappers: warn and return NULL on failure.
void *MEAPI defaultCreate(std::size_t bytes);
void MEAPI defaultDestroy(void *block);
void *MEAPI defaultResize(void *block, std::size_t bytes);

// Built on MeMemoryAPI.create (+ memset): captured when create is replaced.
void *MEAPI defaultCreateZeroed(std::size_t bytes);

// Built on MeMemoryAPI.create / MeMemoryAPI.destroy (MemoryAligned.cpp).
void *MEAPI defaultCreateAligned(std::size_t bytes, unsigned int alignment);
void MEAPI defaultDestroyAligned(void *block);

// The table of all defaults, as MeMemoryAPI starts out.
inline constexpr MeMemoryAPIStruct defaultMemoryAPI = {
    &defaultCreate,       &defaultDestroy,       &defaultResize,
    &defaultCreateZeroed, &defaultCreateAligned, &defaultDestroyAligned,
};

// True if `alignment` is a power of two (which excludes 0).
constexpr bool isPowerOfTwo(unsigned long long alignment) noexcept {
  return alignment != 0 && (alignment & (alignment - 1)) == 0;
}

}  // namespace karma::me

#endif
