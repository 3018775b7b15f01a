// nearfield.h: what every interaction file uses.
//
// Adding an interaction family (say box-box, in nearfield/box_box.cpp):
//  1. write `int MEAPI BoxBoxIntersect(McdModelPair *p, McdIntersectResult *r)`
//     for model1 of the first type and model2 of the second; fill at most
//     r->contactMaxCount contacts with Emit(), set r->touch and r->normal
//     (McdContact.h: normal from model2 towards model1, separation < 0 in
//     penetration), give each contact a feature id (feature_id.h: distinct
//     within the result, stable while the same features touch) and return
//     r->touch;
//  2. add `void MEAPI McdBoxBoxRegisterInteraction(McdFrameworkID)` that
//     calls RegisterInteractionQuietly(fw, typeA, typeB, record) once (the
//     table answers the reversed order), declare it in McdInteraction.h;
//  3. call it from McdPrimitivesRegisterInteractions (framework/registry.cpp)
//     and, for sphere/box/plane pairs, McdSphereBoxPlaneRegisterInteractions;
//  4. list the file in engine/mcd/CMakeLists.txt and test both orders.
#pragma once

#include "mcd_internal.h"

#include <functional>

namespace karma::mcd {

// Registers (a, b) unless either type is unregistered (then nothing).
void RegisterInteractionQuietly(McdFramework *fw, int a, int b, const McdInteractions &fns);

// The world TM of a model (valid after McdModelUpdate).
inline MeMatrix4Ptr ModelTM(const McdModel *m) { return m->instance.tm; }

// The fixed order in which a same-type pair is computed: true when `a`
// goes first. By the models' sort keys where they differ (so the result
// does not depend on creation order, as the guide promises); on equal keys
// by the address of the world TM (the model's or, for an
// aggregate's child, the child's own storage), then of the geometry, then
// of the model: it does not change while the models move, and it is the
// same whichever model an aggregate's stand-in copy is, so (a, b) and
// (b, a) give mirrored contacts with the same feature ids.
inline bool ComputedFirst(const McdModel *a, const McdModel *b) {
  const MeI32 ka = EffectiveSortKey(a), kb = EffectiveSortKey(b);
  if (ka != kb) return ka < kb;
  const std::less<const void *> before;
  if (a->instance.tm != b->instance.tm) return before(a->instance.tm, b->instance.tm);
  if (a->instance.geometry != b->instance.geometry) return before(a->instance.geometry, b->instance.geometry);
  return !before(b, a);
}

// Appends a contact if there is room; returns false when the buffer is full.
// `feature` is the contact's feature id (its encoding: feature_id.h).
inline bool Emit(McdIntersectResult *r, const MeVector3 position, const MeVector3 normal, MeReal separation, int dims1,
                 int dims2, MeU32 feature) {
  if (r->contactCount >= r->contactMaxCount) return false;
  McdContact &c = r->contacts[r->contactCount++];
  MeVector3Copy(c.position, position);
  MeVector3Copy(c.normal, normal);
  c.separation = separation;
  c.dims = (MeI16)((dims1 & 0xFF) | ((dims2 & 0xFF) << 8));
  c.spare = 0;
  c.element1.ptr = nullptr;
  c.element2.ptr = nullptr;
  c.feature = feature;
  return true;
}

}  // namespace karma::mcd
