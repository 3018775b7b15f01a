/* qb_vehicle_controls.h: the loop over the wheels in QuadBike's
 * UpdateVehicleControls(Vehicle *veh) (vehicle.c) and its locals. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD                                                           \
  Vehicle *veh = &quadBike;                                                           \
  const MeReal width = (MeReal)0.5, pgap = (MeReal)0.4, maxSpeed = 5, maxForce = 500; \
  MeVector3 haxis;                                                                    \
  MeReal torque, theta, desired_vel;                                                  \
  int i = 0;
