// interaction_table.cpp: the framework's table of nearfield interactions.
//
// Entry (a, b) answers a pair whose model1 has type a and model2 type b.
// Registering (a, b) explicitly also fills (b, a) as a mirror (swap = 1)
// unless (b, a) was registered explicitly itself; the dispatcher
// (dispatch.cpp) turns a mirrored call round.
#include "mcd_internal.h"
#include "nearfield/nearfield.h"

namespace {

bool ValidType(const McdFramework *fw, int t) { return t >= 0 && t < fw->typeMax && fw->types[t] != nullptr; }

}  // namespace

namespace karma::mcd {

void RegisterInteractionQuietly(McdFramework *fw, int a, int b, const McdInteractions &fns) {
  if (!fw || !ValidType(fw, a) || !ValidType(fw, b)) return;
  McdFrameworkSetInteraction(fw, a, b, &fns);
  // The entries this call wrote are the engine's own.
  const int n = fw->typeMax;
  McdInteractions &ab = fw->table[a * n + b], &ba = fw->table[b * n + a];
  ab.m_builtIn = 1;
  if (a != b && !fw->explicitEntry[b * n + a]) ba.m_builtIn = 1;
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
  McdInteractions &ab = fw->table[a * n + b];
  McdInteractions &ba = fw->table[b * n + a];
  if (!fns) {
    ab = McdInteractions{};
    fw->explicitEntry[a * n + b] = 0;
    if (a != b && !fw->explicitEntry[b * n + a]) ba = McdInteractions{};
    return;
  }
  ab = *fns;
  ab.swap = 0;
  ab.m_builtIn = 0;
  fw->explicitEntry[a * n + b] = 1;
  if (a != b && !fw->explicitEntry[b * n + a]) {
    ba = *fns;
    ba.swap = 1;
    ba.m_builtIn = 0;
  }
}

const McdInteractions *MEAPI McdFrameworkGetInteraction(McdFrameworkID fw, int a, int b) {
  if (!fw || a < 0 || b < 0 || a >= fw->typeMax || b >= fw->typeMax) return nullptr;
  const McdInteractions &e = fw->table[a * fw->typeMax + b];
  return e.intersectFn ? &e : nullptr;
}

}  // extern "C"
