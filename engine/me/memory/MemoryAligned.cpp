// MemoryAligned.cpp: aligned blocks carved out of MeMemoryAPI.create.
//
// Layout of a block from defaultCreateAligned (A = max(alignment,
// alignof(void*))):
//
//   raw ... [raw pointer][aligned block of `bytes` bytes] ... raw + bytes + A-1 + sizeof(void*)
//                         ^ returned address, a multiple of A
//
// The raw address from create is stored in the pointer-sized slot just
// below the returned address, which is why destroyAligned can hand it back
// to MeMemoryAPI.destroy.
#include <cstdint>
#include <cstring>

#include "MeMessage.h"
#include "MemoryDefaults.h"

namespace karma::me {

void *MEAPI defaultCreateAligned(std::size_t bytes, unsigned int alignment) {
  if (!isPowerOfTwo(alignment)) {
    MeWarning(0, "MeMemoryAPI.createAligned: alignment %u is not a power of two", alignment);
    return nullptr;
  }
  const std::size_t align = alignment > alignof(void *) ? alignment : alignof(void *);
  const std::size_t overhead = align - 1 + sizeof(void *);
  if (bytes > SIZE_MAX - overhead) {
    MeWarning(0, "MeMemoryAPI.createAligned: %zu bytes aligned to %u is too large", bytes, alignment);
    return nullptr;
  }
  void *raw = MeMemoryAPI.create(bytes + overhead);
  if (raw == nullptr) return nullptr;  // create has reported the failure
  const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(raw) + sizeof(void *);
  const std::uintptr_t aligned = (first + (align - 1)) & ~static_cast<std::uintptr_t>(align - 1);
  char *block = reinterpret_cast<char *>(aligned);
  std::memcpy(block - sizeof(void *), &raw, sizeof raw);
  return block;
}

void MEAPI defaultDestroyAligned(void *block) {
  if (block == nullptr) return;
  void *raw = nullptr;
  std::memcpy(&raw, static_cast<char *>(block) - sizeof(void *), sizeof raw);
  MeMemoryAPI.destroy(raw);
}

}  // namespace karma::me
