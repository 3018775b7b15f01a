/* MeChunk.h: a growable scratch buffer, the solver's workspace.
 *
 * Kea needs a block of temporary memory for each solve whose size depends on
 * the problem (it grows with the square of the constraint rows). A chunk
 * keeps one buffer from MeMemoryAPI and reuses it from step to step:
 *
 *   void *work = MeChunkGetMem(&chunk, MdtKeaMemoryRequired(...));
 *   ... solve using work ...
 *   MeChunkPutMem(&chunk, work);
 *
 * Size. A new chunk offers ME_CHUNK_DEFAULT_SIZE (1024) bytes. When a request
 * is larger, the size is doubled as often as needed and a single new buffer
 * of that size replaces the old one; the old contents are NOT preserved (it
 * is scratch memory). Each doubling counts towards MeChunkGetGrowCount. The
 * buffer never shrinks until MeChunkTerm.
 *
 * MeChunkSetAuto raises the size up front (e.g. to what the biggest expected
 * scene needs) and allocates it at once, so early frames do not pay for
 * repeated growth.
 *
 * One user at a time: between GetMem and PutMem the chunk is "in use"; a
 * second GetMem in that time warns and returns NULL.
 *
 * The buffer is allocated lazily (first GetMem or SetAuto), so MeChunkInit
 * cannot fail. A zero-filled MeChunk behaves like one initialised with
 * alignment 0. Not thread-safe: one chunk per solving thread. */
#ifndef KARMA_MECHUNK_H
#define KARMA_MECHUNK_H

#include <stddef.h>

#include "MeCall.h"
#include "MePrecision.h"

#define ME_CHUNK_DEFAULT_SIZE 1024

ME_EXTERN_C_BEGIN

typedef struct MeChunk {
  void *buffer;          /* from MeMemoryAPI.createAligned, or NULL (not yet allocated) */
  size_t size;           /* bytes the chunk provides without growing; buffer, when
                         not NULL, holds exactly this many bytes; 0 only in a
                         zero-filled chunk (then treated as the default) */
  size_t largestRequest; /* largest GetMem request seen, for tuning SetAuto */
  int alignment;         /* power of two; buffer is a multiple of it */
  int growCount;         /* how many times size was doubled by GetMem */
  MeBool inUse;          /* TRUE between GetMem and PutMem */
} MeChunk;

/* Prepares an empty chunk of the default size whose memory will be aligned
 * to `alignment` (a power of two; 0 means the platform's strictest standard
 * alignment; anything else warns and uses that default). */
MEPUBLIC void MEAPI MeChunkInit(MeChunk *chunk, int alignment);

/* Releases the buffer and leaves the chunk as MeChunkInit left it (statistics
 * cleared). Warns if the chunk is still in use. NULL is accepted. */
MEPUBLIC void MEAPI MeChunkTerm(MeChunk *chunk);

/* Returns `bytes` bytes of aligned scratch memory, growing the chunk by
 * doubling if needed, and marks the chunk in use. Returns NULL (with a
 * warning) if the chunk is already in use or memory runs out; after an
 * allocation failure the chunk keeps no buffer and is not in use. */
MEPUBLIC void *MEAPI MeChunkGetMem(MeChunk *chunk, size_t bytes);

/* Ends the current use. `mem` must be the pointer GetMem returned; anything
 * else (or a chunk not in use) warns and is ignored. */
MEPUBLIC void MEAPI MeChunkPutMem(MeChunk *chunk, void *mem);

/* Raises the chunk's size to at least initialBytes and allocates it now, so
 * later requests up to that size never grow it. Never shrinks; does not
 * count as growth. Ignored with a warning while the chunk is in use. */
MEPUBLIC void MEAPI MeChunkSetAuto(MeChunk *chunk, size_t initialBytes);

/* Bytes the chunk provides without growing. */
MEPUBLIC size_t MEAPI MeChunkGetSize(const MeChunk *chunk);

/* Number of doublings GetMem has made since Init / Term. */
MEPUBLIC int MEAPI MeChunkGetGrowCount(const MeChunk *chunk);

/* Largest GetMem request since Init / Term (a good MeChunkSetAuto value). */
MEPUBLIC size_t MEAPI MeChunkGetLargestRequest(const MeChunk *chunk);

ME_EXTERN_C_END

#endif /* KARMA_MECHUNK_H */
