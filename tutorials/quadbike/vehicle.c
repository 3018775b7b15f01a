/* vehicle.c: the quad bike (the guide's Vehicle.c): a box chassis with a
 * lowered centre of mass (PASTE_06), four sphere wheels (PASTE_07) on car
 * wheel joints with suspension, the front two steering (PASTE_08),
 * handlebars on a hinge (PASTE_09); throttle on the back wheels (PASTE_10),
 * brakes on all four (PASTE_11), steering of the front wheels (PASTE_12)
 * and of the handlebars (PASTE_13); the wheel-ground contact callback that
 * aligns friction with the rolling direction (PASTE_15). */
#include "quadbike.h"

/* The bike's dimensions (metres). The chassis box's inertia below is the
 * guide's: 1/12 m (b^2 + c^2) of a 1.8 x 0.4 x 0.6 box of 150 kg gives
 * 6.5, 45 and 42.5 kg m^2; the guide rounds them to 5, 45 and 40. A wheel
 * of 10 kg with the guide's 0.25 kg m^2 (2/5 m r^2) has radius 0.25 m. */
const VehicleData quadBikeData = {
    {(MeReal)1.8, (MeReal)0.4, (MeReal)0.6}, /* chassisDims */
    {0, (MeReal)-0.2, 0},                    /* chassisCOMOffset: at the box's floor */
    (MeReal)0.25,                            /* wheelRadius */
    (MeReal)0.22,                            /* wheelWidth */
    {
        {(MeReal)0.65, (MeReal)-0.15, (MeReal)-0.5}, /* FRONT_LEFT */
        {(MeReal)0.65, (MeReal)-0.15, (MeReal)0.5},  /* FRONT_RIGHT */
        {(MeReal)-0.6, (MeReal)-0.15, (MeReal)-0.5}, /* BACK_LEFT */
        {(MeReal)-0.6, (MeReal)-0.15, (MeReal)0.5},  /* BACK_RIGHT */
    },
    {(MeReal)0.55, (MeReal)0.55, 0}, /* hBarOffset */
    (MeReal)0.7,                     /* hBarWidth */
};

