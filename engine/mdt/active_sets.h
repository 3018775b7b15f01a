// active_sets.h: what the step may touch, kept up to date as bodies and
// constraints change, so that a step costs what is awake and not what the
// world holds (issue 17). Not installed.
//
// Three structures, each with its invariant:
//
//   awake       the enabled bodies, each once, in no particular order;
//               body->awakeSlot is its index (-1 for a disabled body).
//               Kept by MdtBodyEnable, MdtBodyDisable and MdtBodyDestroy.
//               The step sorts a copy by (sort key, creation serial), a
//               total order, so the order it was filled in never shows.
//
//   driven      every disabled body whose force, torque or impulse
//               accumulators may be non-zero (body->drivenListed set), and
//               possibly other bodies. Filled by the MdtBodyAdd* calls on
//               a disabled body and by MdtBodyDisable; emptied by
//               wakeDrivenBodies (sleep.cpp), which wakes or clears each.
//               An entry whose body no longer has drivenListed set (it was
//               destroyed and its slot handed out again) is skipped.
//
//   body lists  each body heads an intrusive list of the constraints joined
//               to it (constraint->linked[k] == body, links linkNext[k] and
//               linkPrev[k]). Every enabled constraint that stands alone
//               (no owning group) is linked to exactly its bodies
//               (linked[k] == body[k]); a linked constraint may also be
//               disabled or owned, which the step filters out. Kept by
//               MdtConstraintEnable and MdtConstraintSetBodies (link),
//               MdtConstraintDestroy, the destruction of a contact group's
//               contacts and MdtBodyDestroy (unlink). So the constraints
//               a step simulates -- enabled, alone, with an enabled body --
//               are all reached from the awake bodies.
#pragma once

#include <vector>

#include "constraint.h"

namespace karma::mdt {

struct ActiveSets {
  std::vector<MdtBody *> awake;
  std::vector<MdtBody *> driven;
  std::uint64_t gatherStamp = 0;  // bumped by each gather; see constraintReached
};

void addAwake(MdtWorldPrivate *p, MdtBody *b);
void removeAwake(MdtWorldPrivate *p, MdtBody *b);
// A body whose accumulators may have become non-zero while it is disabled.
void noteDriven(MdtBody *b);
// Links c into the lists of its current bodies (first unlinking it from
// the lists it was in, if different).
void linkConstraint(MdtConstraint *c);
void unlinkConstraint(MdtConstraint *c);
// The constraint after c in body b's list (c->linked[0] or [1] is b).
inline MdtConstraint *nextAtBody(const MdtConstraint *c, const MdtBody *b) {
  return c->linked[0] == b ? c->linkNext[0] : c->linkNext[1];
}

}  // namespace karma::mdt
