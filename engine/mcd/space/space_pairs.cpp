// space_pairs.cpp: pair filters (enable/disable, culling tables) and pair
// retrieval into McdModelPairContainers.
//
// Retrieval: the core fills a chunk of PairRecord pointers laid out as the
// container's blocks (goodbyes [0, g), hellos [g, g + h), stayings
// [g + h, g + h + s)); each record becomes the McdModelPair of its index.
// The hello/staying split is therefore moved to goodbyeEnd, which the
// container's contract allows.
#include "space_internal.h"

using namespace karma::mcd;

namespace {

// The space of two models, both in the same one; else a warning and NULL.
McdSpace *SpaceOfPair(McdModelID a, McdModelID b, const char *fn) {
  McdSpace *s = SpaceOf(a, fn);
  if (!s || !SpaceOf(b, fn)) return nullptr;
  if (a->space != b->space) {
    MeArgumentWarning(fn, "the two models are in different spaces; ignored");
    return nullptr;
  }
  if (a == b) {
    MeArgumentWarning(fn, "a model cannot pair with itself; ignored");
    return nullptr;
  }
  return s;
}

enum class Want { Pairs, Transitions, ActivePairs };

int Fill(McdSpaceID s, McdSpacePairIterator *iter, McdModelPairContainer *c, Want want, const char *fn) {
  ME_REQUIRE_ARG_RET(s != nullptr && iter != nullptr && c != nullptr, 0, fn, "space, iterator or container is NULL");
  ME_REQUIRE_ARG_RET(c->array != nullptr && c->size > 0, 0, fn, "the container has no array or no size");
  if (s->chunk.size() < (std::size_t)c->size) s->chunk.resize((std::size_t)c->size);
  PairChunk chunk;
  chunk.array = s->chunk.data();
  chunk.size = c->size;
  PairIterator it;
  it.generation = iter->generation;
  it.nextGoodbye = iter->nextGoodbye;
  it.nextHello = iter->nextHello;
  it.nextStaying = iter->nextStaying;
  const bool more = want == Want::Pairs         ? s->core->GetPairs(&it, &chunk)
                    : want == Want::Transitions ? s->core->GetTransitions(&it, &chunk)
                                                : s->core->GetActivePairs(&it, &chunk);
  iter->nextGoodbye = it.nextGoodbye;
  iter->nextHello = it.nextHello;
  iter->nextStaying = it.nextStaying;
  for (int i = 0; i < chunk.stayingEnd; ++i) c->array[i] = &s->pairs[(std::size_t)chunk.array[i]->index];
  c->goodbyeFirst = chunk.goodbyeFirst;
  c->goodbyeEnd = chunk.goodbyeEnd;
  c->helloFirst = chunk.helloFirst;
  c->helloEnd = c->stayingFirst = chunk.helloEnd;
  c->stayingEnd = chunk.stayingEnd;
  return more ? 1 : 0;
}

}  // namespace

extern "C" {

MeBool MEAPI McdSpaceEnablePair(McdModelID a, McdModelID b) {
  McdSpace *s = SpaceOfPair(a, b, "McdSpaceEnablePair");
  return s && s->core->EnablePair(a->spaceIndex, b->spaceIndex) ? 1 : 0;
}

MeBool MEAPI McdSpaceDisablePair(McdModelID a, McdModelID b) {
  McdSpace *s = SpaceOfPair(a, b, "McdSpaceDisablePair");
  return s && s->core->DisablePair(a->spaceIndex, b->spaceIndex) ? 1 : 0;
}

MeBool MEAPI McdSpacePairIsEnabled(McdModelID a, McdModelID b) {
  McdSpace *s = SpaceOfPair(a, b, "McdSpacePairIsEnabled");
  return s && s->core->PairIsEnabled(a->spaceIndex, b->spaceIndex) ? 1 : 0;
}

McdCullingTable *MEAPI McdCullingTableCreate(int size) {
  return reinterpret_cast<McdCullingTable *>(CullingTableCreate(size));
}

McdCullingTable *MEAPI McdCullingTableSet(McdCullingTable *const table, MeU32 a, MeU32 b, MeBool flag) {
  ME_REQUIRE_ARG_RET(table != nullptr, nullptr, "McdCullingTableSet", "table is NULL");
  CullingTableSet(reinterpret_cast<CullingTable *>(table), a, b, flag);
  return table;
}

void MEAPI McdCullingTableDestroy(McdCullingTable *table) {
  CullingTableDestroy(reinterpret_cast<CullingTable *>(table));
}

void MEAPI McdSpaceSetModelCullingParameters(McdSpaceID s, McdModelID m, McdCullingTable *table, int cullingIndex,
                                             int cullingID) {
  static const char *fn = "McdSpaceSetModelCullingParameters";
  ME_REQUIRE_ARG(s != nullptr && m != nullptr, fn, "space or model is NULL");
  ME_REQUIRE_ARG(m->space == s, fn, "the model is not in this space");
  s->core->SetCulling(m->spaceIndex, reinterpret_cast<CullingTable *>(table), cullingIndex, cullingID);
}

void MEAPI McdSpacePairIteratorBegin(McdSpaceID s, McdSpacePairIterator *iter) {
  static const char *fn = "McdSpacePairIteratorBegin";
  ME_REQUIRE_ARG(s != nullptr && iter != nullptr, fn, "space or iterator is NULL");
  PairIterator it;
  s->core->PairIteratorBegin(&it);
  iter->generation = it.generation;
  iter->nextGoodbye = iter->nextHello = iter->nextStaying = 0;
}

int MEAPI McdSpaceGetPairs(McdSpaceID s, McdSpacePairIterator *iter, McdModelPairContainer *c) {
  return Fill(s, iter, c, Want::Pairs, "McdSpaceGetPairs");
}

int MEAPI McdSpaceGetTransitions(McdSpaceID s, McdSpacePairIterator *iter, McdModelPairContainer *c) {
  return Fill(s, iter, c, Want::Transitions, "McdSpaceGetTransitions");
}

}  // extern "C"

int karma::mcd::GetActivePairs(McdSpaceID s, McdSpacePairIterator *iter, McdModelPairContainer *c) {
  return Fill(s, iter, c, Want::ActivePairs, "McdSpaceGetPairs");
}