void InitialiseVehicle(Vehicle *veh, const MeVector3 startPos) {
  (void)veh, (void)startPos;
#if QUADBIKE_STEP >= 6
  MeMatrix3 Ixyz = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  MeMatrix4 comTM;
  MeVector3 pos;
  int i;
#  if QUADBIKE_STEP >= 7
  int j;
#  endif
  MeMatrix4TMMakeIdentity(comTM);
  MeMatrix4TMSetPosition(comTM, veh->data->chassisCOMOffset[0], veh->data->chassisCOMOffset[1],
                         veh->data->chassisCOMOffset[2]);
  (void)pos, (void)i;

  /* PASTE_06 */
  /* The chassis: a body and a box model */
  veh->chassisBody = MdtBodyCreate(world);
  veh->chassisGeom =
      McdBoxCreate(framework, veh->data->chassisDims[0], veh->data->chassisDims[1], veh->data->chassisDims[2]);
  veh->chassisCM = McdModelCreate(veh->chassisGeom);
  McdModelSetBody(veh->chassisCM, veh->chassisBody);
  McdModelSetMaterial(veh->chassisCM, chassisMat);
  McdSpaceInsertModel(space, veh->chassisCM);
  MdtBodyEnable(veh->chassisBody);
  MdtBodySetPosition(veh->chassisBody, startPos[0], startPos[1], startPos[2]);
  MdtBodySetMass(veh->chassisBody, 150);
  Ixyz[0][0] = 5;  /* 1/12 m (y^2 + z^2) */
  Ixyz[1][1] = 45; /* 1/12 m (x^2 + z^2) */
  Ixyz[2][2] = 40; /* 1/12 m (x^2 + y^2) */
  MdtBodySetInertiaTensor(veh->chassisBody, Ixyz);
  /* A lower centre of mass: the bike rolls over less easily */
  MdtBodySetCenterOfMassRelativeTransform(veh->chassisBody, comTM);
#endif

#if QUADBIKE_STEP >= 7
  /* PASTE_07 */
  for (i = 0; i < 4; i++) {
    /* A wheel: a body and a sphere model */
    veh->wheelBody[i] = MdtBodyCreate(world);
    veh->wheelGeom[i] = McdSphereCreate(framework, veh->data->wheelRadius);
    veh->wheelCM[i] = McdModelCreate(veh->wheelGeom[i]);
    McdModelSetBody(veh->wheelCM[i], veh->wheelBody[i]);
    McdModelSetMaterial(veh->wheelCM[i], wheelMat);
    McdSpaceInsertModel(space, veh->wheelCM[i]);
    MdtBodyEnable(veh->wheelBody[i]);
    MdtBodySetMass(veh->wheelBody[i], 10);
    Ixyz[0][0] = Ixyz[1][1] = Ixyz[2][2] = 0.25; /* 2/5 m r^2 */
    MdtBodySetInertiaTensor(veh->wheelBody[i], Ixyz);
    MeVector3Add(pos, startPos, veh->data->wheelOffset[i]);
    MdtBodySetPosition(veh->wheelBody[i], pos[0], pos[1], pos[2]);
    /* No collision between a wheel and the chassis */
    McdSpaceDisablePair(veh->wheelCM[i], veh->chassisCM);
    /* nor between the wheels */
    for (j = i - 1; j >= 0; j--) McdSpaceDisablePair(veh->wheelCM[i], veh->wheelCM[j]);
  }
#endif

#if QUADBIKE_STEP >= 8
  /* PASTE_08 */
  for (i = 0; i < 4; i++) {
    veh->wheelJoint[i] = MdtCarWheelCreate(world);
    MdtCarWheelSetBodies(veh->wheelJoint[i], veh->chassisBody, /* the chassis comes first */
                         veh->wheelBody[i]);
    MdtBodyGetPosition(veh->wheelBody[i], pos);
    MdtCarWheelSetPosition(veh->wheelJoint[i], pos[0], pos[1], pos[2]);
    MdtCarWheelSetSteeringAndHingeAxes(veh->wheelJoint[i], 0, 1, 0 /* steering: y */, 0, 0, 1 /* hinge: z */);
    if (i == BACK_LEFT || i == BACK_RIGHT) {
      /* Only the front wheels steer: lock the back ones */
      MdtCarWheelSetSteeringLock(veh->wheelJoint[i], 1);
    }
    /* Spring 50000 N/m, damping 0.4, +-15 cm of travel */
    MdtCarWheelSetSuspension(veh->wheelJoint[i], 50000, 0.4f, 0.001f, -0.15f, 0.15f, 0);
    MdtCarWheelEnable(veh->wheelJoint[i]);
    /* The wheel body remembers its joint (used by WheelGroundCB) */
    MdtBodySetUserData(veh->wheelBody[i], (void *)veh->wheelJoint[i]);
  }
#endif

#if QUADBIKE_STEP >= 9
  /* PASTE_09 */
  veh->hBarBody = MdtBodyCreate(world);
  MdtBodyEnable(veh->hBarBody);
  MeVector3Add(pos, startPos, veh->data->hBarOffset);
  MdtBodySetPosition(veh->hBarBody, pos[0], pos[1], startPos[2]);
  veh->hBarJoint = MdtHingeCreate(world);
  MdtHingeSetBodies(veh->hBarJoint, veh->chassisBody, veh->hBarBody);
  MdtHingeSetAxis(veh->hBarJoint, 0, 1, 0);
  MdtBodyGetPosition(veh->hBarBody, pos);
  MdtHingeSetPosition(veh->hBarJoint, pos[0], pos[1], pos[2]);
  MdtHingeEnable(veh->hBarJoint);
#endif
}

