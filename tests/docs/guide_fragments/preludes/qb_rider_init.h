/* qb_rider_init.h: QuadBike's InitialiseRider(Rider *rider, const
 * MeVector3 startPos) (rider.c) and its locals; PASTE_18 runs inside
 * PASTE_17's loop, where i and hinge are set. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD   \
  Rider *rider = 0;           \
  const MeReal *startPos = 0; \
  MeVector3 pos;              \
  MeMatrix3 R;                \
  int i = 0, j;               \
  MdtBodyID body1, body2;     \
  MdtHingeID hinge = 0;       \
  MdtBSJointID bsj;           \
  MdtLimitID limit;
