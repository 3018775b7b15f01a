/* carterrain.c: see carterrain.h. */
#include "carterrain.h"

#include <stdio.h>
#include <string.h>

#define TERRAIN_TRIANGLES 64 /* most triangles one query may return */

static CarTerrain *active_; /* the one car the callbacks serve */

/* The triangle list's generator: the terrain's triangles under the sphere
 * (pos, radius) around the model that touches the terrain's box. */
static int MEAPI TerrainTriangles(McdModelPair *pair, McdUserTriangle *triangles, MeVector3 pos, MeReal radius,
                                  int maxTriangles) {
  (void)pair;
  return HeightFieldTrianglesNear(&active_->terrain, pos, radius, triangles, maxTriangles);
}

static int WheelOf(const CarTerrain *car, MdtBodyID body) {
  int i;
  for (i = 0; i < CAR_WHEELS; ++i)
    if (car->wheelBody[i] == body) return i;
  return -1;
}

/* Per wheel-ground contact: the primary friction direction is the rolling
 * direction, normal x hinge axis, so that the contact's primary and
 * secondary friction act along and across the tyre. */
static MeBool MEAPI WheelContactCB(McdIntersectResult *result, McdContact *colC, MdtContactID c) {
  CarTerrain *car = active_;
  MeVector3 n, hinge, dir, used;
  MeReal length, dn, dh;
  int i = WheelOf(car, MdtContactGetBody(c, 0));
  (void)result, (void)colC;
  if (i < 0) i = WheelOf(car, MdtContactGetBody(c, 1));
  if (i < 0) return 1;
  MdtContactGetNormal(c, n);
  MdtCarWheelGetHingeAxis(car->joint[i], hinge);
  MeVector3Cross(dir, n, hinge);
  length = MeVector3Magnitude(dir);
  if (length < (MeReal)1e-3) return 1; /* hinge along the normal: leave it automatic */
  MdtContactSetDirection(c, dir[0] / length, dir[1] / length, dir[2] / length);
  MdtContactGetDirection(c, used);
  dn = MeFabs(MeVector3Dot(used, n)), dh = MeFabs(MeVector3Dot(used, hinge));
  if (dn > car->worstDirectionDot) car->worstDirectionDot = dn;
  if (dh > car->worstDirectionDot) car->worstDirectionDot = dh;
  ++car->wheelContacts;
  return 1;
}

static void DisablePair(McdSpaceID space, McdModelID a, McdModelID b) {
  const int open = !McdSpaceIsChanging(space);
  if (open) McdSpaceBeginChanges(space);
  McdSpaceDisablePair(a, b);
  if (open) McdSpaceEndChanges(space);
}

