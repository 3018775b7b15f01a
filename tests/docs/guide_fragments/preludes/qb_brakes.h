/* qb_brakes.h: PASTE_11 is the `else` of the brake test in QuadBike's
 * UpdateVehicleControls(): the `if` it follows comes first. */
#include "qb_vehicle_controls.h"
#undef GUIDE_FRAGMENT_LEAD
#define GUIDE_FRAGMENT_LEAD   \
  Vehicle *veh = &quadBike;   \
  int i = 0;                  \
  if (veh->brakeInput == 0) { \
    /* Brakes off */          \
  }
