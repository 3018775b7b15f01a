/* MdtConstraint.h: what every constraint (joint, limit constraint, contact,
 * contact group) has in common.
 *
 * A constraint joins two bodies, or one body and the world (body1 NULL). It
 * keeps one attachment frame per body -- a point and two orthogonal axes,
 * stored in that body's frame (in the world frame for the world) -- set from
 * world coordinates by the Set{Position,Axis,Axes} functions at the moment
 * they are called. So bodies must be placed before their joints are set up.
 *
 * Life cycle: Mdt*Create (disabled, defaults of its type, no bodies),
 * Mdt*SetBodies, set the geometry, Mdt*Enable. Bodies may only be changed
 * while the constraint is disabled. A constraint whose bodies are all
 * disabled (or destroyed) is not simulated; an enabled body joined to a
 * disabled one by an enabled constraint wakes it up at the next step.
 *
 * Forces: after each step, Mdt*GetForce / GetTorque give the force and
 * torque (world frame, about each body's dynamics origin) that the
 * constraint applied to each body over that step.
 *
 * Order: constraints are handed to the solver in increasing sort key, ties
 * broken by creation order. Giving every body and constraint a distinct sort
 * key makes a simulation independent of the order of creation.
 *
 * Bad input (NULL, non-finite numbers, zero or non-orthogonal axes, a body of
 * another world, changing bodies while enabled) is rejected in every build
 * with a warning naming the function; the call has no effect. */
#ifndef KARMA_MDTCONSTRAINT_H
#define KARMA_MDTCONSTRAINT_H
#include "MeCall.h"
#include "MePrecision.h"
#include "MdtWorld.h"

ME_EXTERN_C_BEGIN

typedef struct MdtConstraint *MdtConstraintID;

/* Every kind of constraint. */
typedef enum MdtConstraintType {
  MdtConstraintTypeBSJoint,
  MdtConstraintTypeHinge,
  MdtConstraintTypePrismatic,
  MdtConstraintTypeUniversal,
  MdtConstraintTypeAngular3,
  MdtConstraintTypeCarWheel,
  MdtConstraintTypeLinear1,
  MdtConstraintTypeLinear2,
  MdtConstraintTypeFixedPath,
  MdtConstraintTypeRPROJoint,
  MdtConstraintTypeSkeletal,
  MdtConstraintTypeSpring6,
  MdtConstraintTypeSpring,
  MdtConstraintTypeConeLimit,
  MdtConstraintTypeContact,
  MdtConstraintTypeContactGroup,
  MdtConstraintTypeCount
} MdtConstraintType;

MEPUBLIC MdtConstraintType MEAPI MdtConstraintGetType(const MdtConstraintID c);
/* "BSJoint", "Hinge", ... */
MEPUBLIC const char *MEAPI MdtConstraintTypeName(const MdtConstraintType t);

/* Destroys the constraint (disabling it first). NULL is ignored. The
 * handle of a destroyed constraint is refused with a warning by the
 * MdtConstraint* and typed calls until its slot serves a new constraint,
 * which is not before every other slot of the world is in use or 64 more
 * constraints (a group's contacts included) have been destroyed. */
MEPUBLIC void MEAPI MdtConstraintDestroy(const MdtConstraintID c);
MEPUBLIC void MEAPI MdtConstraintEnable(const MdtConstraintID c);
MEPUBLIC void MEAPI MdtConstraintDisable(const MdtConstraintID c);
MEPUBLIC MeBool MEAPI MdtConstraintIsEnabled(const MdtConstraintID c);

/* body0 must not be NULL; body1 NULL means the world. The constraint must be
 * disabled, and not a contact of a contact group (the group's bodies are
 * its contacts'). The attachment frames are reset to the bodies' origins
 * and the type's default axes, and the force and torque of the last step
 * to zero. */
MEPUBLIC void MEAPI MdtConstraintSetBodies(const MdtConstraintID c, const MdtBodyID body0, const MdtBodyID body1);
MEPUBLIC MdtBodyID MEAPI MdtConstraintGetBody(const MdtConstraintID c, const unsigned int bodyindex);

/* The attachment point, in world coordinates, for both bodies at once / for
 * one body. GetPosition reports body 0's point. */