void UpdateVehicleControls(Vehicle *veh) {
  /* The steering controllers' settings: the wheels turn at most `width`
   * radians; within `pgap` of the target the turning rate slows down in
   * proportion; at most maxSpeed rad/s with maxForce N m. */
  const MeReal width = (MeReal)0.5, pgap = (MeReal)0.4, maxSpeed = 5, maxForce = 500;
  MeVector3 haxis;
  MeReal torque, theta, desired_vel;
  int i;
  (void)width, (void)pgap, (void)maxSpeed, (void)maxForce, (void)torque, (void)theta, (void)desired_vel, (void)haxis;
  if (!veh->wheelJoint[0]) return; /* before step 8 there is nothing to control */

  for (i = 0; i < 4; i++) {
    MdtCarWheelGetHingeAxis(veh->wheelJoint[i], haxis);
    if (i == BACK_LEFT || i == BACK_RIGHT) {
      /* The back wheels drive */
      if (veh->brakeInput == 0) {
        /* Brakes off */
        MdtCarWheelSetHingeLimitedForceMotor(veh->wheelJoint[i], 0, 0);
#if QUADBIKE_STEP >= 10
        /* PASTE_10 */
        torque = veh->throttleInput * -200;
        /* The engine's torque turns the wheel about its hinge axis */
        MdtBodyAddTorque(veh->wheelBody[i], torque * haxis[0], torque * haxis[1], torque * haxis[2]);
        /* and turns the chassis the other way */
        MdtBodyAddTorque(veh->chassisBody, -torque * haxis[0], -torque * haxis[1], -torque * haxis[2]);
#endif
      }
#if QUADBIKE_STEP >= 11
      /* PASTE_11 */
      else {
        /* Brakes on: a motor holding the wheel's spin at 0 */
        MeReal maxBrakeTorque = veh->brakeInput * 500;
        MdtCarWheelSetHingeLimitedForceMotor(veh->wheelJoint[i], 0, maxBrakeTorque);
      }
#endif
    } else {
      /* The front wheels steer */
#if QUADBIKE_STEP >= 12
      /* PASTE_12 */
      /* Front wheel do the steering proportional gap (radians). */
      theta = MdtCarWheelGetSteeringAngle(veh->wheelJoint[i]);
      desired_vel = veh->steeringInput * width + theta;
      desired_vel = max(-pgap, min(desired_vel, pgap));
      MdtCarWheelSetSteeringLimitedForceMotor(veh->wheelJoint[i], maxSpeed * desired_vel, maxForce);
#endif
      if (veh->brakeInput == 0) {
        /* Brakes off */
        MdtCarWheelSetHingeLimitedForceMotor(veh->wheelJoint[i], 0, 0);
      }
#if QUADBIKE_STEP >= 11
      /* PASTE_11, the second place: brakes on the front wheels too */
      else {
        MeReal maxBrakeTorque = veh->brakeInput * 500;
        MdtCarWheelSetHingeLimitedForceMotor(veh->wheelJoint[i], 0, maxBrakeTorque);
      }
#endif
    }
  }

#if QUADBIKE_STEP >= 13
  /* PASTE_13 */
  /* The handlebars follow the steering, through the hinge's limit
   * controller */
  if (veh->hBarJoint)
    MdtLimitController(MdtHingeGetLimit(veh->hBarJoint), -veh->steeringInput * width, pgap, maxSpeed, maxForce);
#endif
}

MeBool MEAPI WheelGroundCB(McdIntersectResult *result, McdContact *colC, MdtContactID dynC) {
#if QUADBIKE_STEP >= 15
  MdtBodyID body;
  MdtCarWheelID wj;
  MeVector3 haxis, normal, dir;
  MdtContactParamsID params;
  MeReal slip;
  /* PASTE_15 */
  body = MdtContactGetBody(dynC, 0);
  /* The terrain has no body, so the wheel is body 0 */
  wj = (MdtCarWheelID)MdtBodyGetUserData(body);
  if (wj) {
    /* The first friction direction: along the ground, across the hinge
     * axis (normal x hinge axis) */
    MdtCarWheelGetHingeAxis(wj, haxis);
    MdtContactGetNormal(dynC, normal);
    MeVector3Cross(dir, normal, haxis);
    MeVector3Normalize(dir);
    MdtContactSetDirection(dynC, dir[0], dir[1], dir[2]);
    /* More sideways slip the more the wheel leans (camber) */
    params = MdtContactGetParams(dynC);
    slip = 0.001f + MeFabs(MeVector3Dot(normal, haxis));
    MdtContactParamsSetSecondarySlip(params, slip);
  }
#else
  (void)dynC;
#endif
  (void)result, (void)colC;
  return 1;
}
