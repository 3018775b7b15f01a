// contact_internal.h: the layout of contacts and contact groups, shared by
// contact.cpp and contact_group.cpp. Not installed.
#pragma once

#include "MdtContact.h"
#include "bcl_type.h"

// The params start a cache line of their own (as the slot does:
// kConstraintSlotAlignment), and the fields every step reads or writes
// (the bridge, the rows, the impulses' memory) come next, in one line in
// single precision; `direction`, read only when the user set one, comes
// last.
struct MdtContact : MdtConstraint {
  alignas(karma::mdt::kConstraintSlotAlignment) MdtContactParams params;
  MeVector3 normal;  // world frame, unit, from body 1 into body 0
  // The primary friction direction of last step's rows (world frame, unit;
  // zero before the first rows): without a direction set by the user, the next
  // step keeps it, projected onto the new tangent plane, while it stays
  // clear of the normal (contactDirections). So the friction rows turn with
  // the normal instead of jumping by a quarter turn where anyOrthogonal's
  // choice of axis switches (near-vertical normals, |n_x| close to |n_z|).
  MeVector3 frictionAxis;
  MeBool directionSet;
  MeReal penetration;
  MdtContact *next;    // the next contact of the pair / group
  MeReal normalForce;  // last step
  // Identity of the collision features that made it (McdContact::feature),
  // for the bridge's matching; 0 for contacts made by hand.
  MeU32 feature;
  // Memory for the next step's warm start: last step's normal impulse, and
  // its friction impulse as a world vector in the tangent plane (so it
  // survives a change of the friction directions: the new rows start from
  // its projections onto them).
  MeReal warmNormal;
  MeVector3 warmFriction;
  MeVector3 direction;  // world frame, primary friction direction if set
};

namespace karma::mdt {
inline constexpr int kContactHints = 8;
}

// The group's own fields start a cache line (as a contact's params do), so
// that the list's head and the hints are one or two lines the bridge
// prefetches together (MdtContactGroupPrefetch).
struct MdtContactGroup : MdtConstraint {
  alignas(karma::mdt::kConstraintSlotAlignment) MdtContact *first;
  int count;
  MeReal normalForce;
  // The first min(count, kContactHints) contacts in list order, kept by
  // Append and Remove (refreshContactHints), so that the memory of all of
  // them can be asked for at once (MdtContactGroupPrefetchContacts,
  // ConstraintType::prefetch) instead of one link at a time as a walk of the
  // list would. Only ever prefetched, never read for a result.
  MdtContact *hint[karma::mdt::kContactHints];
};
static_assert(alignof(MdtContact) <= karma::mdt::kConstraintSlotAlignment &&
                  alignof(MdtContactGroup) <= karma::mdt::kConstraintSlotAlignment,
              "a slot keeps a contact's and a group's alignment");

namespace karma::mdt {

extern const ConstraintType kContactType;
extern const ConstraintType kContactGroupType;

// Rows of one contact (normal, then friction per its type) appended to
// `sink`; friction rows refer to the normal row by its index in the sink.
void addContactRows(MdtContact *c, RowSink &sink, const StepContext &ctx);
// The same with the contact's body origins (bodyOrigin) given: a group
// finds them once for all its contacts.
void addContactRows(MdtContact *c, RowSink &sink, const StepContext &ctx, const MeVector3 origin[2]);
// The friction directions in use: primary d1 and secondary d2 = n x d1.
// d1 is the first of these whose part in the tangent plane is long enough,
// normalised: the user's direction (MdtContactSetDirection), then the axis
// last step's rows used (frictionAxis), then anyOrthogonal(n).
void contactDirections(const MdtContact *c, MeVector3 d1, MeVector3 d2);
// Sets g->hint to the first contacts of g's list.
void refreshContactHints(MdtContactGroup *g);
// Contact defaults (params, normal, penetration, no direction, no memory).
void resetContact(MdtContact *c);
// Stores the impulses of one contact's rows (normal first, then friction in
// the order addContactRows wrote them; `rows` as written, for the friction
// directions) as its warm-start memory; returns the number of rows read.
int storeContactImpulses(MdtContact *c, const Row *rows, const MeReal *impulse, int n);
// Whether addContactRows writes the friction row of `direction` (0: primary,
// 1: secondary): the contact type has that direction and its force bound is
// not identically zero (Box: friction > 0; NormalForce: coefficient > 0).
bool frictionActs(const MdtContactParams &p, int direction);
// The number of rows addContactRows writes for c: the normal row and one per
// friction direction that acts.
int contactRowCount(const MdtContact *c);

}  // namespace karma::mdt
