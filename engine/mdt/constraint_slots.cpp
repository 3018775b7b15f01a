// constraint_slots.cpp: the world's constraint slots (constraint.h,
// "Slots").
//
// The first pool holds MdtWorldCreate's maxConstraints slots. When it is
// full, the world grows rather than dropping what the program (or the
// collision bridge, for contacts) asks for: another pool is added, as large
// as all the slots so far (so the total doubles), and the growth is reported
// once per world. A constraint keeps its slot, and so its address, for its
// whole life; pools are only released with the world. Slots are handed out
// from the earliest pool with a free one, and walked pool by pool, each in
// MePool's order, so the order depends only on the calls made.
//
// A released slot is marked (its type becomes kDestroyedConstraintType) and
// held back: the last kHeldConstraintSlots released stay in use in their
// pools, in a ring, oldest first. Releasing one more gives the oldest back
// to its pool; when no pool has a free slot, the oldest held one is taken
// before the world grows. So a destroyed constraint's handle is refused
// until its slot is handed out again, which is not before every other slot
// is in use or kHeldConstraintSlots more slots have been released.
#include <climits>
#include <cstddef>

#include "MeMessage.h"
#include "constraint.h"
#include "mdt_internal.h"

namespace karma::mdt {

namespace {

// The pool that holds `slot`, or nullptr.
MePool *ownerPool(MdtWorldPrivate *p, const void *slot) {
  const auto *s = static_cast<const unsigned char *>(slot);
  for (int k = -1; k < p->overflowCount; ++k) {
    MePool *pool = k < 0 ? &p->constraints : &p->overflow[k];
    const auto *begin = static_cast<const unsigned char *>(pool->memory);
    if (begin && s >= begin && s < begin + (size_t)pool->maxCount * (size_t)pool->stride) return pool;
  }
  return nullptr;
}

MePool *poolAt(MdtWorldPrivate *p, int k) { return k < 0 ? &p->constraints : &p->overflow[k]; }

// Adds an overflow pool as large as every slot so far; false when it cannot.
bool grow(MdtWorldPrivate *p) {
  if (p->overflowCount >= kMaxConstraintPools) return false;
  long total = p->constraints.maxCount;
  for (int k = 0; k < p->overflowCount; ++k) total += p->overflow[k].maxCount;
  const int size = (int)(total < 16 ? 16 : total > INT_MAX / 4 ? INT_MAX / 4 : total);
  MePool *pool = &p->overflow[p->overflowCount];
  if (!MePoolInit(pool, size, (int)p->constraintSlotSize, kConstraintSlotAlignment)) return false;
  MePoolSetName(pool, "MdtWorld constraints (grown)");
  ++p->overflowCount;
  if (!p->grewConstraints) {
    MeWarning(0,
              "MdtWorld: the %u constraint slots of MdtWorldCreate are all in use; the world grew to %ld "
              "(reported once per world: size the world for the scene to avoid growing)",
              p->maxConstraints, total + size);
    p->grewConstraints = TRUE;
  }
  return true;
}

// The oldest held slot, no longer held (heldCount > 0).
void *takeOldestHeld(MdtWorldPrivate *p) {
  void *slot = p->heldSlots[p->heldFirst];
  p->heldFirst = (p->heldFirst + 1) % kHeldConstraintSlots;
  --p->heldCount;
  return slot;
}

bool released(const void *slot) {
  return static_cast<const MdtConstraint *>(slot)->type == &kDestroyedConstraintType;
}

// The slot in use after `slot` in the walk's order, held ones included.
void *nextUsedSlot(MdtWorldPrivate *p, void *slot) {
  int k = -1;
  if (slot) {
    MePool *pool = ownerPool(p, slot);
    if (!pool) return nullptr;
    if (void *next = MePoolGetNextUsed(pool, slot)) return next;
    k = pool == &p->constraints ? 0 : (int)(pool - p->overflow) + 1;
  }
  for (; k < p->overflowCount; ++k)
    if (void *first = MePoolGetNextUsed(poolAt(p, k), nullptr)) return first;
  return nullptr;
}

}  // namespace

void *takeConstraintSlot(MdtWorldPrivate *p) {
  for (int k = -1; k < p->overflowCount; ++k)
    if (poolAt(p, k)->freeCount > 0) return MePoolGetStruct(poolAt(p, k));
  if (p->heldCount > 0) return takeOldestHeld(p);
  if (!grow(p)) {
    MeWarning(0, "MdtWorld: out of memory for more constraints; the constraint was not made");
    return nullptr;
  }
  return MePoolGetStruct(&p->overflow[p->overflowCount - 1]);
}

void releaseConstraintSlot(MdtWorldPrivate *p, void *slot) {
  if (!ownerPool(p, slot) || released(slot)) return;
  static_cast<MdtConstraint *>(slot)->type = &kDestroyedConstraintType;
  if (p->heldCount == kHeldConstraintSlots) {
    void *oldest = takeOldestHeld(p);
    MePoolPutStruct(ownerPool(p, oldest), oldest);
  }
  p->heldSlots[(p->heldFirst + p->heldCount) % kHeldConstraintSlots] = slot;
  ++p->heldCount;
}

void *nextConstraintSlot(MdtWorldPrivate *p, void *slot) {
  do {
    slot = nextUsedSlot(p, slot);
  } while (slot && released(slot));
  return slot;
}

int usedConstraintSlots(const MdtWorldPrivate *p) {
  int used = MePoolGetUsed(&p->constraints);
  for (int k = 0; k < p->overflowCount; ++k) used += MePoolGetUsed(&p->overflow[k]);
  return used - p->heldCount;
}

void releaseConstraintPools(MdtWorldPrivate *p) {
  MePoolDestroy(&p->constraints);
  for (int k = 0; k < p->overflowCount; ++k) MePoolDestroy(&p->overflow[k]);
  p->overflowCount = 0;
  p->heldFirst = p->heldCount = 0;
}

}  // namespace karma::mdt
