// constraint.h: the constraint base and the ROW PROTOCOL every constraint
// type in bcl/ implements. Not installed.
//
// =============================================================================
// THE ROW PROTOCOL
// =============================================================================
// Once per step, every enabled constraint of a partition writes its rows.
// A row is one scalar velocity constraint on the two bodies:
//
//     J0lin . v0 + J0ang . w0 + J1lin . v1 + J1ang . w1   =  speed   (+ slack)
//
// with v, w the velocities AFTER the step, world frame; body 1 may be the
// world (its half of J is then ignored). The solver finds one impulse per
// row, lambda = h * f, applied as J^T lambda, such that
//
//     J v' = speed - softness * lambda               (a soft row gives way)
//     lo*h <= lambda <= hi*h, complementary as in kea_lcp.h,
//
// i.e. softness is added to the diagonal of J M^-1 J^T (units 1/mass).
//
//   speed     target constraint velocity: a motor's desired velocity, or the
//             error-correction term gamma * error / h that removes a fraction
//             gamma of the position error `error` per step (error is measured
//             so that J v > 0 reduces it), or a restitution speed.
//   softness  Rigid rows use the world's epsilon (Karma's (A + eps I) x = b).
//             A spring of stiffness k and damping c over a step h is the row
//                 softness = 1 / (h (h k + c)),  speed = k * error / (h k + c),
//             whose force settles at k * error; slip s (velocity = s * force)
//             is softness s / h.
//   lo, hi    bounds on the FORCE (+-MEINFINITY for none): contacts [0, inf),
//             motors [-Fmax, Fmax].
//   friction  for a friction row, the index within the same constraint's
//             rows of its normal row; its bounds become +-mu * normal force.
//   role      what the row is for, so matrix capping knows what may go.
//
// A constraint writes its rows in a fixed order and the same number every
// step as long as nothing about it changes, so last step's impulses can warm
// start the solver row by row. Contacts instead carry their own impulses
// (normal, and friction as a tangent vector) from step to step, because a
// contact group's rows come and go with its contacts (Row::warm).
// =============================================================================
#pragma once

#include <cstdint>

#include "MdtConstraint.h"
#include "MdtLimit.h"
#include "mdt_internal.h"

namespace karma::mdt {

enum class RowRole : std::uint8_t {
  Joint,            // bilateral joint row: never capped
  Limit,            // limit or motor row: never capped
  ContactNormal,    // non-penetration row of a contact
  ContactFriction,  // friction row of a contact
};

struct Row {
  MeReal J[4][3];   // lin0, ang0, lin1, ang1
  MeReal speed;     // target J v'
  MeReal softness;  // added to the diagonal (velocity per unit impulse)
  MeReal lo, hi;    // force bounds
  MeReal mu;        // friction rows: coefficient times normal force = bound
  int friction;     // friction rows: index of the normal row within the constraint, else -1
  RowRole role;
  MeReal depth;            // contact rows: penetration, for capping (shallowest go first)
  MdtConstraint *contact;  // contact rows: the contact they belong to
  // Warm start: the impulse the solver starts this row from. A type that
  // keeps its own memory (contacts: per contact, in the contact's frame)
  // sets `warm` and `warmSet`; for the others the step uses the
  // constraint's row-by-row memory (MdtConstraint::warm).
  MeReal warm;
  bool warmSet;
  // Contact normal rows: a speed J v must reach after the positions have
  // moved (a bounce found apart, within the step); 0 for none.
  MeReal bounceAfter;
};

// The step's view of the world, handed to every constraint.
struct StepContext {
  MeReal h;  // step size
  MeReal invH;
  MeReal epsilon;  // world softness for rigid rows
  MeReal gamma;    // world error reduction
};

// Collects the rows of one constraint.
class RowSink {
 public:
  RowSink(Row *rows, int capacity) : rows_(rows), capacity_(capacity) {}
  // A new row, zeroed, rigid (world softness), unbounded, role Joint.
  Row &add(const StepContext &ctx);
  int count() const { return count_; }
  Row *rows() { return rows_; }
  bool overflowed() const { return overflow_; }

