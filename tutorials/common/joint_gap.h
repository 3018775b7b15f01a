/* joint_gap.h: how far a joint has come apart, the figure the tutorials'
 * behaviour tests bound (QuadBike's rider, Ballman's rag doll,
 * RainbowChain).
 *
 * A joint's anchor is fixed in each of its two bodies; the gap is the
 * distance between the anchor as carried by body 0 and by body 1 (zero for
 * a joint that holds exactly). Header only, so a tutorial's simulation
 * library needs nothing more than this folder on its include path. */
#ifndef KARMA_TUTORIAL_JOINT_GAP_H
#define KARMA_TUTORIAL_JOINT_GAP_H

#include "Mdt.h"

static inline MeReal TutorialJointGap(MdtConstraintID c) {
  MeVector3 p0, p1;
  MdtConstraintBodyGetPosition(c, 0, p0);
  MdtConstraintBodyGetPosition(c, 1, p1);
  return MeVector3Distance(p0, p1);
}

#endif
