/* McdFrame.h: the collision framework.
 *
 * A framework (McdFrameworkID) owns everything of one collision setup: the
 * table of registered geometry types, the table of interactions (nearfield
 * tests) between pairs of types, the pool of models and the pool of child
 * geometry instances used by aggregates. Several frameworks may coexist;
 * they share nothing.
 *
 *   McdFrameworkID fw = McdInit(0, 50, 0, 1);   // no user types, 50 models
 *   McdPrimitivesRegisterTypes(fw);              // every built-in geometry
 *   McdPrimitivesRegisterInteractions(fw);       // every nearfield test built
 *   ...
 *   McdTerm(fw);                                 // frees everything
 *
 * Geometry types. The built-in types have fixed ids (McdGeometryType below);
 * a geometry of a type that was not registered in its framework cannot be
 * created (the Create function warns and returns NULL). Registering only the
 * types a program uses keeps unused code and tables out of the way.
 *
 * Interactions. Each interaction is written "one way round" for an ordered
 * pair of types (say sphere-plane) and registered once; the framework then
 * answers the reversed order (plane-sphere) by swapping the models and
 * negating the contact normals. A pair of types with no registered
 * interaction is ignored: McdIntersect reports no contact. See
 * McdInteraction.h for the function types and McdFrameworkSetInteraction.
 */
#ifndef KARMA_MCDFRAME_H
#define KARMA_MCDFRAME_H
#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct McdFramework McdFramework;
typedef McdFramework *McdFrameworkID;

/* Ids of the built-in geometry types. User types (McdInit's geoTypeMaxCount)
 * take the ids kMcdGeometryBuiltInTypes, kMcdGeometryBuiltInTypes + 1, ... */
typedef enum McdGeometryType {
  kMcdGeometryTypeNull = -1,
  kMcdGeometryTypeSphere = 0,
  kMcdGeometryTypeBox = 1,
  kMcdGeometryTypeCylinder = 2,
  kMcdGeometryTypePlane = 3,
  kMcdGeometryTypeSphyl = 4,
  kMcdGeometryTypeTriangleList = 5,
  kMcdGeometryTypeConvexMesh = 6,
  kMcdGeometryTypeAggregate = 7,
  kMcdGeometryBuiltInTypes = 8
} McdGeometryType;

/* Creates a framework.
 *   geoTypeMaxCount  room for user-defined geometry types beyond the
 *                    built-in ones (0 is fine)
 *   modelCount       the most models alive at once (the model pool)
 *   instanceCount    the most child geometry instances alive at once: an
 *                    aggregate of n elements used by k models takes k*n
 *                    (nested aggregates count every level); may be 0
 *   lengthScale      the size of a medium object; tolerances scale with it
 * Returns NULL with a warning on negative counts or a non-positive or
 * non-finite length scale. No geometry type is registered yet. */
MEPUBLIC McdFrameworkID MEAPI McdInit(int geoTypeMaxCount, int modelCount, int instanceCount, MeReal lengthScale);

/* Destroys the framework and everything it still owns (models, geometries,
 * tables). Handles into it become invalid. NULL is ignored. While a space
 * made on it still exists (McdSpaceDestroy first), it warns and frees
 * nothing. */
MEPUBLIC void MEAPI McdTerm(McdFrameworkID framework);

/* Destroys every model, then every geometry of the framework, regardless of
 * reference counts. The framework and its registrations stay. While any
 * model is in a space it warns and destroys nothing. */
MEPUBLIC void MEAPI McdFrameworkDestroyAllModelsAndGeometries(McdFrameworkID framework);

/* The framework's length scale, model capacity and models alive. */
MEPUBLIC MeReal MEAPI McdFrameworkGetLengthScale(McdFrameworkID framework);
MEPUBLIC int MEAPI McdFrameworkGetModelCount(McdFrameworkID framework);
MEPUBLIC int MEAPI McdFrameworkGetModelMaxCount(McdFrameworkID framework);
/* Shapes closer than the contact tolerance touch: the nearfield reports
 * contacts with a separation up to +tolerance, so resting contacts do not
 * flicker with rounding. Default 1e-5 * lengthScale; >= 0. */
MEPUBLIC void MEAPI McdFrameworkSetContactTolerance(McdFrameworkID framework, MeReal tolerance);
MEPUBLIC MeReal MEAPI McdFrameworkGetContactTolerance(McdFrameworkID framework);
/* Contact reuse (an extension of this engine): McdIntersect tests a pair at
 * the contact tolerance plus `distance`; when every contact found is within
 * the tolerance it remembers them (else it tests again at the tolerance).
 * Later calls are served from that memory, the contacts moved with the two
 * models to first order, while their relative pose has moved no surface
 * point by more than `distance` since the test (and the tolerance asked for
 * leaves room for that motion); a served contact may then be up to
 * `distance` beyond the tolerance (speculative). Pairs of two boxes,
 * cylinders, sphyls or convex meshes tested by the engine's own
 * interactions only; every other pair, and a call with room for no
 * contact, is always tested. Default 1e-4 * lengthScale; 0 tests every
 * call at the tolerance alone; >= 0. */
MEPUBLIC void MEAPI McdFrameworkSetContactReuseDistance(McdFrameworkID framework, MeReal distance);
MEPUBLIC MeReal MEAPI McdFrameworkGetContactReuseDistance(McdFrameworkID framework);
/* Geometries alive in the framework (every type). */
MEPUBLIC int MEAPI McdFrameworkGetGeometryCount(McdFrameworkID framework);

/* Registers every built-in geometry type: Sphere, Box, Cylinder, Plane,
 * Sphyl, TriangleList, ConvexMesh and Aggregate. (The guide calls the last
 * two non-primitive, but its universe programs create them after
 * MstUniverseCreate, which calls only this function, so it registers all.) */
MEPUBLIC void MEAPI McdPrimitivesRegisterTypes(McdFrameworkID framework);
/* Registers every interaction built so far between the registered types
 * (pairs whose types are not registered are skipped quietly). */
MEPUBLIC void MEAPI McdPrimitivesRegisterInteractions(McdFrameworkID framework);
/* The number of built-in geometry types (kMcdGeometryBuiltInTypes). */
MEPUBLIC int MEAPI McdPrimitivesGetTypeCount(void);

/* Registers just sphere, box and plane / the interactions among them. */
MEPUBLIC void MEAPI McdSphereBoxPlaneRegisterTypes(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphereBoxPlaneRegisterInteractions(McdFrameworkID framework);

/* Register one built-in type. Registering twice is harmless. */
MEPUBLIC void MEAPI McdSphereRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdBoxRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdCylinderRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdPlaneRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdSphylRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdTriangleListRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdConvexMeshRegisterType(McdFrameworkID framework);
MEPUBLIC void MEAPI McdAggregateRegisterType(McdFrameworkID framework);

/* TRUE if the type id is registered in the framework. */
MEPUBLIC MeBool MEAPI McdFrameworkIsTypeRegistered(McdFrameworkID framework, int typeId);
/* The registered type's name ("Sphere", ...), or NULL. */
MEPUBLIC const char *MEAPI McdFrameworkGetTypeName(McdFrameworkID framework, int typeId);

ME_EXTERN_C_END
#endif /* KARMA_MCDFRAME_H */
