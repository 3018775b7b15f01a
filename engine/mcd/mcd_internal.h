// mcd_internal.h: the private layouts of the collision framework (not
// installed). Geometries are C structs that start with McdGeometry; the
// framework, models and geometry instances are defined here.
//
// Invariants
//  - A geometry is on its framework's list from creation to destruction and
//    its m_refCount counts the models (one each) and aggregates (one per
//    element slot holding it) that use it.
//  - A model's instance tree mirrors its geometry: an aggregate instance has
//    exactly one child per element, built at McdModelCreate (aggregates are
//    closed once referenced, so the tree cannot go stale).
//  - Child instances come from framework->instances and go back there when
//    the model is destroyed; the pointer array `children` comes from
//    MeMemoryAPI.
//  - Interaction table: entry (a, b) is table[a * typeMax + b], a slot or
//    NULL; a slot's fns always has an intersectFn; explicit[a * typeMax + b]
//    is 1 when registered for that order itself (a mirror never overwrites
//    it).
//  - Interaction slots (interaction_table.cpp): a slot's fns never change
//    once the table holds it, except for m_builtIn in the registration that
//    made it. A pair between McdHello and McdGoodbye points at the fns of
//    the slot it was greeted with (McdModelPair::m_interaction) and counts
//    in its `pairs`; a registration that replaces or clears the entry
//    retires the slot, which lives on (on the framework's retired list)
//    until its last pair's goodbye, so that pair's queries and goodbye run
//    the functions its hello ran, on the data its hello made.
#pragma once

#include "Mcd.h"

#include <cstddef>

struct McdFramework;

namespace karma::mcd {

// One registration's functions, shared by the pairs greeted with them (see
// the invariants above). fns is the first member: a pair's m_interaction
// points at it and InteractionSlotOf goes back.
struct InteractionSlot {
  McdInteractions fns;
  int pairs;                    // pairs greeted with it and not yet said goodbye
  bool retired;                 // no longer in the table
  InteractionSlot *nextRetired; // the framework's retired list
  McdFramework *framework;      // the table's owner
};

// What the framework knows about a geometry type. Mass properties are for
// density 1 (mass == volume); each type file defines one record.
struct GeometryType {
  const char *name;
  // Frees memory the geometry owns besides its own block (may be NULL).
  void (*release)(McdGeometry *g);
  // World AABB of the geometry placed at tm.
  void (*aabb)(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx);
  // Volume, centre of mass and inertia about it (density 1); false when the
  // shape has no finite volume.
  bool (*mass)(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 inertia);
};

extern const GeometryType kSphereType, kBoxType, kCylinderType, kPlaneType, kSphylType, kTriangleListType,
    kConvexMeshType, kAggregateType;

// The geometry's type record, or NULL when its framework lacks it.
const GeometryType *TypeOf(const McdGeometry *g);

// Allocates a zeroed geometry block of `bytes` of the given registered type,
// links it into the framework. Warns (naming fn) and returns NULL on a NULL
// framework or an unregistered type.
McdGeometry *NewGeometry(McdFramework *fw, int type, std::size_t bytes, const char *fn);
// Unlinks and frees a geometry regardless of its reference count.
void FreeGeometry(McdGeometry *g);

// Drops an aggregate's references to its elements (count becomes 0).
void AggregateDropElements(McdGeometry *g);

// Returns g when it is a geometry of `type`, else warns (naming fn) and
// returns NULL.
McdGeometry *CheckType(McdGeometry *g, int type, const char *fn);
template <class T>
inline T *As(McdGeometry *g, int type, const char *fn) {
  return reinterpret_cast<T *>(CheckType(g, type, fn));
}

// True when x is finite and > 0 (>= 0 when zeroOk).
bool PositiveFinite(MeReal x, bool zeroOk = false);
bool IsFiniteTM(MECONSTMATRIX MeMatrix4 tm);

// Geometry instances (instance.cpp).
bool BuildInstance(McdFramework *fw, McdGeometryInstance *inst, McdGeometry *g, McdModel *model,
                   McdGeometryInstance *parent);
void ReleaseInstance(McdFramework *fw, McdGeometryInstance *inst);
// Places the instance at world transform tm (stored in inst->tm for
// children) and caches its AABB, recursively.
void PlaceInstance(McdGeometryInstance *inst, MECONSTMATRIX MeMatrix4 tm);

// The touch tolerance of the framework (see McdFrameworkGetContactTolerance).
MeReal ContactTolerance(const McdFramework *fw);
// Records that a geometry of the framework changed its size: every pair's
// remembered contacts (contact_reuse.h) are stale.
void ShapeChanged(McdGeometry *g);

// The key a model's pairs are ordered by: its own sort key once
// McdModelSetSortKey was called, else its inherited key (0 by default).
MeI32 EffectiveSortKey(const McdModel *m);
// Hands the model's effective key to its space, if it is in one
// (space_models.cpp).
void RefreshSpaceSortKey(McdModel *m);

// The contact cap of one McdIntersect: the result's contactMaxCount, lowered
// to the pair's request's (McdModelPairSetRequestPtr) when that is set and
// positive.
int EffectiveContactCap(const McdModelPair *pair, int resultCap);

// McdIntersect (checked arguments, a helloed pair) without contact reuse:
// a full test at the framework's tolerance, memory neither read nor
// written. For queries at poses of their own (McdSafeTime).
int IntersectWithoutReuse(McdModelPair *pair, McdIntersectResult *result);

// The interaction slots' lifetime (interaction_table.cpp). A pair greeted
// with the slot of `fns` (McdHello) holds it; its goodbye lets it go, and a
// retired slot goes with its last pair. FreeInteractionSlots frees every
// slot, in the table and retired (McdTerm).
void HoldInteraction(const McdInteractions *fns);
void ReleaseInteraction(const McdInteractions *fns);
void FreeInteractionSlots(McdFramework *fw);

}  // namespace karma::mcd

