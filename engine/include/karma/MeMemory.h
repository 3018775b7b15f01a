/* MeMemory.h: the one door through which Karma allocates memory.
 *
 * Every allocation Karma makes (pools, chunks, worlds, command-line copies,
 * ...) calls a function pointer in the global struct MeMemoryAPI. To route
 * Karma's memory through your own allocator, assign the members before the
 * first other Karma call and leave them alone afterwards:
 *
 *   MeMemoryAPI.create  = MyCreate;
 *   MeMemoryAPI.destroy = MyDestroy;
 *   world = MdtWorldCreate(...);
 *
 * Families. create / destroy / resize work on the same blocks and must be
 * replaced together (resize defaults to realloc, so it only matches a
 * malloc-compatible create). The defaults of createZeroed, createAligned and
 * destroyAligned are built on top of MeMemoryAPI.create and
 * MeMemoryAPI.destroy as they are at the time of the call, so replacing just
 * create and destroy captures every allocation Karma makes. createAligned
 * and destroyAligned form a second family: replace both or neither.
 *
 * Failure. The defaults never crash on exhaustion: they emit an MeWarning
 * naming the size and return NULL, and every Karma caller copes with NULL.
 * Replacement functions should behave the same way.
 *
 * Not thread-safe to modify; reading it (allocating) from several threads is
 * as safe as the functions installed. */
#ifndef KARMA_MEMEMORY_H
#define KARMA_MEMEMORY_H

#include <stddef.h>

#include "MeCall.h"

ME_EXTERN_C_BEGIN

typedef struct MeMemoryAPIStruct {
  /* Returns a block of at least `bytes` bytes (a zero-byte request still
     * yields a distinct block), suitably aligned for any standard type, or
     * NULL on failure. Default: malloc. */
  void *(MEAPI *create)(size_t bytes);

  /* Releases a block from create / createZeroed / resize; NULL is ignored.
     * Default: free. */
  void(MEAPI *destroy)(void *block);

  /* Changes a block's size keeping its contents up to the smaller size.
     * resize(NULL, n) acts as create(n). On failure returns NULL and leaves
     * the old block untouched. Default: realloc. */
  void *(MEAPI *resize)(void *block, size_t bytes);

  /* As create, with every byte zero. Default: MeMemoryAPI.create + memset. */
  void *(MEAPI *createZeroed)(size_t bytes);

  /* Returns a block whose address is a multiple of `alignment`, which must
     * be a power of two (otherwise MeWarning and NULL). Release it with
     * destroyAligned, never destroy. Default: over-allocates through
     * MeMemoryAPI.create and hides the original address just below the
     * aligned one. */
  void *(MEAPI *createAligned)(size_t bytes, unsigned int alignment);

  /* Releases a block from createAligned; NULL is ignored. Default: recovers
     * the original address and passes it to MeMemoryAPI.destroy. */
  void(MEAPI *destroyAligned)(void *block);
} MeMemoryAPIStruct;

/* The allocator table every Karma module uses. */
extern MEPUBLIC MeMemoryAPIStruct MeMemoryAPI;

/* Puts the default functions back into every member of MeMemoryAPI.
 * Only call it when no Karma memory from replaced functions is still live. */
MEPUBLIC void MEAPI MeMemoryAPIReset(void);

ME_EXTERN_C_END

#endif /* KARMA_MEMEMORY_H */
