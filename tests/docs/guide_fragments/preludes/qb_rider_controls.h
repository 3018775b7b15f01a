/* qb_rider_controls.h: QuadBike's UpdateRiderControls(Rider *rider)
 * (rider.c) and its locals; maxAng is the tutorial's constant. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD          \
  Rider *rider = 0;                  \
  const MeReal maxAng = (MeReal)0.3; \
  MeVector3 vel;                     \
  MeVector3Ptr xAxis;                \
  MeReal speed, angle;               \
  MdtLimitID limit;
