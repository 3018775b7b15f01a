/* McdSpace.h: the collision farfield, an axis-sorted space of models.
 *
 * A space keeps the models inserted in it sorted along the chosen axes and
 * reports the pairs whose boxes overlap (touching counts) as McdModelPairs;
 * a model's box is its AABB grown by the framework's contact tolerance and
 * its bounds padding (McdModelSetBoundsPadding):
 *   hello    overlapping now, not at the previous McdSpaceEndChanges
 *   staying  overlapping now and before: the SAME McdModelPair as its hello
 *   goodbye  reported before, not now: the overlap ended, a model was
 *            removed, the pair was disabled or culled, or both models froze
 * Every hello is matched by exactly one goodbye; a goodbye pair is valid
 * until the next McdSpaceBeginChanges, after which the space reuses it.
 * A hello pair has model1 before model2 in the space's order: the lower
 * sort key (McdModelSetSortKey), or between equal keys the earlier
 * insertion; the goodbye, hello and staying ranges each list their pairs in
 * that order, by model1 then model2. userData and responseData are NULL at
 * hello.
 *
 * Change blocks (the guide's validity tables). Inside a block
 * (McdSpaceIsChanging true): Insert*, RemoveModel, UpdateModel(s),
 * UpdateAll, Enable/DisablePair, SetModelCullingParameters, EndChanges.
 * Outside: GetPairs, GetTransitions, PairIteratorBegin, SetAABBFn,
 * BeginChanges. Anywhere: Freeze/Unfreeze/ModelIsFrozen, IsChanging,
 * PairIsEnabled, GetModelCount, the model iterator, user data, Build.
 * A call in the wrong mode warns (naming the function) and does nothing.
 * A new space is inside a change block.
 *
 * Frozen models. A frozen model is neither updated by McdSpaceUpdateAll
 * nor paired with another frozen model. Frozen-pair policy: a pair that is
 * reported when both its models freeze is KEPT (it stays, with its
 * responseData), so a contact group between two sleeping bodies survives
 * and wakes them together; two frozen models never START a pair. Change it
 * with McdSpaceSetKeepFrozenPairs(space, 0) for the guide's plain "pairs of
 * frozen models are not reported" (they then say goodbye).
 *
 * Capacity: objectCount models; pairCount reported pairs to begin with.
 * Pair storage is taken as pairs appear (a large pairCount costs nothing
 * until its pairs exist); pairs keep their addresses. More overlapping
 * pairs than pairCount: the space grows its limit (by as much again, at
 * least 16), reports every pair, and McdSpaceEndChanges warns once per
 * space (an extension: Karma 1.2 made the extra pairs wait). */
#ifndef KARMA_MCDSPACE_H
#define KARMA_MCDSPACE_H
#include "MeCall.h"
#include "MePrecision.h"
#include "McdFrame.h"
#include "McdModel.h"
#include "McdModelPair.h"

ME_EXTERN_C_BEGIN

typedef struct McdSpace McdSpace;
typedef McdSpace *McdSpaceID;

/* Axes of McdSpaceAxisSortCreate (a non-empty combination). */
enum { McdXAxis = 1, McdYAxis = 2, McdZAxis = 4, McdAllAxes = 7 };

/* Position in the current pair events (from McdSpacePairIteratorBegin). */
typedef struct McdSpacePairIterator {
  unsigned long long generation;
  int nextGoodbye, nextHello, nextStaying;
} McdSpacePairIterator;

/* Position in the space's models (from McdSpaceModelIteratorBegin). */
typedef struct McdSpaceModelIterator {
  int cursor;
} McdSpaceModelIterator;

/* A symmetric table of "do not pair" flags (opaque). */
typedef struct McdCullingTable McdCullingTable;

/* Computes a model's world AABB for the space (after McdModelUpdate). */
typedef void(MEAPI *McdSpaceAABBFnPtr)(McdModelID model, MeVector3 minCorner, MeVector3 maxCorner);

/* A space of at most objectCount models and, to begin with, pairCount
 * reported pairs (both >= 1; see "Capacity" above), inside a change block.
 * NULL with a warning on bad input. */
MEPUBLIC McdSpaceID MEAPI McdSpaceAxisSortCreate(McdFrameworkID framework, int axes, int objectCount, int pairCount);
/* Destroys the space; its models leave it (not destroyed, no goodbyes). */
MEPUBLIC void MEAPI McdSpaceDestroy(McdSpaceID space);
MEPUBLIC McdFrameworkID MEAPI McdSpaceGetFramework(McdSpaceID space);

MEPUBLIC void MEAPI McdSpaceBeginChanges(McdSpaceID space);
MEPUBLIC void MEAPI McdSpaceEndChanges(McdSpaceID space);
MEPUBLIC int MEAPI McdSpaceIsChanging(McdSpaceID space);

/* Inserting does not update: the space uses the model's AABB of its last
 * McdModelUpdate (a model never updated is updated here if it has a
 * transform). Without an AABB function (McdSpaceSetAABBFn), a model that
 * has no AABB yet (no transform, or only non-finite ones) is refused with
 * a warning. A model can be in one space only. 1 on success. */
