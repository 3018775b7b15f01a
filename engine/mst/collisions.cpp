// collisions.cpp: MstHandleCollisions, collision contacts to dynamics
// contacts (see MstBridge.h for the rules and the callbacks' order).
//
// Per hello or staying pair:
//   skip       both models frozen (the group keeps its contacts), or no body
//   intersect  McdIntersect into the bridge's buffer, reporting contacts up
//              to a speculative margin ahead of touching (below)
//   convert    on touch: Intersect CB; the group on first touch; this
//              step's contacts matched to the group's (contact_cache.h:
//              a contact reported again keeps its MdtContact and impulses),
//              each with the materials' params (PerContact CB); PerPair CB;
//              the group enabled iff it has contacts
// Body order: model1's body is body 0 unless model1 has none, in which
// case model2's body is body 0 and every normal is negated (collision
// normals point from model2 towards model1; MdtContact pushes body 0 along
// +normal).
//
// Speculative margin. Contacts are asked for up to
//     margin = tolerance + h * (|v1 - v2| + |w1| rho1 + |w2| rho2 + |g| h)
// apart, with h the world's last step size, v, w the bodies' velocities and
// rho how far a turn of a model moves its surface per radian (TurnReach):
// the most the gap can close in the coming step. A contact found
// apart has a negative penetration, and its normal row lets the gap close
// within the step but no further (engine/mdt/bcl/contact.cpp).
#include <cmath>
#include <cstdint>

#include "contact_cache.h"
#include "mdt_bridge.h"
#include "mst_internal.h"

using namespace karma::mst;