// Aggregate layout (shared by aggregate.cpp, instance.cpp and mass code).
struct McdAggregateData {
  McdGeometry m_g;
  int maxCount;
  int count;
  McdGeometry **elements;  // maxCount slots
  MeMatrix4Ptr *relTMs;    // maxCount slots, user pointers
};

struct McdGeometryInstance {
  McdGeometry *geometry;
  MeMatrix4Ptr tm;  // world TM: the model's pointer, a user pointer or &ownTM
  MeMatrix4 ownTM;  // storage for a child without a user pointer
  McdGeometryInstance *parent;
  McdGeometryInstance **children;
  int childCount;
  McdModel *model;
  MeVector3 aabbMin, aabbMax;
  int material;
};

struct McdModel {
  McdGeometryInstance instance;  // top instance; instance.tm is the model TM
  McdFramework *framework;
  MeMatrix4Ptr relTM;   // optional relative transform...
  MeMatrix4Ptr linkTM;  // ...composed with this into instance.tm
  McdModelUpdateCallback callback;
  void *userData;
  MdtBodyID body;
  MeReal *linearVelocity;
  MeReal *angularVelocity;
  void *space;
  int spaceIndex;
  int sortKey;             // McdModelSetSortKey's key
  int sortKeySet;          // 1 once McdModelSetSortKey was called
  MeI32 inheritedSortKey;  // McdModelSetInheritedSortKey's key (Mst: the body's)
  MeReal boundsPadding;    // McdModelSetBoundsPadding's margin, >= 0
  int updated;             // 1 once McdModelUpdate cached an AABB
};

struct McdFramework {
  MeReal lengthScale;
  MeReal contactTolerance;
  MeReal contactReuseDistance;  // McdFrameworkSetContactReuseDistance (contact_reuse.h)
  unsigned shapeRevision;       // counts size changes of any geometry (contact_reuse.h)
  int typeMax;                             // built-in + user slots
  const karma::mcd::GeometryType **types;  // typeMax, NULL = unregistered
  karma::mcd::InteractionSlot **table;     // typeMax * typeMax, NULL = no interaction
  karma::mcd::InteractionSlot *retired;    // slots replaced while pairs used them
  unsigned char *explicitEntry;            // typeMax * typeMax
  MePool models;
  MePool instances;
  McdGeometry *geometries;  // list head
  int geometryCount;
  int spaceCount;  // spaces made on the framework and not yet destroyed
};
