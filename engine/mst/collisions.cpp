// collisions.cpp: MstHandleCollisions, collision contacts to dynamics
// contacts (see MstBridge.h for the rules and the callbacks' order).
//
// Per hello or staying pair:
//   skip       both models frozen (the group keeps its contacts), or no body
//   intersect  McdIntersect into the bridge's buffer; the group's old
//              contacts are destroyed (contacts are re-made every step)
//   convert    on touch: Intersect CB; the group on first touch; one
//              MdtContact per collision contact with the materials' params
//              (PerContact CB); PerPair CB; enabled iff it has contacts
// Body order: model1's body is body 0 unless model1 has none, in which
// case model2's body is body 0 and every normal is negated (collision
// normals point from model2 towards model1; MdtContact pushes body 0 along
// +normal).
#include "mst_internal.h"

using namespace karma::mst;

namespace {

void ClearContacts(MdtContactGroupID g) {
    while (MdtContactID c = MdtContactGroupGetFirstContact(g)) MdtContactGroupDestroyContact(g, c);
}

void Collide(McdModelPair *pair, MdtWorldID world, MstBridge *b) {
    McdModelID m1 = pair->model1, m2 = pair->model2;
    if (McdSpaceModelIsFrozen(m1) && McdSpaceModelIsFrozen(m2)) return;
    MdtBodyID b1 = McdModelGetBody(m1), b2 = McdModelGetBody(m2);
    if (!b1 && !b2) return;
    const bool flip = b1 == nullptr;
    auto group = static_cast<MdtContactGroupID>(pair->responseData);
    if (group) ClearContacts(group);

    McdIntersectResult r{};
    r.contacts = b->contacts;
    r.contactMaxCount = kContactBuffer;
    int count = 0;
    MaterialEntry *e = nullptr;
    if (McdIntersect(pair, &r) && r.contactCount > 0) {
        e = Entry(b, McdModelGetMaterial(m1), McdModelGetMaterial(m2), "MstHandleCollisions");
        if (!e) e = &b->materials[0];  // (warned) an unknown material acts as the default
        count = (e->intersectCB && !e->intersectCB(&r)) ? 0 : r.contactCount;
    }
    if (count > 0 && !group) {
        group = MdtContactGroupCreate(world);
        if (!group) return;  // the constraint pool is full (it warned)
        MdtContactGroupSetBodies(group, flip ? b2 : b1, flip ? nullptr : b2);
        pair->responseData = group;
    }
    const MeReal sign = flip ? -1 : 1;
    for (int i = 0; i < count && i < kContactBuffer; ++i) {
        const McdContact &cc = r.contacts[i];
        MdtContactID c = MdtContactGroupCreateContact(group);
        if (!c) break;
        MdtContactSetPosition(c, cc.position[0], cc.position[1], cc.position[2]);
        MdtContactSetNormal(c, sign * cc.normal[0], sign * cc.normal[1], sign * cc.normal[2]);
        MdtContactSetPenetration(c, -cc.separation);
        MdtContactSetParams(c, &e->params);
        if (e->perContactCB && !e->perContactCB(&r, &r.contacts[i], c))
            MdtContactGroupDestroyContact(group, c);
    }
    if (group && count > 0 && e->perPairCB && !e->perPairCB(&r, group)) ClearContacts(group);
    if (!group) return;
    if (MdtContactGroupGetCount(group) > 0)
        MdtContactGroupEnable(group);
    else
        MdtContactGroupDisable(group);
}

}  // namespace

extern "C" {

void MEAPI MstHandleCollisions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world,
                               MstBridgeID b) {
    static const char *fn = "MstHandleCollisions";
    ME_REQUIRE_ARG(pairs != nullptr && world != nullptr && b != nullptr, fn,
                   "container, world or bridge is NULL");
    (void)space;  // frozen states are read through the models
    for (int i = pairs->helloFirst; i < pairs->stayingEnd; ++i) Collide(pairs->array[i], world, b);
}

}  // extern "C"
