// nearfield.h: what every interaction file uses.
//
// Adding an interaction family (say box-box, in nearfield/box_box.cpp):
//  1. write `int MEAPI BoxBoxIntersect(McdModelPair *p, McdIntersectResult *r)`
//     for model1 of the first type and model2 of the second; fill at most
//     r->contactMaxCount contacts with Emit(), set r->touch and r->normal
//     (McdContact.h: normal from model2 towards model1, separation < 0 in
//     penetration) and return r->touch;
//  2. add `void MEAPI McdBoxBoxRegisterInteraction(McdFrameworkID)` that
//     calls RegisterInteractionQuietly(fw, typeA, typeB, record) once (the
//     table answers the reversed order), declare it in McdInteraction.h;
//  3. call it from McdPrimitivesRegisterInteractions (framework/registry.cpp)
//     and, for sphere/box/plane pairs, McdSphereBoxPlaneRegisterInteractions;
//  4. list the file in engine/mcd/CMakeLists.txt and test both orders.
#pragma once

#include "mcd_internal.h"

namespace karma::mcd {

// Registers (a, b) unless either type is unregistered (then nothing).
void RegisterInteractionQuietly(McdFramework *fw, int a, int b, const McdInteractions &fns);

// The world TM of a model (valid after McdModelUpdate).
inline MeMatrix4Ptr ModelTM(const McdModel *m) { return m->instance.tm; }

// Appends a contact if there is room; returns false when the buffer is full.
inline bool Emit(McdIntersectResult *r, const MeVector3 position, const MeVector3 normal,
                 MeReal separation, int dims1, int dims2) {
    if (r->contactCount >= r->contactMaxCount) return false;
    McdContact &c = r->contacts[r->contactCount++];
    MeVector3Copy(c.position, position);
    MeVector3Copy(c.normal, normal);
    c.separation = separation;
    c.dims = (MeI16)((dims1 & 0xFF) | ((dims2 & 0xFF) << 8));
    c.spare = 0;
    c.element1.ptr = nullptr;
    c.element2.ptr = nullptr;
    c.feature = 0;
    return true;
}

}  // namespace karma::mcd