 private:
  Row *rows_;
  int capacity_;
  int count_ = 0;
  bool overflow_ = false;
  Row spare_{};
};

// What a constraint type provides. Every function receives the constraint
// as its base; the type casts to its own struct.
struct ConstraintType {
  MdtConstraintType id;
  const char *name;
  unsigned size;  // sizeof the type's struct
  int maxRows;    // most rows it ever writes in one step
  // Optional: the most rows this particular constraint can write (contact
  // groups grow with their contacts); maxRows when NULL.
  int (*rowCapacity)(const MdtConstraint *c);
  // Sets the type's defaults (called by Create and Reset, after the base
  // has been reset).
  void (*reset)(MdtConstraint *c);
  // Writes this step's rows. May update state that depends on the current
  // configuration (limit positions). Bodies are those of the constraint.
  void (*addRows)(MdtConstraint *c, RowSink &rows, const StepContext &ctx);
  // Optional: after the solve, with this constraint's n rows as written and
  // their impulses (same order). The base has already stored force and
  // torque.
  void (*afterSolve)(MdtConstraint *c, const Row *rows, const MeReal *impulse, int n, const StepContext &ctx);
  // Optional: called when the constraint is destroyed (contact groups free
  // their contacts).
  void (*destroy)(MdtConstraint *c);
  // Optional: called after MdtConstraintSetBodies (and Mdt*Reset) has put
  // the default attachment (attachDefault), so a type can replace it with
  // its own (Spring: each body's own origin; RPRO: the centres of mass).
  void (*attach)(MdtConstraint *c);
  // Optional: asks for the memory addRows and afterSolve will read beyond
  // the constraint's own struct (a contact group: its contacts), called a
  // constraint ahead of its turn. Changes no result. (Defaults to none, so
  // the types without one need not name it.)
  void (*prefetch)(const MdtConstraint *c) = nullptr;
  // (Not yet a member: one that enumerates the bodies beyond body[0..1]
  // that rows touch; no type needs it, every row touches body[0] and
  // body[1] only.)
};

constexpr int kMaxWarmRows = 16;  // warm-start memory per constraint

}  // namespace karma::mdt

// The base of every constraint. Each type's struct derives from it.
// Ordered by when a step touches the fields, the slot starting on a cache
// line (kConstraintSlotAlignment): in single precision the first 64 bytes
// hold what every type's rows and the bridge read (the type, the bodies,
// the attachment points), the next 64 what the gather and the partitions
// read (the flags, the sort key, the body lists), the next 112 what every
// step writes after the solve (force, torque, warm memory); the rest is
// read when a user asks, a joint's rows need it, or a constraint joins or
// leaves a body's list (linkPrev).
struct MdtConstraint {
  const karma::mdt::ConstraintType *type;
  MdtWorldID world;
  MdtBodyID body[2];  // body[1] NULL: the world
  // Attachment point per body, in that body's frame (world frame for the world).
  MeVector3 localPos[2];
  // Contacts owned by a contact group are stepped through the group.
  MdtConstraint *owner;
  MeBool enabled;
  MeI32 sortKey;
  std::uint64_t serial;
  // Scratch of the step (partitioning).
  int mark;
  int warmRows;  // rows of `warm` that hold last step's impulses
  // The body lists (active_sets.h): the bodies whose lists hold this
  // constraint and its neighbours there; gatherStamp marks it as reached
  // by the current gather.
  MdtBody *linked[2];
  MdtConstraint *linkNext[2];
  std::uint64_t gatherStamp;
  MeVector3 force[2];  // last step, world frame
  MeVector3 torque[2];
  // Warm start: last step's impulses, valid for `warmRows` rows.
  MeReal warm[karma::mdt::kMaxWarmRows];
  MdtConstraint *linkPrev[2];
  // Attachment axes per body, in that body's frame (world frame for the world).
  MeVector3 localAxis[2];   // primary
  MeVector3 localOrtho[2];  // secondary, orthogonal to the primary
  void *userData;
};