int CarTerrainCreate(CarTerrain *car, const char *terrainName) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  MstBridgeID bridge;
  McdFrameworkID frame;
  McdGeometryID chassisGeom, wheelGeom;
  MdtContactParamsID p;
  MeVector3 lo, hi;
  MeReal y0, chassisY;
  const MeReal wheelVolume = (MeReal)(4.0 / 3.0 * ME_PI) * CAR_WHEEL_RADIUS * CAR_WHEEL_RADIUS * CAR_WHEEL_RADIUS;
  const MeReal chassisVolume = CAR_CHASSIS_LENGTH * CAR_CHASSIS_HEIGHT * CAR_CHASSIS_WIDTH;
  int i;

  memset(car, 0, sizeof *car);
  if (active_) {
    fprintf(stderr, "carterrain: only one car at a time\n");
    return 0;
  }
  if (!HeightFieldFromBMP(&car->terrain, terrainName, CAR_TERRAIN_SCALE)) return 0;
  car->universe = MstUniverseCreate(&sizes);
  if (!car->universe) {
    HeightFieldDestroy(&car->terrain);
    return 0;
  }
  active_ = car;
  frame = car->universe->frame;
  bridge = car->universe->bridge;
  MdtWorldSetGravity(car->universe->world, 0, (MeReal)-9.81, 0);
  /* The car is the only thing that moves: keep it awake, so it answers the
   * throttle at once however long it has stood still. */
  MdtWorldSetAutoDisable(car->universe->world, 0);
  /* Harder constraints than the default epsilon 0.01: a loaded wheel
   * carries about 2 kN, and at 0.01 it would rest 3 cm into the ground
   * (the guide: lower epsilon for heavy objects). */
  MdtWorldSetEpsilon(car->universe->world, CAR_EPSILON);

  /* Materials: grippy tyres on the ground, a chassis that slides. */
  car->groundMaterial = MstBridgeGetNewMaterial(bridge);
  car->wheelMaterial = MstBridgeGetNewMaterial(bridge);
  car->chassisMaterial = MstBridgeGetNewMaterial(bridge);
  p = MstBridgeGetContactParams(bridge, car->wheelMaterial, car->groundMaterial);
  MdtContactParamsSetType(p, MdtContactTypeFriction2D);
  /* Box friction: a fixed limit on the friction force, here a coefficient
   * times the static load on one wheel (a linear problem for the solver,
   * cheaper and steadier than the normal-force model). */
  MdtContactParamsSetPrimaryFriction(p, CAR_GRIP_ALONG * CAR_WHEEL_LOAD);    /* traction, braking */
  MdtContactParamsSetSecondaryFriction(p, CAR_GRIP_ACROSS * CAR_WHEEL_LOAD); /* cornering */
  MdtContactParamsSetRestitution(p, 0);
  MstBridgeSetPerContactCB(bridge, car->wheelMaterial, car->groundMaterial, WheelContactCB);
  p = MstBridgeGetContactParams(bridge, car->chassisMaterial, car->groundMaterial);
  MdtContactParamsSetType(p, MdtContactTypeFriction2D);
  MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
  MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
  MdtContactParamsSetFrictionCoefficient(p, (MeReal)0.5);

  /* The terrain: a triangle list over the field's bounding box. */
  HeightFieldGetBounds(&car->terrain, lo, hi);
  lo[1] -= 1, hi[1] += 1;
  MeMatrix4TMMakeIdentity(car->groundTM);
  car->ground = MstFixedModelCreate(
      car->universe, McdTriangleListCreate(frame, lo, hi, TERRAIN_TRIANGLES, TerrainTriangles), car->groundTM);
  McdModelSetMaterial(car->ground, car->groundMaterial);

  /* The chassis, its wheels just touching the ground, unloaded springs. */
  y0 = HeightFieldHeightAt(&car->terrain, 0, 0);
  chassisY = y0 + CAR_WHEEL_RADIUS + CAR_WHEEL_DROP + (MeReal)0.01;
  chassisGeom = McdBoxCreate(frame, CAR_CHASSIS_LENGTH, CAR_CHASSIS_HEIGHT, CAR_CHASSIS_WIDTH);
  car->chassis = MstModelAndBodyCreate(car->universe, chassisGeom, CAR_CHASSIS_MASS / chassisVolume);
  car->chassisBody = McdModelGetBody(car->chassis);
  McdModelSetMaterial(car->chassis, car->chassisMaterial);
  MdtBodySetPosition(car->chassisBody, 0, chassisY, 0);

  wheelGeom = McdSphereCreate(frame, CAR_WHEEL_RADIUS);
  for (i = 0; i < CAR_WHEELS; ++i) {
    const MeReal x = i < CAR_REAR_LEFT ? CAR_WHEEL_X : -CAR_WHEEL_X;
    const MeReal z = i % 2 ? CAR_WHEEL_Z : -CAR_WHEEL_Z;
    const MeReal y = chassisY - CAR_WHEEL_DROP;
    int j;
    car->wheel[i] = MstModelAndBodyCreate(car->universe, wheelGeom, CAR_WHEEL_MASS / wheelVolume);
    car->wheelBody[i] = McdModelGetBody(car->wheel[i]);
    McdModelSetMaterial(car->wheel[i], car->wheelMaterial);
    MdtBodySetPosition(car->wheelBody[i], x, y, z);
    DisablePair(car->universe->space, car->chassis, car->wheel[i]);
    for (j = 0; j < i; ++j) DisablePair(car->universe->space, car->wheel[i], car->wheel[j]);

    /* Chassis is body 0, the wheel body 1. The steering (and suspension)
     * axis is the chassis's y, the hinge axis the wheel's z. */
    car->joint[i] = MdtCarWheelCreate(car->universe->world);
    MdtCarWheelSetBodies(car->joint[i], car->chassisBody, car->wheelBody[i]);
    MdtCarWheelSetPosition(car->joint[i], x, y, z);
    MdtCarWheelSetSteeringAndHingeAxes(car->joint[i], 0, 1, 0, 0, 0, 1);
    /* Springs relax at the wheel's starting height; hard stops 0.2 m
     * either way. The static load sags each by (M g / 4) / Kp = 49 mm. */
    MdtCarWheelSetSuspension(car->joint[i], CAR_SPRING, CAR_DAMPER, 0, -CAR_TRAVEL, CAR_TRAVEL, 0);
    if (i >= CAR_REAR_LEFT) MdtCarWheelSetSteeringLock(car->joint[i], 1);
    MdtCarWheelEnable(car->joint[i]);
  }
  return 1;
}

