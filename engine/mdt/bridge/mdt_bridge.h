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
 *    that Mdt enables or disables. */
#ifndef KARMA_MDT_BRIDGE_H
#define KARMA_MDT_BRIDGE_H
#include "MdtBody.h"

ME_EXTERN_C_BEGIN

MEPUBLIC MeReal *MEAPI MdtBodyGetLinearVelocityPtr(const MdtBodyID body);
MEPUBLIC MeReal *MEAPI MdtBodyGetAngularVelocityPtr(const MdtBodyID body);
MEPUBLIC void MEAPI MdtBodySetCollisionModel(const MdtBodyID body, void *model);
MEPUBLIC void *MEAPI MdtBodyGetCollisionModel(const MdtBodyID body);

ME_EXTERN_C_END
#endif