namespace karma::mdt {

// Registry of all types (bcl/registry.cpp).
const ConstraintType *const *allConstraintTypes();
unsigned largestConstraintSize();

// Slots (constraint_slots.cpp). Every constraint lives in a slot of its
// world's constraint pools; the pools grow when full (reported once per
// world), and a slot keeps its address until it is released. A released
// slot has the type kDestroyedConstraintType until it is taken again, and
// the last kHeldConstraintSlots released are taken again only when no other
// slot is free, oldest first, so a stale handle is refused (liveConstraint,
// checkType) rather than reaching the next constraint made.
//   takeConstraintSlot: a free slot, or nullptr (with a warning) only when
//     memory runs out;
//   releaseConstraintSlot: gives a slot back (one not in the pools is ignored);
//   nextConstraintSlot: the used slot after `slot` (nullptr: the first), in a
//     fixed order, nullptr at the end, passing over released slots;
//   usedConstraintSlots: how many are in use;
//   releaseConstraintPools: frees every pool (the world's end).
void *takeConstraintSlot(MdtWorldPrivate *p);
void releaseConstraintSlot(MdtWorldPrivate *p, void *slot);
void *nextConstraintSlot(MdtWorldPrivate *p, void *slot);
int usedConstraintSlots(const MdtWorldPrivate *p);
void releaseConstraintPools(MdtWorldPrivate *p);

// The type of a released slot: no constraint type has it.
extern const ConstraintType kDestroyedConstraintType;
// True for a constraint between its Create and its Destroy; for NULL or a
// released slot (a stale handle) it warns, naming `fn`, and is false.
bool liveConstraint(const MdtConstraint *c, const char *fn);

// Allocation: a new constraint of `type` in `world`, base and type reset;
// NULL with a warning when the world's constraint pool is full.
MdtConstraint *createConstraint(MdtWorldID world, const ConstraintType &type);
// Base defaults: no bodies, origin, primary axis x, secondary y.
void resetBase(MdtConstraint *c);
// Forgets the force and torque the constraint applied in its last step
// (MdtConstraintGetForce / GetTorque, the geometric stiffness): they were on
// the bodies it had.
void clearForces(MdtConstraint *c);
// Attachment at body 0's origin with the world's x and y axes (SetBodies).
void attachDefault(MdtConstraint *c);
// Reset to defaults keeping the bodies (Mdt*Reset).
void resetKeepingBodies(MdtConstraint *c);
// The type check of MdtConstraintDCast*: c if it is of `type`, else NULL.
MdtConstraint *castTo(MdtConstraint *c, const ConstraintType &type);
// The type check of the typed API: false (with a warning naming `fn`) when
// c is NULL, a released slot or not of `type`.
bool checkType(const MdtConstraint *c, const ConstraintType &type, const char *fn);

// ---- attachment frames in world coordinates ---------------------------------
void attachmentPoint(const MdtConstraint *c, int i, MeVector3 out);  // world point
void attachmentAxis(const MdtConstraint *c, int i, MeVector3 out);   // world primary
void attachmentOrtho(const MdtConstraint *c, int i, MeVector3 out);  // world secondary
// World vector -> body i's frame (identity for the world).
void toBodyFrame(const MdtConstraint *c, int i, const MeVector3 world, MeVector3 local);
void pointToBodyFrame(const MdtConstraint *c, int i, const MeVector3 world, MeVector3 local);
// Gives c the bodies b0 and b1 (either may be NULL: the world), each
// attachment point and axis re-expressed from its old body's frame in its
// new body's, so that it keeps its place in the world; a body that stays
// keeps its stored attachment exactly.
void moveToBodies(MdtConstraint *c, MdtBody *b0, MdtBody *b1);
// The world point p as the attachment point in both bodies' frames; a
// non-finite p is ignored with a warning naming fn.
void setWorldPosition(MdtConstraint *c, const MeVector3 p, const char *fn);
// Sets both bodies' attachment axes from world axes (normalised, orthogonal).
void setWorldAxes(MdtConstraint *c, const MeVector3 primary, const MeVector3 ortho);
// Any unit vector orthogonal to a unit vector n.
void anyOrthogonal(const MeVector3 n, MeVector3 out);

// World velocity of body i at world point p (zero for the world).
void pointVelocity(const MdtConstraint *c, int i, const MeVector3 p, MeVector3 out);
// Position of body i's origin (zero for the world), for lever arms.
void bodyOrigin(const MdtConstraint *c, int i, MeVector3 out);
// A joint whose two attachment points coincide when it holds (ball and
// socket, hinge, universal, skeletal).
bool isPointJoint(const MdtConstraint *c);

}  // namespace karma::mdt
