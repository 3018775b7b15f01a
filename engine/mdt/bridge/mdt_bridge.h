/* mdt_bridge.h: what the bridge (Mst) needs of a body beyond the public
 * API. Build tree only, not installed: Mst's private door into Mdt.
 *
 *  - Stable pointers to the body's world-frame linear velocity (of its
 *    centre of mass) and angular velocity, 3 MeReals each, valid for the
 *    body's life: McdModelSetBody points the model's velocity pointers at
 *    them (for McdSafeTime).
 *  - One collision-model slot per body (a void *, NULL by default, never
 *    read by Mdt): McdModelSetBody stores the model there so the world's
 *    body-enable callback (MstSetWorldHandlers) can find the model of a body
 *    that Mdt enables or disables.
 *  - A body-destroy callback: MdtBodyDestroy calls it, while the body is
 *    still valid, for a body whose collision-model slot is set, so the
 *    bridge can detach the model (MstSetWorldHandlers) instead of leaving
 *    it to drive whichever body takes the freed slot next.
 *  - The contact matching's reads and writes (Mst's contact_cache.h), one
 *    call per group or contact instead of one per field:
 *    MdtContactGroupGetContacts writes a group's contacts, in the group's
 *    order, at most `max` of them, and each one's feature, and returns how
 *    many it wrote; MdtContactSetFromCollision has, on a contact, the
 *    effect of MdtContactSetPosition, MdtContactSetNormal,
 *    MdtContactSetPenetration, MdtContactSetParams and
 *    MdtContactSetFeature called in that order, each field checked as
 *    there; a field it ignores warns once under its own name, and a
 *    constraint that is not a contact (or NULL) warns once and is left
 *    unchanged.
 *  - Prefetches for the pairs ahead of the one being matched (they change
 *    no result): MdtContactGroupPrefetch asks for the group's own lines
 *    that the next call reads, MdtContactGroupPrefetchContacts (a contact
 *    group's header already at hand) for the lines of its first contacts
 *    that the matching and the step read. */
#ifndef KARMA_MDT_BRIDGE_H
#define KARMA_MDT_BRIDGE_H
#include "MdtBody.h"
#include "MdtContact.h"
#include "MdtWorld.h"

ME_EXTERN_C_BEGIN

MEPUBLIC MeReal *MEAPI MdtBodyGetLinearVelocityPtr(const MdtBodyID body);
MEPUBLIC MeReal *MEAPI MdtBodyGetAngularVelocityPtr(const MdtBodyID body);
MEPUBLIC void MEAPI MdtBodySetCollisionModel(const MdtBodyID body, void *model);
MEPUBLIC void *MEAPI MdtBodyGetCollisionModel(const MdtBodyID body);
typedef void(MEAPI *MdtBodyDestroyCallbackPtr)(MdtBodyID body, void *model);
MEPUBLIC void MEAPI MdtWorldSetBodyDestroyCallback(MdtWorldID world, MdtBodyDestroyCallbackPtr cb);
MEPUBLIC int MEAPI MdtContactGroupGetContacts(const MdtContactGroupID g, MdtContactID *contacts, MeU32 *features,
                                              int max);
MEPUBLIC void MEAPI MdtContactGroupPrefetch(const MdtContactGroupID g);
MEPUBLIC void MEAPI MdtContactGroupPrefetchContacts(const MdtContactGroupID g);
MEPUBLIC void MEAPI MdtContactSetFromCollision(const MdtContactID c, const MeVector3 position, const MeVector3 normal,
                                               MeReal penetration, const MdtContactParams *params, MeU32 feature);

ME_EXTERN_C_END
#endif
