// model_pair.cpp: model pairs and pair containers.
#include "mcd_internal.h"

#include <cstring>

extern "C" {

McdModelPairID MEAPI McdModelPairCreate(McdModelID m1, McdModelID m2) {
  static const char *fn = "McdModelPairCreate";
  ME_REQUIRE_ARG_RET(m1 != nullptr && m2 != nullptr, nullptr, fn, "a model is NULL");
  ME_REQUIRE_ARG_RET(m1 != m2, nullptr, fn, "a model cannot pair with itself");
  auto *p = static_cast<McdModelPair *>(MeMemoryAPI.createZeroed(sizeof(McdModelPair)));
  if (!p) return nullptr;
  p->model1 = m1;
  p->model2 = m2;
  p->m_spaceIndex = -1;
  return p;
}

void MEAPI McdModelPairDestroy(McdModelPairID p) {
  if (!p) return;
  if (p->m_helloed) McdGoodbye(p);
  MeMemoryAPI.destroy(p);
}

void MEAPI McdModelPairReset(McdModelPairID p, McdModelID m1, McdModelID m2) {
  static const char *fn = "McdModelPairReset";
  ME_REQUIRE_ARG(p != nullptr, fn, "pair is NULL");
  ME_REQUIRE_ARG(!p->m_helloed, fn, "the pair is between McdHello and McdGoodbye");
  ME_REQUIRE_ARG(m1 != nullptr && m2 != nullptr && m1 != m2, fn, "the models must be two distinct non-NULL models");
  std::memset(p, 0, sizeof *p);
  p->model1 = m1;
  p->model2 = m2;
  p->m_spaceIndex = -1;
}

void MEAPI McdModelPairSetUserData(McdModelPairID p, void *data) {
  ME_REQUIRE_ARG(p != nullptr, "McdModelPairSetUserData", "pair is NULL");
  p->userData = data;
}

void *MEAPI McdModelPairGetUserData(McdModelPairID p) { return p ? p->userData : nullptr; }

McdModelPairContainer *MEAPI McdModelPairContainerCreate(int size) {
  static const char *fn = "McdModelPairContainerCreate";
  ME_REQUIRE_ARG_RET(size > 0, nullptr, fn, "size must be positive, got %d", size);
  auto *c = static_cast<McdModelPairContainer *>(MeMemoryAPI.createZeroed(sizeof(McdModelPairContainer)));
  if (!c) return nullptr;
  c->array = static_cast<McdModelPair **>(MeMemoryAPI.createZeroed(sizeof(McdModelPair *) * (std::size_t)size));
  if (!c->array) {
    MeMemoryAPI.destroy(c);
    return nullptr;
  }
  c->size = size;
  McdModelPairContainerReset(c);
  return c;
}

void MEAPI McdModelPairContainerReset(McdModelPairContainer *c) {
  ME_REQUIRE_ARG(c != nullptr, "McdModelPairContainerReset", "container is NULL");
  c->goodbyeFirst = c->goodbyeEnd = 0;
  c->helloFirst = c->helloEnd = c->stayingFirst = c->stayingEnd = (c->size + 1) / 2;
}

void MEAPI McdModelPairContainerDestroy(McdModelPairContainer *c) {
  if (!c) return;
  MeMemoryAPI.destroy(c->array);
  MeMemoryAPI.destroy(c);
}

}  // extern "C"
