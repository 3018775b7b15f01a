// interaction_table.cpp: the framework's table of nearfield interactions.
//
// Entry (a, b) answers a pair whose model1 has type a and model2 type b.
// Registering (a, b) explicitly also fills (b, a) as a mirror (swap = 1)
// unless (b, a) was registered explicitly itself; the dispatcher
// (dispatch.cpp) turns a mirrored call round. Each registration makes new
// slots (mcd_internal.h): a pair keeps the functions it was greeted with
// until its goodbye, whatever the table holds by then.
#include "mcd_internal.h"
#include "nearfield/nearfield.h"

namespace {

using karma::mcd::InteractionSlot;

bool ValidType(const McdFramework *fw, int t) { return t >= 0 && t < fw->typeMax && fw->types[t] != nullptr; }

InteractionSlot *SlotOf(const McdInteractions *fns) {
  return reinterpret_cast<InteractionSlot *>(const_cast<McdInteractions *>(fns));
}

void FreeSlot(InteractionSlot *slot) { MeMemoryAPI.destroy(slot); }

// A slot holding `fns` with the table's own fields set; NULL (warned) when
// memory runs out.
InteractionSlot *NewSlot(McdFramework *fw, const McdInteractions &fns, int swap, const char *fn) {
  auto *slot = static_cast<InteractionSlot *>(MeMemoryAPI.createZeroed(sizeof(InteractionSlot)));
  if (!slot) {
    MeWarning(0, "%s: out of memory; the interaction table is unchanged", fn);
    return nullptr;
  }
  slot->fns = fns;
  slot->fns.swap = swap;
  slot->fns.m_builtIn = 0;
  slot->framework = fw;
  return slot;
}

// The slot leaves the table: freed now if no pair holds it, else kept on
// the retired list until its last pair's goodbye.
void Retire(McdFramework *fw, InteractionSlot *slot) {
  if (!slot) return;
  if (slot->pairs == 0) {
    FreeSlot(slot);
    return;
  }
  slot->retired = true;
  slot->nextRetired = fw->retired;
  fw->retired = slot;
}

void Put(McdFramework *fw, int cell, InteractionSlot *slot) {
  InteractionSlot *old = fw->table[cell];
  fw->table[cell] = slot;
  Retire(fw, old);
}

}  // namespace

namespace karma::mcd {

void RegisterInteractionQuietly(McdFramework *fw, int a, int b, const McdInteractions &fns) {
  if (!fw || !ValidType(fw, a) || !ValidType(fw, b)) return;
  const int n = fw->typeMax;
  const InteractionSlot *before[2] = {fw->table[a * n + b], fw->table[b * n + a]};
  McdFrameworkSetInteraction(fw, a, b, &fns);
  // The slots this call made are the engine's own (none when it ran out of
  // memory: the table then still holds the slots it had, perhaps a user's).
  InteractionSlot *ab = fw->table[a * n + b], *ba = fw->table[b * n + a];
  if (ab && ab != before[0]) ab->fns.m_builtIn = 1;
  if (a != b && ba && ba != before[1] && !fw->explicitEntry[b * n + a]) ba->fns.m_builtIn = 1;
}

void HoldInteraction(const McdInteractions *fns) {
  if (fns) ++SlotOf(fns)->pairs;
}

void ReleaseInteraction(const McdInteractions *fns) {
  if (!fns) return;
  InteractionSlot *slot = SlotOf(fns);
  if (--slot->pairs > 0 || !slot->retired) return;
  for (InteractionSlot **link = &slot->framework->retired; *link; link = &(*link)->nextRetired)
    if (*link == slot) {
      *link = slot->nextRetired;
      break;
    }
  FreeSlot(slot);
}

void FreeInteractionSlots(McdFramework *fw) {
  if (fw->table)
    for (int cell = 0; cell < fw->typeMax * fw->typeMax; ++cell) {
      FreeSlot(fw->table[cell]);
      fw->table[cell] = nullptr;
    }
  while (InteractionSlot *slot = fw->retired) {
    fw->retired = slot->nextRetired;
    FreeSlot(slot);
  }
}

}  // namespace karma::mcd

extern "C" {

void MEAPI McdFrameworkSetInteraction(McdFrameworkID fw, int a, int b, const McdInteractions *fns) {
  static const char *fn = "McdFrameworkSetInteraction";
  ME_REQUIRE_ARG(fw != nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG(ValidType(fw, a) && ValidType(fw, b), fn, "geometry types %d and %d must both be registered first", a,
                 b);
  ME_REQUIRE_ARG(fns == nullptr || fns->intersectFn != nullptr, fn, "the interaction has no intersectFn");
  const int n = fw->typeMax;
  const bool mirror = a != b && !fw->explicitEntry[b * n + a];
  if (!fns) {
    Put(fw, a * n + b, nullptr);
    fw->explicitEntry[a * n + b] = 0;
    if (mirror) Put(fw, b * n + a, nullptr);
    return;
  }
  InteractionSlot *ab = NewSlot(fw, *fns, 0, fn);
  InteractionSlot *ba = mirror ? NewSlot(fw, *fns, 1, fn) : nullptr;
  if (!ab || (mirror && !ba)) {
    FreeSlot(ab);
    FreeSlot(ba);
    return;
  }
  Put(fw, a * n + b, ab);
  fw->explicitEntry[a * n + b] = 1;
  if (mirror) Put(fw, b * n + a, ba);
}

const McdInteractions *MEAPI McdFrameworkGetInteraction(McdFrameworkID fw, int a, int b) {
  if (!fw || a < 0 || b < 0 || a >= fw->typeMax || b >= fw->typeMax) return nullptr;
  const InteractionSlot *slot = fw->table[a * fw->typeMax + b];
  return slot ? &slot->fns : nullptr;
}

}  // extern "C"