MEPUBLIC MeBool MEAPI McdSpaceInsertModel(McdSpaceID space, McdModelID model);
MEPUBLIC MeBool MEAPI McdSpaceInsertModelWithCulling(McdSpaceID space, McdModelID model, McdCullingTable *table,
                                                     int cullingIndex, int cullingID);
/* Its hello and staying pairs become goodbyes at the next EndChanges. */
MEPUBLIC MeBool MEAPI McdSpaceRemoveModel(McdModelID model);
/* McdModelUpdate, then the model's AABB in the space (not on a frozen model). */
MEPUBLIC void MEAPI McdSpaceUpdateModel(McdModelID model);
/* McdSpaceUpdateModel on every unfrozen model (McdSpaceUpdateAll is the same). */
MEPUBLIC void MEAPI McdSpaceUpdateModels(McdSpaceID space);
MEPUBLIC void MEAPI McdSpaceUpdateAll(McdSpaceID space);
/* Replaces the model's AABB (default: McdModelGetAABB); NULL restores it. */
MEPUBLIC void MEAPI McdSpaceSetAABBFn(McdSpaceID space, McdSpaceAABBFnPtr fn);

MEPUBLIC MeBool MEAPI McdSpaceFreezeModel(McdModelID model);
MEPUBLIC MeBool MEAPI McdSpaceUnfreezeModel(McdModelID model);
MEPUBLIC MeBool MEAPI McdSpaceModelIsFrozen(McdModelID model);
/* The frozen-pair policy (see the top of this file); default 1 (keep). */
MEPUBLIC void MEAPI McdSpaceSetKeepFrozenPairs(McdSpaceID space, MeBool keep);

/* The two models must be in the same space. */
MEPUBLIC MeBool MEAPI McdSpaceEnablePair(McdModelID model1, McdModelID model2);
MEPUBLIC MeBool MEAPI McdSpaceDisablePair(McdModelID model1, McdModelID model2);
/* Not disabled and not culled. */
MEPUBLIC MeBool MEAPI McdSpacePairIsEnabled(McdModelID model1, McdModelID model2);

MEPUBLIC McdCullingTable *MEAPI McdCullingTableCreate(int size);
MEPUBLIC McdCullingTable *MEAPI McdCullingTableSet(McdCullingTable *const table, MeU32 a, MeU32 b, MeBool flag);
MEPUBLIC void MEAPI McdCullingTableDestroy(McdCullingTable *table);
/* table NULL clears the model's culling parameters. */
MEPUBLIC void MEAPI McdSpaceSetModelCullingParameters(McdSpaceID space, McdModelID model, McdCullingTable *table,
                                                      int cullingIndex, int cullingID);

/* Brings the sorted axes up to date now (EndChanges does it anyway). */
MEPUBLIC void MEAPI McdSpaceBuild(McdSpaceID space);

/* The pair events of the last EndChanges, in chunks: reset the container,
 * call GetPairs; a non-zero return means "call again with the same
 * iterator" (overflow). Goodbyes come first. GetTransitions leaves out
 * the staying pairs. */
MEPUBLIC void MEAPI McdSpacePairIteratorBegin(McdSpaceID space, McdSpacePairIterator *iter);
MEPUBLIC int MEAPI McdSpaceGetPairs(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *pairs);
MEPUBLIC int MEAPI McdSpaceGetTransitions(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *pairs);

MEPUBLIC int MEAPI McdSpaceGetModelCount(McdSpaceID space);
MEPUBLIC void MEAPI McdSpaceModelIteratorBegin(McdSpaceID space, McdSpaceModelIterator *iter);
/* The next model in *model; 0 (model NULL) at the end. */
MEPUBLIC MeBool MEAPI McdSpaceGetModel(McdSpaceID space, McdSpaceModelIterator *iter, McdModelID *model);

MEPUBLIC void MEAPI McdSpaceSetUserData(McdSpaceID space, void *data);
MEPUBLIC void *MEAPI McdSpaceGetUserData(McdSpaceID space);

/* Older names the guide still uses in its prose (each the same function as
 * the one named beside it, with the same arguments and result):
 *   McdSpaceUpdate          McdSpaceUpdateAll
 *   McdSpaceUpdateAllModels McdSpaceUpdateModels
 *   McdSpaceIsFrozen        McdSpaceModelIsFrozen
 *   McdUnfreezeInSpace      McdSpaceUnfreezeModel
 *   McdDisablePair          McdSpaceDisablePair */
MEPUBLIC void MEAPI McdSpaceUpdate(McdSpaceID space);
MEPUBLIC void MEAPI McdSpaceUpdateAllModels(McdSpaceID space);
MEPUBLIC MeBool MEAPI McdSpaceIsFrozen(McdModelID model);
MEPUBLIC MeBool MEAPI McdUnfreezeInSpace(McdModelID model);
MEPUBLIC MeBool MEAPI McdDisablePair(McdModelID model1, McdModelID model2);

ME_EXTERN_C_END
#endif /* KARMA_MCDSPACE_H */
