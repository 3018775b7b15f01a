// model_update.cpp: McdModelUpdate and the cached world AABB.
//
//   1. relative transform: TM = relTM composed with linkTM (apply relTM,
//      then linkTM), written to the model's TM pointer;
//   2. the instance tree is placed (child TMs, per-instance AABBs);
//   3. the model's AABB is the top instance's;
//   4. the update callback runs last, so it sees the new AABB.
// A missing or non-finite transform leaves the previous AABB and warns.
#include "mcd_internal.h"

using namespace karma::mcd;

extern "C" {

void MEAPI McdModelUpdate(McdModelID m) {
  static const char *fn = "McdModelUpdate";
  ME_REQUIRE_ARG(m != nullptr, fn, "model is NULL");
  ME_REQUIRE_ARG(m->instance.tm != nullptr, fn,
                 "the model has no transform (McdModelSetTransformPtr or McdModelSetBody)");
  if (m->relTM) MeMatrix4TMCompose(m->instance.tm, m->relTM, m->linkTM);
  ME_REQUIRE_ARG(IsFiniteTM(m->instance.tm), fn, "the model's transform is not finite; its AABB is left as it was");
  PlaceInstance(&m->instance, m->instance.tm);
  m->updated = 1;
  if (m->callback) m->callback(m);
}

void MEAPI McdModelGetAABB(McdModelID m, MeVector3 mn, MeVector3 mx) {
  static const char *fn = "McdModelGetAABB";
  ME_REQUIRE_ARG(mn != nullptr && mx != nullptr, fn, "an output vector is NULL");
  MeVector3Set(mn, 0, 0, 0);
  MeVector3Set(mx, 0, 0, 0);
  ME_REQUIRE_ARG(m != nullptr, fn, "model is NULL");
  MeVector3Copy(mn, m->instance.aabbMin);
  MeVector3Copy(mx, m->instance.aabbMax);
}

}  // extern "C"
