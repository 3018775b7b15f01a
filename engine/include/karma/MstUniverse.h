/* MstUniverse.h: a collision framework, a space, a dynamics world and a
 * bridge made and stepped together, and models with bodies.
 *
 *   MstUniverseSizes sizes = MstUniverseDefaultSizes;
 *   MstUniverseID u = MstUniverseCreate(&sizes);
 *   ... MstModelAndBodyCreate / MstFixedModelCreate ...
 *   MstUniverseStep(u, h);   // models' keys and padding for the step;
 *                            // McdSpaceUpdateAll; MstBridgeUpdateContacts;
 *                            // MdtWorldStep
 *   MstUniverseDestroy(u);   // every body, constraint, model, geometry
 *
 * MstUniverseCreate: McdInit(collisionUserGeometryTypesMaxCount,
 * collisionModelsMaxCount, collisionGeometryInstancesMaxCount, lengthScale)
 * with every primitive type and interaction registered;
 * McdSpaceAxisSortCreate(McdAllAxes, collisionModelsMaxCount,
 * collisionPairsMaxCount); MdtWorldCreate(dynamicBodiesMaxCount,
 * dynamicConstraintsMaxCount, lengthScale, massScale); MstBridgeCreate
 * (materialsMaxCount); MstSetWorldHandlers. */
#ifndef KARMA_MSTUNIVERSE_H
#define KARMA_MSTUNIVERSE_H
#include "MstBridge.h"

ME_EXTERN_C_BEGIN

typedef struct MstUniverseSizes {
  int dynamicBodiesMaxCount;
  int dynamicConstraintsMaxCount;
  int collisionUserGeometryTypesMaxCount;
  int collisionModelsMaxCount;
  int collisionPairsMaxCount;
  int collisionGeometryInstancesMaxCount;
  int materialsMaxCount;
  MeReal lengthScale;
  MeReal massScale;
} MstUniverseSizes;

/* Appendix A: 100, 500, 0, 100, 500, 100, 10, 1, 1 (in the order above). */
MEPUBLIC extern const MstUniverseSizes MstUniverseDefaultSizes;

typedef struct MstUniverse {
  MdtWorldID world;
  McdFrameworkID frame;
  McdSpaceID space;
  MstBridgeID bridge;
  MstUniverseSizes sizes;
} MstUniverse;
typedef MstUniverse *MstUniverseID;

/* NULL with a warning on bad sizes (counts < 0, no models, pairs, bodies or
 * materials, non-positive scales). */
MEPUBLIC MstUniverseID MEAPI MstUniverseCreate(const MstUniverseSizes *sizes);
MEPUBLIC void MEAPI MstUniverseDestroy(MstUniverseID universe);
MEPUBLIC void MEAPI MstUniverseStep(MstUniverseID universe, MeReal stepSize);
/* The first stage of MstUniverseStep alone: every unfrozen model takes its
 * body's sort key and a bounds padding for a step of stepSize (how far it
 * can move in it), so that the space pairs it with what it can reach within
 * the step and the bridge finds the contacts before it touches. A program
 * that runs the stages itself (to time them apart) calls it before
 * McdSpaceUpdateAll; stepSize > 0. */
MEPUBLIC void MEAPI MstUniversePrepareStep(MstUniverseID universe, MeReal stepSize);

MEPUBLIC MdtWorldID MEAPI MstUniverseGetWorld(MstUniverseID universe);
MEPUBLIC McdSpaceID MEAPI MstUniverseGetSpace(MstUniverseID universe);
MEPUBLIC MstBridgeID MEAPI MstUniverseGetBridge(MstUniverseID universe);
MEPUBLIC McdFrameworkID MEAPI MstUniverseGetFramework(MstUniverseID universe);

/* A model of `geometry` with a new enabled body whose mass properties come
 * from the geometry at `density` (MstAutoSetMassProperties), joined by
 * McdModelSetBody and inserted into the universe's space. */
MEPUBLIC McdModelID MEAPI MstModelAndBodyCreate(MstUniverseID universe, McdGeometryID geometry, MeReal density);
/* Removes the model from its space (its contact groups go at once), then
 * destroys body and model (not the geometry). */
MEPUBLIC void MEAPI MstModelAndBodyDestroy(McdModelID model);
/* A model with no body at *tm (the pointer is kept, not copied), inserted,
 * updated and frozen. */
MEPUBLIC McdModelID MEAPI MstFixedModelCreate(MstUniverseID universe, McdGeometryID geometry, MeMatrix4Ptr tm);
MEPUBLIC void MEAPI MstFixedModelDestroy(McdModelID model);

/* Mass, inertia tensor (about the centre of mass) and centre-of-mass offset
 * of the body from the geometry at `density` (McdGeometryGetMassProperties).
 * A geometry without volume (plane, triangle list) warns and leaves the
 * body unchanged. */
MEPUBLIC void MEAPI MstAutoSetMassProperties(MdtBodyID body, McdGeometryID geometry, MeReal density);

/* A model with a body: the body back at the origin, identity orientation,
 * at rest. */
MEPUBLIC void MEAPI McdModelDynamicsReset(McdModelID model);

ME_EXTERN_C_END
#endif /* KARMA_MSTUNIVERSE_H */
