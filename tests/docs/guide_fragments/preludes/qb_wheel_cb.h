/* qb_wheel_cb.h: QuadBike's WheelGroundCB(McdIntersectResult *result,
 * McdContact *colC, MdtContactID dynC) (vehicle.c) and its locals. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD       \
  McdIntersectResult *result = 0; \
  McdContact *colC = 0;           \
  MdtContactID dynC = 0;          \
  MdtBodyID body;                 \
  MdtCarWheelID wj;               \
  MeVector3 haxis, normal, dir;   \
  MdtContactParamsID params;      \
  MeReal slip;
