// dispatch.cpp: McdHello / McdIntersect / McdGoodbye / McdNearby.
//
// A mirrored table entry (swap = 1) holds functions written for the other
// order. For the call the pair's models are exchanged; afterwards every
// contact is turned back into the caller's order:
//   normal -> -normal            (it points from model2 towards model1)
//   element1 <-> element2
//   dims low byte <-> high byte
// The separation and position do not depend on the order.
//
// Contact reuse (contact_reuse.h): a pair of served types is tested at the
// caller's tolerance plus the reuse distance; when every contact found is
// within the tolerance, that is the answer and it is remembered, else the
// pair is tested again at the tolerance. Later calls are served from the
// memory while the reuse rule holds. A call with room for no contact is
// always tested (its answer is `touch` alone). The memory lives in
// m_contactMemory from the first test to McdGoodbye.
#include "contact_reuse.h"
#include "mcd_internal.h"

#include <utility>

namespace {

void Swap(McdModelPair *pair) { std::swap(pair->model1, pair->model2); }

void TurnRound(McdIntersectResult *r) {
  for (int i = 0; i < r->contactCount; ++i) {
    McdContact &c = r->contacts[i];
    MeVector3Negate(c.normal);
    std::swap(c.element1, c.element2);
    const unsigned d = (unsigned)(unsigned short)c.dims;
    c.dims = (MeI16)(((d & 0xFFu) << 8) | (d >> 8));
  }
  MeVector3Negate(r->normal);
}

// Calls fn with the pair in the order the interaction expects.
template <class F>
void InOrder(McdModelPair *pair, bool swap, F &&fn) {
  if (swap) Swap(pair);
  fn();
  if (swap) Swap(pair);
}

// No contact, no touch, no normal: what a result holds before a test.
void Clear(McdIntersectResult *result) {
  result->contactCount = 0;
  result->touch = 0;
  MeVector3Set(result->normal, 0, 0, 0);
}

// The result names the pair and its models.
void Name(McdIntersectResult *result, McdModelPair *pair) {
  result->pair = pair;
  result->model1 = pair->model1;
  result->model2 = pair->model2;
}

// The interaction's test of the pair, at most `cap` contacts, in the
// caller's order.
void Test(McdModelPair *pair, const McdInteractions *e, McdIntersectResult *result, int cap) {
  const bool swap = e->swap != 0;
  const int resultCap = result->contactMaxCount;
  result->contactMaxCount = cap;
  InOrder(pair, swap, [&] {
    result->model1 = pair->model1;  // the interaction's order
    result->model2 = pair->model2;
    e->intersectFn(pair, result);
  });
  result->model1 = pair->model1;
  result->model2 = pair->model2;
  if (result->contactCount > result->contactMaxCount) result->contactCount = result->contactMaxCount;
  result->contactMaxCount = resultCap;
  if (result->contactCount < 0) result->contactCount = 0;
  if (swap) TurnRound(result);
}

}  // namespace

extern "C" {

void MEAPI McdHello(McdModelPair *pair) {
  static const char *fn = "McdHello";
  ME_REQUIRE_ARG(pair != nullptr, fn, "pair is NULL");
  ME_REQUIRE_ARG(pair->model1 && pair->model2, fn, "the pair has a NULL model");
  if (pair->m_helloed) return;
  pair->m_helloed = 1;
  pair->m_interaction = nullptr;
  pair->m_cachedData = nullptr;
  McdFramework *fw = pair->model1->framework;
  if (fw != pair->model2->framework) {
    MeArgumentWarning(fn, "the models belong to different frameworks; they will not collide");
    return;
  }
  const McdInteractions *e = McdFrameworkGetInteraction(fw, McdGeometryGetTypeId(pair->model1->instance.geometry),
                                                        McdGeometryGetTypeId(pair->model2->instance.geometry));
  pair->m_interaction = e;
  karma::mcd::HoldInteraction(e);
  if (e && e->helloFn) InOrder(pair, e->swap != 0, [&] { e->helloFn(pair); });
}

void MEAPI McdGoodbye(McdModelPair *pair) {
  ME_REQUIRE_ARG(pair != nullptr, "McdGoodbye", "pair is NULL");
  if (!pair->m_helloed) return;
  const McdInteractions *e = pair->m_interaction;
  if (e && e->goodbyeFn) InOrder(pair, e->swap != 0, [&] { e->goodbyeFn(pair); });
  karma::mcd::ReleaseInteraction(e);
  pair->m_interaction = nullptr;
  pair->m_cachedData = nullptr;
  karma::mcd::Forget(pair);
  pair->m_helloed = 0;
}

MeBool MEAPI McdNearby(McdModelPair *pair) {
  static const char *fn = "McdNearby";
  ME_REQUIRE_ARG_RET(pair != nullptr, 0, fn, "pair is NULL");
  ME_REQUIRE_ARG_RET(pair->model1 && pair->model2, 0, fn, "the pair has a NULL model");
  const McdGeometryInstance &a = pair->model1->instance, &b = pair->model2->instance;
  for (int k = 0; k < 3; ++k)
    if (a.aabbMax[k] < b.aabbMin[k] || b.aabbMax[k] < a.aabbMin[k]) return 0;
  return 1;
}

}  // extern "C"

