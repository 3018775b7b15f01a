/* McdModel.h: collision models.
 *
 * A model is what the collision spaces sort and what the nearfield tests:
 * one geometry instance (a geometry placed by a transform), a material, an
 * optional dynamics body and the world AABB cached at its last update.
 * Models come from the framework's model pool (McdInit's modelCount).
 *
 * Transform. A model holds a POINTER to its transform (MeMatrix4: rows 0-2
 * the axes, row 3 the position), never a copy. Until one is given,
 * McdModelGetTransformPtr returns NULL and McdModelUpdate warns. With
 * McdModelSetRelativeTransformPtrs the model's transform is instead
 * computed at each update as relTM composed with a link TM (typically a
 * body's), written into a transform the caller provides.
 *
 * Update. McdModelUpdate (the space calls it for every unfrozen model)
 *   1. composes the relative transform, if one is set;
 *   2. places every child instance of an aggregate;
 *   3. computes and caches the world AABB (McdModelGetAABB);
 *   4. calls the update callback, if one is set.
 *
 * Bodies. McdModelSetBody (declared here, DEFINED IN THE MST LIBRARY since
 * Mcd does not know Mdt) stores the body and points the model's transform
 * and velocity pointers at the body's: link Karma::Mst to use it. Mcd itself
 * only stores the handle (McdModelStoreBody, which Mst calls) and reads the
 * velocities through the pointers (McdModelSetLinearVelocityPtr, ...) for
 * McdSafeTime. A model with no body (fixed terrain) keeps its own TM. */
#ifndef KARMA_MCDMODEL_H
#define KARMA_MCDMODEL_H
#include "MeCall.h"
#include "MePrecision.h"
#include "McdGeometry.h"

ME_EXTERN_C_BEGIN

/* The dynamics body handle, declared as in MdtWorld.h (an identical typedef
 * is valid C11 and C++, so either header may come first). */
#ifndef KARMA_MDTWORLD_H
typedef struct MdtBody *MdtBodyID;
#endif

typedef struct McdModel McdModel;
typedef McdModel *McdModelID;

typedef void(MEAPI *McdModelUpdateCallback)(McdModelID model);

/* A model of `geometry` (not NULL), taking one reference to it; for an
 * aggregate, one child instance per element from the instance pool. NULL
 * with a warning when a pool is exhausted. The model has no transform yet,
 * no body, material 0. */
MEPUBLIC McdModelID MEAPI McdModelCreate(McdGeometryID geometry);
/* Releases the model, its child instances and its geometry reference.
 * A model still in a space is not destroyed (a warning): remove it from
 * the space first. NULL is ignored. */
MEPUBLIC void MEAPI McdModelDestroy(McdModelID model);

MEPUBLIC McdGeometryID MEAPI McdModelGetGeometry(McdModelID model);
MEPUBLIC McdGeometryInstanceID MEAPI McdModelGetGeometryInstance(McdModelID model);
MEPUBLIC McdFrameworkID MEAPI McdModelGetFramework(McdModelID model);

/* The transform pointer (kept, not copied). Setting one clears any relative
 * transform set below. */
MEPUBLIC void MEAPI McdModelSetTransformPtr(McdModelID model, MeMatrix4Ptr tm);
MEPUBLIC MeMatrix4Ptr MEAPI McdModelGetTransformPtr(McdModelID model);
/* Makes the model's transform globalTM = relTM composed with linkTM ("apply
 * relTM, then linkTM"), recomputed at each McdModelUpdate; globalTM becomes
 * the transform pointer. All three are kept by pointer and must be distinct
 * and persistent. relTM NULL clears the relative transform (the transform
 * pointer stays globalTM). */
MEPUBLIC void MEAPI McdModelSetRelativeTransformPtrs(McdModelID model, MeMatrix4Ptr relTM, MeMatrix4Ptr linkTM,
                                                     MeMatrix4Ptr globalTM);
MEPUBLIC MeMatrix4Ptr MEAPI McdModelGetRelativeTransformPtr(McdModelID model);

