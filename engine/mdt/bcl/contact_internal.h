// contact_internal.h: the layout of contacts and contact groups, shared by
// contact.cpp and contact_group.cpp. Not installed.
#pragma once

#include "MdtContact.h"
#include "bcl_type.h"

struct MdtContact : MdtConstraint {
  MdtContactParams params;
  MeVector3 normal;     // world frame, unit, from body 1 into body 0
  MeVector3 direction;  // world frame, primary friction direction if set
  MeBool directionSet;
  MeReal penetration;
  MdtContact *next;     // the next contact of the pair / group
  MeReal normalForce;   // last step
};

struct MdtContactGroup : MdtConstraint {
  MdtContact *first;
  int count;
  MeReal normalForce;
};

namespace karma::mdt {

extern const ConstraintType kContactType;
extern const ConstraintType kContactGroupType;

// Rows of one contact (normal, then friction per its type) appended to
// `sink`; friction rows refer to the normal row by its index in the sink.
void addContactRows(MdtContact *c, RowSink &sink, const StepContext &ctx);
// The friction directions in use: primary d1 and secondary d2 = n x d1.
void contactDirections(const MdtContact *c, MeVector3 d1, MeVector3 d2);
// Contact defaults (params, normal, penetration, no direction).
void resetContact(MdtContact *c);

}  // namespace karma::mdt