namespace {

void ClearContacts(MdtContactGroupID g) {
  while (MdtContactID c = MdtContactGroupGetFirstContact(g)) MdtContactGroupDestroyContact(g, c);
}

// How far a turn of the model about its origin can move its surface
// towards another shape, per radian: at most rho_out - rho_in, the largest
// and smallest distances from the origin to the surface. Bounded here from
// the geometry's own box (half its diagonal, less half its smallest side);
// a sphere turning about its centre does not move its surface at all.
// d is the edge lengths of that box. A box geometry's AABB about its own
// origin is exactly [-half, half] (each bound is one half length plus
// zeros), so its d = 2 half is read from the radii, bit for bit the
// AABB's hi - lo.
MeReal TurnReach(McdModelID m) {
  McdGeometryID g = McdModelGetGeometry(m);
  const int type = McdGeometryGetType(g);
  if (type == kMcdGeometryTypeSphere) return 0;
  MeVector3 d;
  if (type == kMcdGeometryTypeBox) {
    McdBoxGetRadii(g, d);
    MeVector3Scale(d, 2);
  } else {
    static const MeMatrix4 kIdentity = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    MeVector3 lo, hi;
    McdGeometryGetAABB(g, kIdentity, lo, hi);
    MeVector3Subtract(d, hi, lo);
  }
  const MeReal smallest = d[0] < d[1] ? (d[0] < d[2] ? d[0] : d[2]) : (d[1] < d[2] ? d[1] : d[2]);
  const MeReal r = (MeReal)0.5 * (MeVector3Magnitude(d) - smallest);
  return std::isfinite(r) && r > 0 ? r : 0;
}

// The most the two models' gap can close in the coming step (see the top).
MeReal ClosingDistance(McdModelID m1, McdModelID m2, MdtWorldID world) {
  const MeReal h = MdtWorldGetLastStepSize(world);
  if (!(h > 0)) return 0;
  MeVector3 v = {0, 0, 0}, g;
  MeReal angular = 0;
  const McdModelID models[2] = {m1, m2};
  for (int k = 0; k < 2; ++k) {
    MdtBodyID b = McdModelGetBody(models[k]);
    if (!b || !MdtBodyIsEnabled(b)) continue;
    MeVector3 vb, wb;
    MdtBodyGetLinearVelocity(b, vb);
    MdtBodyGetAngularVelocity(b, wb);
    MeVector3MultiplyAdd(v, k == 0 ? 1 : -1, vb);
    angular += MeVector3Magnitude(wb) * TurnReach(models[k]);
  }
  MdtWorldGetGravity(world, g);
  const MeReal speed = MeVector3Magnitude(v) + angular + MeVector3Magnitude(g) * h;
  const MeReal closing = h * speed;
  return std::isfinite(closing) ? closing : 0;
}

// McdIntersect with the contact tolerance raised by `extra` for this call.
int IntersectWithMargin(McdModelPair *pair, McdIntersectResult *r, MeReal extra) {
  McdFrameworkID fw = McdModelGetFramework(pair->model1);
  const MeReal tolerance = McdFrameworkGetContactTolerance(fw);
  if (extra > 0) McdFrameworkSetContactTolerance(fw, tolerance + extra);
  const int touch = McdIntersect(pair, r);
  if (extra > 0) McdFrameworkSetContactTolerance(fw, tolerance);
  return touch;
}

void Collide(McdModelPair *pair, MdtWorldID world, MstBridge *b) {
  McdModelID m1 = pair->model1, m2 = pair->model2;
  if (McdSpaceModelIsFrozen(m1) && McdSpaceModelIsFrozen(m2)) return;
  MdtBodyID b1 = McdModelGetBody(m1), b2 = McdModelGetBody(m2);
  const bool flip = b1 == nullptr;
  auto group = static_cast<MdtContactGroupID>(pair->responseData);
  // A group acts between the bodies the models had when it was made, with
  // the normal's sign that goes with them; a model given another body since
  // (McdModelSetBody in a callback: from the pair's next collision on;
  // between steps McdModelSetBody drops the groups itself), or none, needs
  // a new one or none.
  if (group && (MdtContactGroupGetBody(group, 0) != (flip ? b2 : b1) ||
                MdtContactGroupGetBody(group, 1) != (flip ? nullptr : b2))) {
    DropContactGroup(pair);
    group = nullptr;
  }
  if (b1 == b2) return;  // no body, or one body's two models: nothing to push apart

  McdIntersectResult r{};
  r.contacts = b->contacts;
  r.contactMaxCount = kContactBuffer;
  int count = 0;
  MaterialEntry *e = nullptr;
  if (IntersectWithMargin(pair, &r, ClosingDistance(m1, m2, world)) && r.contactCount > 0) {
    e = Entry(b, McdModelGetMaterial(m1), McdModelGetMaterial(m2), "MstHandleCollisions");
    if (!e) e = &b->materials[0];  // (warned) an unknown material acts as the default
    count = (e->intersectCB && !e->intersectCB(&r)) ? 0 : r.contactCount;
  }
  if (count > kContactBuffer) count = kContactBuffer;
  if (count > 0 && !group) {
    group = MdtContactGroupCreate(world);
    if (!group) return;  // the constraint pool is full (it warned)
    MdtContactGroupSetBodies(group, flip ? b2 : b1, flip ? nullptr : b2);
    pair->responseData = group;
  }
  if (!group) return;
  if (count == 0) {
    ClearContacts(group);
  } else {
    const MeReal reach = kMatchDistance * McdFrameworkGetLengthScale(McdModelGetFramework(m1));
    MatchContacts(group, r.contacts, count, flip ? -1 : 1, e->params, reach, e->perContactCB, &r);
    if (e->perPairCB && !e->perPairCB(&r, group)) ClearContacts(group);
  }
  if (MdtContactGroupGetCount(group) > 0)
    MdtContactGroupEnable(group);
  else
    MdtContactGroupDisable(group);
}

// The coming pairs' memory, asked for ahead of their turn: a heap's pairs,
// models and contact memories were allocated as the scene made them, so a
// pair's first touch of them would wait on memory. Three pairs ahead the
// pair itself; two ahead what it points to: its models, its contact group's
// header and hints (mdt_bridge.h), and of the collision's contact memory (a
// header and the kept contacts) the eight lines of a box resting on four
// (contact_reuse.cpp); one ahead the group's contacts, through the hints
// read from the header asked for a pair before (walking the group's list
// instead waits on each link in turn). The contact memory's addresses are
// integers: the last lines may lie past a smaller block, which a prefetch
// may touch but pointer arithmetic may not name. A prefetch changes no
// result. Always inlined: GCC takes a function that only prefetches for one
// without effects and drops its calls.
[[gnu::always_inline]] inline void PrefetchAhead(const McdModelPairContainer *pairs, int i) {
  if (i + 3 < pairs->stayingEnd) __builtin_prefetch(pairs->array[i + 3]);
  if (i + 2 < pairs->stayingEnd) {
    const McdModelPair *next = pairs->array[i + 2];
    __builtin_prefetch(next->model1);
    __builtin_prefetch(next->model2);
    if (next->responseData) MdtContactGroupPrefetch(static_cast<MdtContactGroupID>(next->responseData));
    if (const auto memory = reinterpret_cast<std::uintptr_t>(next->m_contactMemory))
      for (std::uintptr_t line = 0; line < 8; ++line)
        __builtin_prefetch(reinterpret_cast<const void *>(memory + 64 * line));
  }
  if (i + 1 < pairs->stayingEnd)
    if (auto group = static_cast<MdtContactGroupID>(pairs->array[i + 1]->responseData))
      MdtContactGroupPrefetchContacts(group);
}

}  // namespace

extern "C" {

void MEAPI MstHandleCollisions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world, MstBridgeID b) {
  static const char *fn = "MstHandleCollisions";
  ME_REQUIRE_ARG(pairs != nullptr && world != nullptr && b != nullptr, fn, "container, world or bridge is NULL");
  (void)space;  // frozen states are read through the models
  for (int i = pairs->helloFirst; i < pairs->stayingEnd; ++i) {
    PrefetchAhead(pairs, i);
    Collide(pairs->array[i], world, b);
  }
}

}  // extern "C"