MEPUBLIC void MEAPI MdtConstraintSetPosition(const MdtConstraintID c, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtConstraintGetPosition(const MdtConstraintID c, MeVector3 position);
MEPUBLIC void MEAPI MdtConstraintBodySetPosition(const MdtConstraintID c, const unsigned int bodyindex, const MeReal x,
                                                 const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtConstraintBodyGetPosition(const MdtConstraintID c, const unsigned int bodyindex,
                                                 MeVector3 position);

/* The primary axis (the secondary is made orthogonal to it), or both axes
 * (normalised; they must be orthogonal), in world coordinates, for both
 * bodies. Get* report body 0's axes in world coordinates. */
MEPUBLIC void MEAPI MdtConstraintSetAxis(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz);
MEPUBLIC void MEAPI MdtConstraintSetAxes(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz,
                                         const MeReal ox, const MeReal oy, const MeReal oz);
MEPUBLIC void MEAPI MdtConstraintGetAxis(const MdtConstraintID c, MeVector3 axis);
MEPUBLIC void MEAPI MdtConstraintGetAxes(const MdtConstraintID c, MeVector3 primary, MeVector3 ortho);
MEPUBLIC void MEAPI MdtConstraintBodySetAxes(const MdtConstraintID c, const unsigned int bodyindex, const MeReal px,
                                             const MeReal py, const MeReal pz, const MeReal ox, const MeReal oy,
                                             const MeReal oz);
MEPUBLIC void MEAPI MdtConstraintBodyGetAxes(const MdtConstraintID c, const unsigned int bodyindex, MeVector3 primary,
                                             MeVector3 ortho);
/* The guide's older, deprecated names of the three functions above (the
 * same functions): MdtConstraintSetBothAxis (sic) is MdtConstraintSetAxes,
 * MdtConstraintGetBothAxes is MdtConstraintGetAxes, MdtConstraintBodyGetBothAxes
 * is MdtConstraintBodyGetAxes. */
MEPUBLIC void MEAPI MdtConstraintSetBothAxis(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz,
                                             const MeReal ox, const MeReal oy, const MeReal oz);
MEPUBLIC void MEAPI MdtConstraintGetBothAxes(const MdtConstraintID c, MeVector3 primary, MeVector3 ortho);
MEPUBLIC void MEAPI MdtConstraintBodyGetBothAxes(const MdtConstraintID c, const unsigned int bodyindex,
                                                 MeVector3 primary, MeVector3 ortho);

/* Force and torque this constraint applied to body `bodyindex` over the last
 * step, world frame (zero before its first step). */
MEPUBLIC void MEAPI MdtConstraintGetForce(const MdtConstraintID c, const unsigned int bodyindex, MeVector3 force);
MEPUBLIC void MEAPI MdtConstraintGetTorque(const MdtConstraintID c, const unsigned int bodyindex, MeVector3 torque);

MEPUBLIC MdtWorldID MEAPI MdtConstraintGetWorld(const MdtConstraintID c);
MEPUBLIC void MEAPI MdtConstraintSetUserData(const MdtConstraintID c, void *data);
MEPUBLIC void *MEAPI MdtConstraintGetUserData(const MdtConstraintID c);
MEPUBLIC void MEAPI MdtConstraintSetSortKey(const MdtConstraintID c, const MeI32 key);
MEPUBLIC MeI32 MEAPI MdtConstraintGetSortKey(const MdtConstraintID c);

/* Constraints in the world: all of them / the capacity. */
MEPUBLIC unsigned int MEAPI MdtWorldGetConstraintCount(const MdtWorldID world);
MEPUBLIC unsigned int MEAPI MdtWorldGetMaxConstraints(const MdtWorldID world);

ME_EXTERN_C_END

/* MDT_CONSTRAINT_COMMON_API(Prefix, IDType): the functions every constraint
 * type Mdt<Prefix> has, as thin typed wrappers over MdtConstraint*:
 * Destroy, Enable, Disable, IsEnabled, SetBodies, GetBody, GetForce,
 * GetTorque, GetWorld, Set/GetUserData, Set/GetSortKey. Each type's header
 * also declares Mdt<Prefix>Create, Reset, QuaConstraint and
 * MdtConstraintDCast<Prefix> as real functions. */
#define MDT_CONSTRAINT_COMMON_API(P, ID)                                                                             \
  static inline void Mdt##P##Destroy(const ID j) { MdtConstraintDestroy(Mdt##P##QuaConstraint(j)); }                 \
  static inline void Mdt##P##Enable(const ID j) { MdtConstraintEnable(Mdt##P##QuaConstraint(j)); }                   \
  static inline void Mdt##P##Disable(const ID j) { MdtConstraintDisable(Mdt##P##QuaConstraint(j)); }                 \
  static inline MeBool Mdt##P##IsEnabled(const ID j) { return MdtConstraintIsEnabled(Mdt##P##QuaConstraint(j)); }    \
  static inline void Mdt##P##SetBodies(const ID j, const MdtBodyID b0, const MdtBodyID b1) {                         \
    MdtConstraintSetBodies(Mdt##P##QuaConstraint(j), b0, b1);                                                        \
  }                                                                                                                  \
  static inline MdtBodyID Mdt##P##GetBody(const ID j, const unsigned int i) {                                        \
    return MdtConstraintGetBody(Mdt##P##QuaConstraint(j), i);                                                        \
  }                                                                                                                  \
  static inline void Mdt##P##GetForce(const ID j, const unsigned int i, MeVector3 f) {                               \
    MdtConstraintGetForce(Mdt##P##QuaConstraint(j), i, f);                                                           \
  }                                                                                                                  \
  static inline void Mdt##P##GetTorque(const ID j, const unsigned int i, MeVector3 t) {                              \
    MdtConstraintGetTorque(Mdt##P##QuaConstraint(j), i, t);                                                          \
  }                                                                                                                  \
  static inline MdtWorldID Mdt##P##GetWorld(const ID j) { return MdtConstraintGetWorld(Mdt##P##QuaConstraint(j)); }  \
  static inline void Mdt##P##SetUserData(const ID j, void *d) {                                                      \
    MdtConstraintSetUserData(Mdt##P##QuaConstraint(j), d);                                                           \
  }                                                                                                                  \
  static inline void *Mdt##P##GetUserData(const ID j) { return MdtConstraintGetUserData(Mdt##P##QuaConstraint(j)); } \
  static inline void Mdt##P##SetSortKey(const ID j, const MeI32 k) {                                                 \
    MdtConstraintSetSortKey(Mdt##P##QuaConstraint(j), k);                                                            \
  }                                                                                                                  \
  static inline MeI32 Mdt##P##GetSortKey(const ID j) { return MdtConstraintGetSortKey(Mdt##P##QuaConstraint(j)); }

/* MDT_CONSTRAINT_POSITION_API(Prefix, IDType): Set/GetPosition for the types
 * with one joint position (all but Prismatic, Angular3, Spring, FixedPath,
 * RPRO). */
#define MDT_CONSTRAINT_POSITION_API(P, ID)                                                             \
  static inline void Mdt##P##SetPosition(const ID j, const MeReal x, const MeReal y, const MeReal z) { \
    MdtConstraintSetPosition(Mdt##P##QuaConstraint(j), x, y, z);                                       \
  }                                                                                                    \
  static inline void Mdt##P##GetPosition(const ID j, MeVector3 p) {                                    \
    MdtConstraintGetPosition(Mdt##P##QuaConstraint(j), p);                                             \
  }

/* MDT_CONSTRAINT_TYPE_DECL(Prefix, IDType): the opaque ID and the four real
 * functions of each type. */
#define MDT_CONSTRAINT_TYPE_DECL(P, ID)                             \
  typedef struct Mdt##P *ID;                                        \
  MEPUBLIC ID MEAPI Mdt##P##Create(const MdtWorldID world);         \
  MEPUBLIC void MEAPI Mdt##P##Reset(const ID j);                    \
  MEPUBLIC MdtConstraintID MEAPI Mdt##P##QuaConstraint(const ID j); \
  MEPUBLIC ID MEAPI MdtConstraintDCast##P(const MdtConstraintID c);

#endif /* KARMA_MDTCONSTRAINT_H */
