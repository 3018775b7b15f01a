/* McdGeometry.h: geometries (shapes) and geometry instances.
 *
 * A geometry describes a shape in its own frame and nothing else: a sphere
 * of radius 1, a 2x1x3 box. Many models may share one geometry. A geometry
 * instance places a geometry in the world: it points at the geometry and at
 * a transform (MeMatrix4, rows = axes, row 3 = position), and for an
 * aggregate it owns one child instance per element.
 *
 * Reference counting. Every model using a geometry and every aggregate
 * holding it as an element counts one reference. McdGeometryDestroy on a
 * geometry still referenced warns and leaves the geometry alone (destroy the
 * models and aggregates first).
 *
 * Mass properties. Every solid geometry reports, for a uniform density, its
 * mass, its centre of mass and its inertia tensor about the centre of mass,
 * both in the geometry's frame (McdGeometryGetMassProperties). The
 * primitives are centred on their origin; a convex mesh or an aggregate may
 * not be. The plane and the triangle list have no finite volume.
 *
 * The struct McdGeometry is public only so that geometry structs can embed
 * it first (the guide writes `((McdTriangleList*)g)->triangleMaxCount`); its
 * members are private: use the functions. */
#ifndef KARMA_MCDGEOMETRY_H
#define KARMA_MCDGEOMETRY_H
#include "MeCall.h"
#include "MePrecision.h"
#include "MeMath.h"
#include "McdFrame.h"

ME_EXTERN_C_BEGIN

typedef struct McdGeometry {
  int m_type;                 /* McdGeometryType or a user type id */
  int m_refCount;             /* models + aggregates using it */
  McdFramework *m_framework;  /* owner */
  struct McdGeometry *m_prev; /* the framework's list of geometries */
  struct McdGeometry *m_next;
  void *m_userData;
} McdGeometry;
typedef McdGeometry *McdGeometryID;

typedef struct McdGeometryInstance McdGeometryInstance;
typedef McdGeometryInstance *McdGeometryInstanceID;

/* Destroys a geometry no model or aggregate uses any more. On a geometry
 * still referenced: a warning naming the count, and nothing happens.
 * NULL is ignored. */
MEPUBLIC void MEAPI McdGeometryDestroy(McdGeometryID geometry);

/* The geometry's type id (McdGeometryType or a user type), or
 * kMcdGeometryTypeNull for NULL. */
MEPUBLIC int MEAPI McdGeometryGetTypeId(McdGeometryID geometry);
MEPUBLIC int MEAPI McdGeometryGetType(McdGeometryID geometry); /* same */
/* The type's name ("Box", ...). */
MEPUBLIC const char *MEAPI McdGeometryGetTypeName(McdGeometryID geometry);
/* Number of references (models and aggregates) to the geometry. */
MEPUBLIC int MEAPI McdGeometryGetReferenceCount(McdGeometryID geometry);
MEPUBLIC McdFrameworkID MEAPI McdGeometryGetFramework(McdGeometryID geometry);
MEPUBLIC void MEAPI McdGeometrySetUserData(McdGeometryID geometry, void *data);
MEPUBLIC void *MEAPI McdGeometryGetUserData(McdGeometryID geometry);

/* Mass properties of the geometry filled with the given density (> 0):
 *   mass          density * volume
 *   centreOfMass  in the geometry's frame (zero for the primitives)
 *   inertia       the inertia tensor about the centre of mass, axes of the
 *                 geometry's frame, in mass * length^2
 * Returns TRUE on success. For a geometry without finite volume (plane,
 * triangle list), a non-positive or non-finite density or NULL arguments it
 * warns, zeroes the outputs it was given and returns FALSE. Any output
 * pointer may be NULL except that at least the geometry must be valid. */
MEPUBLIC MeBool MEAPI McdGeometryGetMassProperties(McdGeometryID geometry, MeReal density, MeReal *mass,
                                                   MeMatrix3 inertia, MeVector3 centreOfMass);
/* The geometry's volume (0 for plane and triangle list). */
MEPUBLIC MeReal MEAPI McdGeometryGetVolume(McdGeometryID geometry);

/* The axis-aligned box bounding the geometry placed at transform `tm`.
 * Unbounded directions (a plane) give -MEINFINITY / +MEINFINITY. */
MEPUBLIC void MEAPI McdGeometryGetAABB(McdGeometryID geometry, MECONSTMATRIX MeMatrix4 tm, MeVector3 minCorner,
                                       MeVector3 maxCorner);

/* Geometry instances. A model owns one (McdModelGetGeometryInstance); an
 * aggregate's instance has one child per element, in the order the elements
 * were added, allocated from the framework's instance pool.
 *
 * The transform pointer of a child is optional: when set (to persistent
 * memory), each McdModelUpdate writes the child's world transform there
 * (the element's relTM composed with the parent's world TM). */
MEPUBLIC McdGeometryID MEAPI McdGeometryInstanceGetGeometry(McdGeometryInstanceID instance);
MEPUBLIC int MEAPI McdGeometryInstanceGetChildCount(McdGeometryInstanceID instance);
/* Child i (0 <= i < child count), or NULL with a warning. */
MEPUBLIC McdGeometryInstanceID MEAPI McdGeometryInstanceGetChild(McdGeometryInstanceID instance, int i);
MEPUBLIC void MEAPI McdGeometryInstanceSetTransformPtr(McdGeometryInstanceID instance, MeMatrix4Ptr tm);
/* The transform the instance was last placed at: for a model's top instance
 * the model's TM pointer; for a child the pointer set above, else an
 * internal copy refreshed by McdModelUpdate (never NULL after an update). */
MEPUBLIC MeMatrix4Ptr MEAPI McdGeometryInstanceGetTransformPtr(McdGeometryInstanceID instance);
/* The world AABB cached at the last McdModelUpdate. */
MEPUBLIC void MEAPI McdGeometryInstanceGetAABB(McdGeometryInstanceID instance, MeVector3 minCorner,
                                               MeVector3 maxCorner);
/* Materials are per instance (so each element of an aggregate may differ);
 * McdModelSetMaterial sets the top instance's. Default 0. */
MEPUBLIC void MEAPI McdGeometryInstanceSetMaterial(McdGeometryInstanceID instance, int material);
MEPUBLIC int MEAPI McdGeometryInstanceGetMaterial(McdGeometryInstanceID instance);

ME_EXTERN_C_END
#endif /* KARMA_MCDGEOMETRY_H */
