/* qb_vehicle_init.h: QuadBike's InitialiseVehicle(Vehicle *veh, const
 * MeVector3 startPos) (vehicle.c) and its locals. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD                           \
  Vehicle *veh = &quadBike;                           \
  const MeReal *startPos = 0;                         \
  MeMatrix3 Ixyz = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; \
  MeMatrix4 comTM;                                    \
  MeVector3 pos;                                      \
  int i, j;