void CarTerrainDestroy(CarTerrain *car) {
  if (car->universe) MstUniverseDestroy(car->universe);
  HeightFieldDestroy(&car->terrain);
  if (active_ == car) active_ = NULL;
  car->universe = NULL;
}

void CarTerrainScript(CarTerrain *car) {
  const MeReal t = (MeReal)car->steps * CAR_STEP;
  car->throttle = t < 1 || t >= 18 ? 0 : (MeReal)0.5;
  car->steering = t >= 3 && t < 18 ? (MeReal)0.35 : 0;
  car->brake = t >= 18;
}

static void ApplyControls(CarTerrain *car) {
  int i;
  for (i = 0; i < CAR_WHEELS; ++i) {
    MdtCarWheelID j = car->joint[i];
    MeVector3 axis;
    if (car->brake)
      MdtCarWheelSetHingeLimitedForceMotor(j, 0, CAR_BRAKE_TORQUE);
    else if (i >= CAR_REAR_LEFT && car->throttle != 0)
      /* Rear-wheel drive. Rolling forward (+x) turns the wheel about -z,
       * so a forward speed v is a hinge rate of -v / r. */
      MdtCarWheelSetHingeLimitedForceMotor(j, -car->throttle * CAR_TOP_SPEED / CAR_WHEEL_RADIUS, CAR_DRIVE_TORQUE);
    else
      MdtCarWheelSetHingeLimitedForceMotor(j, 0, 0); /* free to roll */
    if (i < CAR_REAR_LEFT) {
      /* Steering: a motor turning the wheel towards the wanted angle. The
       * motor drives the wheel's turn relative to the chassis and the joint
       * reports the chassis relative to the wheel (the opposite sign), so
       * the gap is want + angle, as in the guide's QuadBike (PASTE_12). */
      const MeReal want = car->steering * CAR_MAX_STEER;
      MdtCarWheelSetSteeringLimitedForceMotor(j, 8 * (want + MdtCarWheelGetSteeringAngle(j)), 400);
    }
    /* The guide's advice for fast-turning wheels: the hinge axis as the
     * fast-spin axis, set before every step. */
    MdtCarWheelGetHingeAxis(j, axis);
    MdtBodySetFastSpinAxis(car->wheelBody[i], axis[0], axis[1], axis[2]);
  }
}

void CarTerrainStep(CarTerrain *car) {
  MeVector3 before, after, d;
  if (car->throttle > 1) car->throttle = 1;
  if (car->throttle < -1) car->throttle = -1;
  if (car->steering > 1) car->steering = 1;
  if (car->steering < -1) car->steering = -1;
  ApplyControls(car);
  MdtBodyGetPosition(car->chassisBody, before);
  MstUniverseStep(car->universe, CAR_STEP);
  MdtBodyGetPosition(car->chassisBody, after);
  MeVector3Subtract(d, after, before);
  car->distance += MeVector3Magnitude(d);
  ++car->steps;
}

MeReal CarTerrainForwardSpeed(const CarTerrain *car) {
  MeMatrix4Ptr tm = MdtBodyGetTransformPtr(car->chassisBody);
  MeVector3 v;
  MdtBodyGetLinearVelocity(car->chassisBody, v);
  return v[0] * tm[0][0] + v[1] * tm[0][1] + v[2] * tm[0][2];
}
