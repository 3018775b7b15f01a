/* McdInteraction.h: nearfield tests and the interaction table.
 *
 * Direct use (the guide's "Testing Collision Directly"):
 *
 *   McdModelPair *pair = McdModelPairCreate(m1, m2);
 *   McdHello(pair);                       // picks and caches the interaction
 *   if (McdNearby(pair)) {                // the cached AABBs overlap
 *       McdIntersectResult r;
 *       r.contacts = buffer; r.contactMaxCount = 20;
 *       if (McdIntersect(pair, &r)) ...   // r.contactCount contacts
 *   }
 *   McdGoodbye(pair);
 *   McdModelPairDestroy(pair);
 *
 * The models must have been updated (McdModelUpdate, or by their space)
 * since they last moved.
 *
 * Writing an interaction. An interaction for the ordered pair of geometry
 * types (A, B) is a McdInteractions record; only intersectFn is required:
 *   helloFn      called by McdHello; may allocate pair->m_cachedData
 *   intersectFn  fills result->contacts (at most result->contactMaxCount),
 *                contactCount, touch and normal, with model1 of type A and
 *                model2 of type B, and returns touch. Conventions of
 *                McdContact.h: normal from model2 towards model1, separation
 *                negative in penetration.
 *   goodbyeFn    called by McdGoodbye; frees what helloFn allocated
 *   safetimeFn   time of impact (McdSafeTime); may be NULL
 * Register it with McdFrameworkSetInteraction(fw, A, B, &record). Unless
 * (B, A) has its own registration, the table then also answers (B, A): the
 * dispatcher swaps model1 and model2 in the pair for the call and then
 * negates every normal and swaps element1/element2 and the dims bytes, so
 * callers always see their own order. One file per family of interactions
 * lives in engine/mcd/nearfield/ (see ARCHITECTURE.md). */
#ifndef KARMA_MCDINTERACTION_H
#define KARMA_MCDINTERACTION_H
#include "MeCall.h"
#include "MePrecision.h"
#include "McdFrame.h"
#include "McdContact.h"
#include "McdModelPair.h"

ME_EXTERN_C_BEGIN

struct McdSafeTimeResult;

typedef void(MEAPI *McdHelloFnPtr)(McdModelPair *pair);
typedef int(MEAPI *McdIntersectFnPtr)(McdModelPair *pair, McdIntersectResult *result);
typedef void(MEAPI *McdGoodbyeFnPtr)(McdModelPair *pair);
typedef MeBool(MEAPI *McdSafeTimeFnPtr)(McdModelPair *pair, MeReal maxTime, struct McdSafeTimeResult *result);

typedef struct McdInteractions {
  McdHelloFnPtr helloFn;
  McdIntersectFnPtr intersectFn;
  McdGoodbyeFnPtr goodbyeFn;
  McdSafeTimeFnPtr safetimeFn;
  /* Set by the table: 1 in the mirrored entry of a one-way registration
     * (the functions expect the models the other way round). */
  int swap;
  /* Set by the table: 1 for the engine's own interactions, whose contacts
   * McdIntersect may reuse (McdFrameworkSetContactReuseDistance); 0 for an
   * application's. */
  int m_builtIn;
} McdInteractions;

/* Registers `fns` (copied) for (type1, type2) and, unless registered on its
 * own, the mirrored (type2, type1). Both types must be registered and
 * fns->intersectFn set, else a warning and nothing happens. Registering
 * again replaces. fns NULL removes the entry (and its automatic mirror).
 * A pair already greeted (McdHello) keeps the interaction it was greeted
 * with until its McdGoodbye: its tests and its goodbye run the functions
 * its hello ran, on the data that hello made. The change reaches the pairs
 * greeted after it. */
MEPUBLIC void MEAPI McdFrameworkSetInteraction(McdFrameworkID framework, int type1, int type2,
                                               const McdInteractions *fns);
/* The entry for (type1, type2), or NULL when none is registered. The
 * pointer is valid until the entry is registered again or removed. */
MEPUBLIC const McdInteractions *MEAPI McdFrameworkGetInteraction(McdFrameworkID framework, int type1, int type2);

/* Built-in interactions, one family per call. Each registers (A, B) for the
 * types named; nothing happens (no warning) when a type is not registered. */
MEPUBLIC void MEAPI McdSphereSphereRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSpherePlaneRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdBoxPlaneRegisterInteraction(McdFrameworkID framework);
/* Analytic primitive pairs: sphere-box, sphere-cylinder, sphere-sphyl and
 * sphyl-sphyl (one contact; two for parallel overlapping sphyls), box-box
 * (separating axes, then a clipped face manifold of up to 8 points, or one
 * edge-edge point), sphyl-box (up to 2 when lying flat on a face),
 * cylinder-plane (rim points: 8 standing, 2 lying) and sphyl-plane (1-2). */
MEPUBLIC void MEAPI McdSphereBoxRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphereCylinderRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphereSphylRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdBoxBoxRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphylSphylRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphylBoxRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdCylinderPlaneRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphylPlaneRegisterInteraction(McdFrameworkID framework);
/* General convex pairs (libccd GJK/EPA plus a clipped contact manifold):
 * convex mesh against sphere, box, cylinder, sphyl, convex mesh; convex mesh
 * against plane (vertices below it); box-cylinder, cylinder-cylinder,
 * cylinder-sphyl. Aggregates against every type, child by child (element1
 * of each contact is the child McdGeometryInstance). Sphere, box,
 * cylinder, sphyl and convex mesh against a triangle list, honouring the
 * McdTriangleFlags (element2 is the McdUserTriangle). */
MEPUBLIC void MEAPI McdConvexMeshSphereRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshBoxRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshCylinderRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshSphylRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshConvexMeshRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshPlaneRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdBoxCylinderRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdCylinderCylinderRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdCylinderSphylRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdAggregateRegisterInteractions(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphereTriangleListRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdBoxTriangleListRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdCylinderTriangleListRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphylTriangleListRegisterInteraction(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshTriangleListRegisterInteraction(McdFrameworkID framework);

/* Prepares a pair for queries: caches the interaction for the models'
 * geometry types (none: the pair is still valid and tests report nothing)
 * and calls its helloFn. A second hello without goodbye is ignored. */
MEPUBLIC void MEAPI McdHello(McdModelPair *pair);
/* Releases what hello cached. Ignored on a pair not helloed. */
MEPUBLIC void MEAPI McdGoodbye(McdModelPair *pair);
/* TRUE when the two models' cached AABBs overlap (touching counts). */
MEPUBLIC MeBool MEAPI McdNearby(McdModelPair *pair);
/* The nearfield test of a helloed pair. Fills `result` (see McdContact.h)
 * and returns result->touch: 1 when the models touch, 0 when they do not or
 * when no interaction is registered for their types. The guide also shows a
 * third `time` argument; it was unused and C has no overloads, so this is
 * the two-argument form its examples call. */
MEPUBLIC int MEAPI McdIntersect(McdModelPair *pair, McdIntersectResult *result);
/* McdHello / McdGoodbye on every hello / goodbye pair of a container. */
MEPUBLIC void MEAPI McdHelloEach(McdModelPairContainer *pairs);
MEPUBLIC void MEAPI McdGoodbyeEach(McdModelPairContainer *pairs);

ME_EXTERN_C_END
#endif /* KARMA_MCDINTERACTION_H */
