// Chunk.cpp: MeChunk, the growable scratch buffer.
// Invariants: buffer == NULL or buffer holds exactly `size` bytes aligned to
// `alignment`; inUse implies buffer != NULL.
#include <cstddef>
#include <cstdint>

#include "MeChunk.h"
#include "MeMemory.h"
#include "MeMessage.h"
#include "MemoryDefaults.h"

namespace karma::me {
namespace {

constexpr int defaultChunkAlignment = static_cast<int>(alignof(std::max_align_t));

// A zero-filled chunk reads as a default one.
std::size_t chunkSize(const MeChunk &chunk) noexcept { return chunk.size != 0 ? chunk.size : ME_CHUNK_DEFAULT_SIZE; }

unsigned chunkAlignment(const MeChunk &chunk) noexcept {
  return static_cast<unsigned>(chunk.alignment != 0 ? chunk.alignment : defaultChunkAlignment);
}

// Replaces the buffer with a fresh one of `bytes` bytes (old contents are
// dropped, and the old buffer is freed first to keep the peak low). On
// failure the chunk is left without a buffer and FALSE is returned.
bool reallocateChunk(MeChunk &chunk, std::size_t bytes, const char *caller) noexcept {
  if (chunk.buffer != nullptr) {
    MeMemoryAPI.destroyAligned(chunk.buffer);
    chunk.buffer = nullptr;
  }
  chunk.buffer = MeMemoryAPI.createAligned(bytes, chunkAlignment(chunk));
  if (chunk.buffer == nullptr) {
    MeWarning(0, "%s: could not allocate %zu bytes of scratch memory", caller, bytes);
    return false;
  }
  return true;
}

}  // namespace
}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC void MEAPI MeChunkInit(MeChunk *chunk, int alignment) {
  ME_REQUIRE_ARG(chunk != nullptr, "MeChunkInit", "chunk is NULL");
  *chunk = MeChunk{};
  chunk->size = ME_CHUNK_DEFAULT_SIZE;
  chunk->alignment = defaultChunkAlignment;
  if (alignment != 0) {
    if (alignment > 0 && isPowerOfTwo(static_cast<unsigned>(alignment)))
      chunk->alignment = alignment;
    else
      MeWarning(0, "MeChunkInit: alignment %d is not a power of two; using %d", alignment, defaultChunkAlignment);
  }
}

MEPUBLIC void MEAPI MeChunkTerm(MeChunk *chunk) {
  if (chunk == nullptr) return;
  if (chunk->inUse) MeWarning(0, "MeChunkTerm: the chunk is still in use (MeChunkPutMem was not called)");
  if (chunk->buffer != nullptr) MeMemoryAPI.destroyAligned(chunk->buffer);
  const int alignment = chunk->alignment;
  *chunk = MeChunk{};
  chunk->size = ME_CHUNK_DEFAULT_SIZE;
  chunk->alignment = alignment != 0 ? alignment : defaultChunkAlignment;
}

MEPUBLIC void *MEAPI MeChunkGetMem(MeChunk *chunk, size_t bytes) {
  ME_REQUIRE_ARG_RET(chunk != nullptr, nullptr, "MeChunkGetMem", "chunk is NULL");
  if (chunk->inUse) {
    MeWarning(0,
              "MeChunkGetMem: the chunk is already in use (one user at a time: call "
              "MeChunkPutMem first); returning NULL");
    return nullptr;
  }
  if (bytes > chunk->largestRequest) chunk->largestRequest = bytes;

  std::size_t size = chunkSize(*chunk);
  int doublings = 0;
  while (size < bytes) {
    if (size > SIZE_MAX / 2) {
      MeWarning(0, "MeChunkGetMem: %zu bytes is more than a chunk can hold", bytes);
      return nullptr;
    }
    size *= 2;
    ++doublings;
  }
  if (doublings > 0 || chunk->buffer == nullptr) {
    if (!reallocateChunk(*chunk, size, "MeChunkGetMem"))
      return nullptr;  // size and growCount unchanged: the next call retries
    chunk->size = size;
    chunk->growCount += doublings;
  }
  chunk->inUse = TRUE;
  return chunk->buffer;
}

MEPUBLIC void MEAPI MeChunkPutMem(MeChunk *chunk, void *mem) {
  ME_REQUIRE_ARG(chunk != nullptr, "MeChunkPutMem", "chunk is NULL");
  ME_REQUIRE_ARG(chunk->inUse, "MeChunkPutMem", "the chunk is not in use; ignored");
  ME_REQUIRE_ARG(mem == chunk->buffer, "MeChunkPutMem", "%p is not the memory MeChunkGetMem returned; ignored", mem);
  chunk->inUse = FALSE;
}

MEPUBLIC void MEAPI MeChunkSetAuto(MeChunk *chunk, size_t initialBytes) {
  ME_REQUIRE_ARG(chunk != nullptr, "MeChunkSetAuto", "chunk is NULL");
  ME_REQUIRE_ARG(!chunk->inUse, "MeChunkSetAuto", "the chunk is in use; ignored");
  const std::size_t current = chunkSize(*chunk);
  const std::size_t wanted = initialBytes > current ? initialBytes : current;
  chunk->size = wanted;
  if (chunk->buffer != nullptr && wanted == current) return;  // already big enough and allocated
  // On failure the raised size stands and GetMem retries the allocation.
  reallocateChunk(*chunk, wanted, "MeChunkSetAuto");
}

MEPUBLIC size_t MEAPI MeChunkGetSize(const MeChunk *chunk) { return chunk != nullptr ? chunkSize(*chunk) : 0; }

MEPUBLIC int MEAPI MeChunkGetGrowCount(const MeChunk *chunk) { return chunk != nullptr ? chunk->growCount : 0; }

MEPUBLIC size_t MEAPI MeChunkGetLargestRequest(const MeChunk *chunk) {
  return chunk != nullptr ? chunk->largestRequest : 0;
}

}  // extern "C"