/* Recomputes what depends on the transform (see the top of this file). */
MEPUBLIC void MEAPI McdModelUpdate(McdModelID model);
MEPUBLIC void MEAPI McdModelSetUpdateCallback(McdModelID model, McdModelUpdateCallback callback);
MEPUBLIC McdModelUpdateCallback MEAPI McdModelGetUpdateCallback(McdModelID model);
/* The world AABB cached at the last McdModelUpdate (zero before the first). */
MEPUBLIC void MEAPI McdModelGetAABB(McdModelID model, MeVector3 minCorner, MeVector3 maxCorner);

/* Material id (default 0), indexing the bridge's material table. */
MEPUBLIC void MEAPI McdModelSetMaterial(McdModelID model, int material);
MEPUBLIC int MEAPI McdModelGetMaterial(McdModelID model);

MEPUBLIC void MEAPI McdModelSetUserData(McdModelID model, void *data);
MEPUBLIC void *MEAPI McdModelGetUserData(McdModelID model);

/* Sort key in [0, 2^15 - 1]; default 0. A space orders its pairs, and the
 * two models inside each pair (model1 first), by their models' keys; only
 * between equal keys does the earlier insertion come first (the rule is in
 * farfield/axis_sort_space.h, "Pair order"). Takes effect at the space's
 * next McdSpaceEndChanges. */
MEPUBLIC void MEAPI McdModelSetSortKey(McdModelID model, int key);
MEPUBLIC int MEAPI McdModelGetSortKey(McdModelID model);
/* Karma extension. The key a model is ordered by while McdModelSetSortKey
 * has never been called on it (>= 0, default 0). MstUniverseStep gives each
 * model with a body its body's key (MdtBodyGetSortKey) this way, so keys set
 * on bodies alone also order the collision pairs; a key set on the model
 * itself always wins. */
MEPUBLIC void MEAPI McdModelSetInheritedSortKey(McdModelID model, MeI32 key);
MEPUBLIC MeI32 MEAPI McdModelGetInheritedSortKey(McdModelID model);

/* Karma extension. Bounds padding: the box a space sorts a model by is its
 * AABB (or the space's AABB function's box) grown on every side by the
 * framework's contact tolerance plus `margin` (>= 0, default 0), read at
 * each McdSpaceUpdateModel / McdSpaceUpdateAll. So the space pairs models
 * up to a gap of twice the tolerance (the nearfield reports contacts up to
 * one tolerance), and up to the margins more. Before each step,
 * MstUniverseStep sets the margin of each model with an enabled body to a
 * bound on how far the model can move in that step (0 for the others). */
MEPUBLIC void MEAPI McdModelSetBoundsPadding(McdModelID model, MeReal margin);
MEPUBLIC MeReal MEAPI McdModelGetBoundsPadding(McdModelID model);

/* Bodies. McdModelSetBody is implemented by Mst (see the top of the file). */
MEPUBLIC void MEAPI McdModelSetBody(McdModelID model, MdtBodyID body);
MEPUBLIC MdtBodyID MEAPI McdModelGetBody(McdModelID model);
/* Stores the body handle only (no pointer changes): Mst's building block. */
MEPUBLIC void MEAPI McdModelStoreBody(McdModelID model, MdtBodyID body);
/* Pointers to the world-frame linear / angular velocity (3 MeReals each),
 * kept, not copied; NULL means at rest. */
MEPUBLIC void MEAPI McdModelSetLinearVelocityPtr(McdModelID model, MeReal *velocity);
MEPUBLIC void MEAPI McdModelSetAngularVelocityPtr(McdModelID model, MeReal *angularVelocity);
MEPUBLIC MeReal *MEAPI McdModelGetLinearVelocityPtr(McdModelID model);
MEPUBLIC MeReal *MEAPI McdModelGetAngularVelocityPtr(McdModelID model);

/* Slots for the one space holding the model (private to the farfield):
 * the space handle and an index it may use. NULL / -1 when in no space. */
MEPUBLIC void MEAPI McdModelSetSpaceData(McdModelID model, void *space, int index);
MEPUBLIC void *MEAPI McdModelGetSpace(McdModelID model);
MEPUBLIC int MEAPI McdModelGetSpaceIndex(McdModelID model);

ME_EXTERN_C_END
#endif /* KARMA_MCDMODEL_H */
