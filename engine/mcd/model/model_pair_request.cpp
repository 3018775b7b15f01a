// model_pair_request.cpp: McdModelPairSetRequestPtr / GetRequestPtr, the
// application's request on a pair (McdModelPair.h). McdIntersect reads it
// (framework/dispatch.cpp) through EffectiveContactCap.
#include "mcd_internal.h"

extern "C" {

void MEAPI McdModelPairSetRequestPtr(McdModelPairID p, McdRequest *request) {
  static const char *fn = "McdModelPairSetRequestPtr";
  ME_REQUIRE_ARG(p != nullptr, fn, "pair is NULL");
  ME_REQUIRE_ARG(!p->m_helloed, fn, "the pair is between McdHello and McdGoodbye; the request is not changed");
  ME_REQUIRE_ARG(request == nullptr || request->contactMaxCount >= 0, fn,
                 "request->contactMaxCount is negative (%d); ignored", request ? request->contactMaxCount : 0);
  p->m_request = request;
}

McdRequest *MEAPI McdModelPairGetRequestPtr(McdModelPairID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, nullptr, "McdModelPairGetRequestPtr", "pair is NULL");
  return p->m_request;
}

}  // extern "C"

namespace karma::mcd {

int EffectiveContactCap(const McdModelPair *pair, int resultCap) {
  const McdRequest *r = pair->m_request;
  if (!r || r->contactMaxCount <= 0) return resultCap;
  return r->contactMaxCount < resultCap ? r->contactMaxCount : resultCap;
}

}  // namespace karma::mcd