namespace {

// McdIntersect after its argument checks; `reuse` false tests every call.
int Intersect(McdModelPair *pair, McdIntersectResult *result, bool reuse) {
  // The interaction the pair was greeted with, even if the table has been
  // given another or none since; a pair greeted with none is ignored.
  const McdInteractions *e = pair->m_interaction;
  if (!e) return 0;
  const int resultCap = result->contactMaxCount;
  const int cap = karma::mcd::EffectiveContactCap(pair, resultCap);
  McdFramework *fw = pair->model1->framework;
  const MeReal tolerance = fw->contactTolerance;
  const MeReal d = reuse && cap > 0 ? karma::mcd::ReuseDistance(pair) : 0;
  if (!(d > 0)) {
    Test(pair, e, result, cap);
    return result->touch;
  }
  const karma::mcd::RelativePose now = karma::mcd::PoseOf(pair->model1, pair->model2);
  if (karma::mcd::ServeFromMemory(pair, result, tolerance, cap, d, now)) return result->touch;
  fw->contactTolerance = tolerance + d;
  Test(pair, e, result, cap);
  fw->contactTolerance = tolerance;
  if (karma::mcd::AllWithin(result, tolerance)) {
    karma::mcd::Remember(pair, result, tolerance + d, cap, now);
    return result->touch;
  }
  // A contact beyond the tolerance may have taken the place of one within
  // it when the interaction reduced its points: the call's answer is a
  // test at the tolerance, and nothing is remembered.
  Clear(result);
  Test(pair, e, result, cap);
  return result->touch;
}

}  // namespace

namespace karma::mcd {

int IntersectWithoutReuse(McdModelPair *pair, McdIntersectResult *result) {
  Clear(result);
  Name(result, pair);
  return Intersect(pair, result, false);
}

}  // namespace karma::mcd

extern "C" {

int MEAPI McdIntersect(McdModelPair *pair, McdIntersectResult *result) {
  static const char *fn = "McdIntersect";
  ME_REQUIRE_ARG_RET(result != nullptr, 0, fn, "result is NULL");
  Clear(result);
  ME_REQUIRE_ARG_RET(pair != nullptr, 0, fn, "pair is NULL");
  ME_REQUIRE_ARG_RET(pair->model1 && pair->model2, 0, fn, "the pair has a NULL model");
  Name(result, pair);
  ME_REQUIRE_ARG_RET(result->contactMaxCount >= 0, 0, fn, "result->contactMaxCount is negative (%d)",
                     result->contactMaxCount);
  ME_REQUIRE_ARG_RET(result->contacts != nullptr || result->contactMaxCount == 0, 0, fn,
                     "result->contacts is NULL but contactMaxCount is %d", result->contactMaxCount);
  ME_REQUIRE_ARG_RET(pair->m_helloed, 0, fn, "call McdHello on the pair first");
  return Intersect(pair, result, true);
}

void MEAPI McdHelloEach(McdModelPairContainer *pairs) {
  ME_REQUIRE_ARG(pairs != nullptr, "McdHelloEach", "container is NULL");
  for (int i = pairs->helloFirst; i < pairs->helloEnd; ++i) McdHello(pairs->array[i]);
}

void MEAPI McdGoodbyeEach(McdModelPairContainer *pairs) {
  ME_REQUIRE_ARG(pairs != nullptr, "McdGoodbyeEach", "container is NULL");
  for (int i = pairs->goodbyeFirst; i < pairs->goodbyeEnd; ++i) McdGoodbye(pairs->array[i]);
}

}  // extern "C"
