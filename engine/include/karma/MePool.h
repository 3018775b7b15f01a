/* MePool.h: a fixed-capacity pool of equal-sized structs.
 *
 * A pool takes all its memory from MeMemoryAPI once, in MePoolInit, and
 * never allocates again: MePoolGetStruct and MePoolPutStruct are a few
 * instructions each. Mdt keeps its bodies and constraints in pools.
 *
 * Determinism: structs are handed out in an order that depends only on the
 * sequence of Get/Put/Reset calls. A fresh (or reset) pool hands out its
 * structs in address order; after that, the most recently returned struct is
 * handed out first (a LIFO free list).
 *
 * Exhaustion: when every struct is in use, MePoolGetStruct returns NULL and
 * emits one MeWarning giving the pool's name and capacity. It stays quiet
 * on further failures until a struct has been returned (or the pool reset),
 * so a full pool cannot flood the log.
 *
 * Bad returns: putting back a pointer that is not a struct of this pool, or
 * one that is already free, is always detected and ignored (the pool's
 * bookkeeping stays intact); the check build also says so with an MeWarning.
 *
 * The struct is public so that users can embed a pool in their own structs;
 * treat its fields as read-only and use the functions. A pool filled with
 * zero bytes is a valid, empty, uninitialised pool: MePoolDestroy accepts
 * it and MePoolGetStruct returns NULL from it. */
#ifndef KARMA_MEPOOL_H
#define KARMA_MEPOOL_H

#include <stddef.h>

#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MePool {
  /* Start of the single block from MeMemoryAPI.createAligned (NULL when
     * the pool is not initialised or has capacity 0). The structs come
     * first: struct i lives at memory + i * stride. */
  void *memory;
  /* Stack of free struct indices; the top, freeStack[freeCount - 1], is
     * the next struct handed out. Lives inside `memory`. */
  int *freeStack;
  /* inUse[i] is 1 while struct i is handed out, 0 while it is free.
     * Lives inside `memory`. */
  unsigned char *inUse;
  int maxCount;      /* capacity, >= 0 */
  int structSize;    /* bytes requested per struct, > 0 once initialised */
  int stride;        /* structSize rounded up to a multiple of alignment */
  int alignment;     /* power of two; every struct address is a multiple */
  int freeCount;     /* structs free; usedCount + freeCount == maxCount */
  int usedCount;     /* structs handed out */
  MeBool warnedFull; /* exhaustion already reported since the last Put */
  const char *name;  /* for messages (not copied); NULL means "unnamed" */
} MePool;

/* Prepares `pool` to hold up to maxCount structs of structSize bytes, each
 * aligned to `alignment` (a power of two; 0 means the platform's strictest
 * standard alignment). maxCount may be 0 (every Get then fails). Returns
 * TRUE on success; on bad arguments or allocation failure, warns, leaves
 * the pool empty (as if zero-filled) and returns FALSE. */
MEPUBLIC MeBool MEAPI MePoolInit(MePool *pool, int maxCount, int structSize, int alignment);

/* Releases the pool's memory and leaves it empty. Structs still in use
 * become invalid. NULL and never-initialised pools are accepted. */
MEPUBLIC void MEAPI MePoolDestroy(MePool *pool);

/* Names the pool in its messages, e.g. "MdtWorld bodies". The string is
 * not copied and must outlive the pool. */
MEPUBLIC void MEAPI MePoolSetName(MePool *pool, const char *name);

/* Hands out a free struct (its contents are whatever was there before), or
 * NULL with one warning when the pool is exhausted. */
MEPUBLIC void *MEAPI MePoolGetStruct(MePool *pool);

/* Returns a struct to the pool; it becomes the next one handed out.
 * NULL is ignored silently. */
MEPUBLIC void MEAPI MePoolPutStruct(MePool *pool, void *s);

/* Marks every struct free and restores the fresh hand-out order. */
MEPUBLIC void MEAPI MePoolReset(MePool *pool);

/* Number of structs handed out / still free / the capacity. */
MEPUBLIC int MEAPI MePoolGetUsed(const MePool *pool);
MEPUBLIC int MEAPI MePoolGetUnused(const MePool *pool);
MEPUBLIC int MEAPI MePoolGetMaxCount(const MePool *pool);

/* Iterates over the structs in use, in address order:
 *   for (p = MePoolGetNextUsed(pool, NULL); p; p = MePoolGetNextUsed(pool, p))
 * `previous` is NULL to start, else a struct of this pool. Returns NULL after
 * the last one. A whole pass costs O(maxCount). The pool may not be changed
 * during a pass, except by putting back the struct just returned. */
MEPUBLIC void *MEAPI MePoolGetNextUsed(const MePool *pool, const void *previous);

ME_EXTERN_C_END

#endif /* KARMA_MEPOOL_H */
