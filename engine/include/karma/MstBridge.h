/* MstBridge.h: the bridge between Karma Collision and Karma Dynamics.
 *
 * Each step, MstBridgeUpdateContacts runs the guide's loop:
 *   McdSpaceEndChanges(space);
 *   McdSpacePairIteratorBegin(space, &iter);
 *   do { McdModelPairContainerReset(pairs);
 *        overflow = McdSpaceGetPairs(space, &iter, pairs);
 *        MstHandleTransitions(pairs);
 *        MstHandleCollisions(pairs, space, world, bridge);
 *   } while (overflow);
 *   McdSpaceBeginChanges(space);
 * so between steps the space is inside a change block (models may be
 * inserted, removed and updated there, as the guide's programs do).
 *
 * Transitions: a hello pair gets McdHello; a goodbye pair loses its contact
 * group (pair->responseData, destroyed) and gets McdGoodbye.
 * Collisions: for each hello or staying pair with at least one model not
 * frozen and two different bodies (or one), McdIntersect; the pair's
 * MdtContactGroup is the bridge's: created on first touch and kept until the
 * goodbye, or until a model of the pair is given another body or none
 * (McdModelSetBody), when it is destroyed and, on touch, made again between
 * the new bodies (a group ID kept from a callback then dangles; a program
 * does not set a bridge group's bodies itself). Its contacts are re-created
 * every step from the collision contacts with the contact parameters of the
 * two models' materials. A pair of two frozen models is otherwise left as it
 * is (its group keeps its contacts while the bodies sleep). When
 * one model has no body, the dynamic body is the group's body 0 (the
 * guide's body1) and the normals are turned to point towards it.
 *
 * Materials: a symmetric table of materialsMaxCount^2 entries, each a
 * MdtContactParams and three callbacks; (a, b) and (b, a) are one entry.
 * Material 0 is the default (MstBridgeGetDefaultMaterial()).
 *
 * Callbacks, per pair of materials (NULL = none), in this order:
 *   Intersect   once per touching pair, with the collision contacts (it may
 *               edit or cull result->contacts / contactCount). Returning 0
 *               drops the pair's contacts for this step.
 *   PerContact  once per dynamics contact made, with the collision contact
 *               it came from. Returning 0 deletes that MdtContact.
 *   PerPair     once per pair with the contact group holding the step's
 *               contacts. Returning 0 deletes the whole set.
 * A group left without contacts is disabled until it has some again. */
#ifndef KARMA_MSTBRIDGE_H
#define KARMA_MSTBRIDGE_H
#include "MeCall.h"
#include "MePrecision.h"
#include "Mdt.h"
#include "Mcd.h"

ME_EXTERN_C_BEGIN

typedef struct MstBridge MstBridge;
typedef MstBridge *MstBridgeID;
typedef int MstMaterialID;

typedef MeBool(MEAPI *MstIntersectCBPtr)(McdIntersectResult *result);
typedef MeBool(MEAPI *MstPerContactCBPtr)(McdIntersectResult *result, McdContact *colC, MdtContactID dynC);
typedef MeBool(MEAPI *MstPerPairCBPtr)(McdIntersectResult *result, MdtContactGroupID contacts);

/* The default material, 0. */
#define MstBridgeGetDefaultMaterial() ((MstMaterialID)0)

/* A bridge with a material table of maxMaterials (>= 1) materials, the
 * default one in use; NULL with a warning on bad input. */
MEPUBLIC MstBridgeID MEAPI MstBridgeCreate(McdFrameworkID framework, const int maxMaterials);
MEPUBLIC void MEAPI MstBridgeDestroy(MstBridgeID bridge);

/* The next unused material, or -1 with a warning when all are in use. */
MEPUBLIC MstMaterialID MEAPI MstBridgeGetNewMaterial(MstBridgeID bridge);
MEPUBLIC int MEAPI MstBridgeGetMaterialCount(MstBridgeID bridge);
/* The parameters of a pair of materials (either order: the same entry);
 * NULL with a warning for a material not in use. */
MEPUBLIC MdtContactParamsID MEAPI MstBridgeGetContactParams(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2);

MEPUBLIC void MEAPI MstBridgeSetIntersectCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2,
                                            MstIntersectCBPtr cb);
MEPUBLIC MstIntersectCBPtr MEAPI MstBridgeGetIntersectCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2);
MEPUBLIC void MEAPI MstBridgeSetPerContactCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2,
                                             MstPerContactCBPtr cb);
MEPUBLIC MstPerContactCBPtr MEAPI MstBridgeGetPerContactCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2);
MEPUBLIC void MEAPI MstBridgeSetPerPairCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2, MstPerPairCBPtr cb);
MEPUBLIC MstPerPairCBPtr MEAPI MstBridgeGetPerPairCB(MstBridgeID bridge, MstMaterialID m1, MstMaterialID m2);

/* The loop at the top of this file (the space must be inside a change
 * block, as McdSpaceAxisSortCreate and the previous call leave it). */
MEPUBLIC void MEAPI MstBridgeUpdateContacts(MstBridgeID bridge, McdSpaceID space, MdtWorldID world);
MEPUBLIC void MEAPI MstHandleTransitions(McdModelPairContainer *pairs);
MEPUBLIC void MEAPI MstHandleCollisions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world,
                                        MstBridgeID bridge);

/* Makes the world freeze the collision model of a body it disables (after
 * one last McdSpaceUpdateModel when the space is in a change block) and
 * unfreeze the model of a body it enables (the body-enable callback of
 * MdtWorld.h; the model is the one McdModelSetBody gave the body). */
MEPUBLIC void MEAPI MstSetWorldHandlers(MdtWorldID world);

ME_EXTERN_C_END
#endif /* KARMA_MSTBRIDGE_H */
