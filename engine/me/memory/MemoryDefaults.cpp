// MemoryDefaults.cpp: the default create / destroy / resize / createZeroed.
// These are the only functions in Karma that call the C heap directly.
#include "MemoryDefaults.h"

#include <cstdlib>
#include <cstring>

#include "MeMessage.h"

namespace karma::me {

void *MEAPI defaultCreate(std::size_t bytes) {
  // A zero-byte request still gets a distinct, freeable block.
  void *block = std::malloc(bytes != 0 ? bytes : 1);
  if (block == nullptr) MeWarning(0, "MeMemoryAPI.create: out of memory allocating %zu bytes", bytes);
  return block;
}

void MEAPI defaultDestroy(void *block) { std::free(block); }

void *MEAPI defaultResize(void *block, std::size_t bytes) {
  // realloc(p, 0) may free p; asking for one byte keeps the block alive.
  void *resized = std::realloc(block, bytes != 0 ? bytes : 1);
  if (resized == nullptr) MeWarning(0, "MeMemoryAPI.resize: out of memory resizing a block to %zu bytes", bytes);
  return resized;
}

void *MEAPI defaultCreateZeroed(std::size_t bytes) {
  void *block = MeMemoryAPI.create(bytes);
  if (block != nullptr) std::memset(block, 0, bytes);
  return block;
}

}  // namespace karma::me
