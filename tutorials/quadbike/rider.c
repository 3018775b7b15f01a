/* rider.c: the rider (the guide's Rider.c): eight box limbs (PASTE_16),
 * joined to each other, to the chassis (ankles) and to the handlebars
 * (wrists) by hinges and ball-and-socket joints (PASTE_17), held in their
 * posture by stiff, damped hinge limits (PASTE_18), which the controls move
 * to crouch and lean into turns (PASTE_19). */
#include "quadbike.h"

/* The rider sitting on the bike, in the bike's start frame (x forward, y
 * up, z to the right; the chassis box's centre at 0, its top at y = 0.2).
 * Key points: ankles A (0, 0.15), knees K (0.2, 0.6), hips H (-0.3, 0.45),
 * shoulders S (0, 1.0, +-0.25), neck (0, 1.04), elbows E (0.375, 0.9375,
 * +-0.25), grips W (0.55, 0.55, +-0.25) on the handlebars. Each limb is a
 * box whose long side (x) runs between its two joints, turned about z by
 * limbAng[0]. Masses are left at MdtBodyCreate's default (1 kg). */
const RiderData riderData = {
    /* limbPos */
    {
        {(MeReal)0.1, (MeReal)0.375, 0},                  /* LOWER_LEGS: A-K */
        {(MeReal)-0.05, (MeReal)0.525, 0},                /* UPPER_LEGS: K-H */
        {(MeReal)-0.15, (MeReal)0.725, 0},                /* TORSO: H to the shoulders */
        {(MeReal)0.03, (MeReal)1.18, 0},                  /* HEAD */
        {(MeReal)0.1875, (MeReal)0.96875, (MeReal)0.25},  /* R_UPPER_ARM: S-E */
        {(MeReal)0.4625, (MeReal)0.74375, (MeReal)0.25},  /* R_LOWER_ARM: E-W */
        {(MeReal)0.1875, (MeReal)0.96875, (MeReal)-0.25}, /* L_UPPER_ARM */
        {(MeReal)0.4625, (MeReal)0.74375, (MeReal)-0.25}, /* L_LOWER_ARM */
    },
    /* limbAng: (psi, theta, phi); with theta = phi = 0 a turn by psi about z */
    {
        {(MeReal)1.1526, 0, 0}, /* atan2(0.45, 0.2) */
        {(MeReal)0.2915, 0, 0}, /* atan2(0.15, 0.5) */
        {(MeReal)1.0714, 0, 0}, /* atan2(0.55, 0.3) */
        {0, 0, 0},
        {(MeReal)-0.1651, 0, 0}, /* atan2(-0.0625, 0.375) */
        {(MeReal)-1.1466, 0, 0}, /* atan2(-0.3875, 0.175) */
        {(MeReal)-0.1651, 0, 0},
        {(MeReal)-1.1466, 0, 0},
    },
    /* limbDim */
    {
        {(MeReal)0.49, (MeReal)0.13, (MeReal)0.4},
        {(MeReal)0.52, (MeReal)0.16, (MeReal)0.42},
        {(MeReal)0.63, (MeReal)0.22, (MeReal)0.4},
        {(MeReal)0.22, (MeReal)0.24, (MeReal)0.2},
        {(MeReal)0.38, (MeReal)0.09, (MeReal)0.09},
        {(MeReal)0.425, (MeReal)0.08, (MeReal)0.08},
        {(MeReal)0.38, (MeReal)0.09, (MeReal)0.09},
        {(MeReal)0.425, (MeReal)0.08, (MeReal)0.08},
    },
    /* jointPos */
    {
        {0, (MeReal)0.15, 0},                           /* ANKLES */
        {(MeReal)0.2, (MeReal)0.6, 0},                  /* KNEES */
        {(MeReal)-0.3, (MeReal)0.45, 0},                /* HIPS */
        {0, (MeReal)1.04, 0},                           /* NECK */
        {0, (MeReal)1.0, (MeReal)0.25},                 /* R_SHOULDER */
        {(MeReal)0.375, (MeReal)0.9375, (MeReal)0.25},  /* R_ELBOW */
        {(MeReal)0.55, (MeReal)0.55, (MeReal)0.25},     /* R_WRIST */
        {0, (MeReal)1.0, (MeReal)-0.25},                /* L_SHOULDER */
        {(MeReal)0.375, (MeReal)0.9375, (MeReal)-0.25}, /* L_ELBOW */
        {(MeReal)0.55, (MeReal)0.55, (MeReal)-0.25},    /* L_WRIST */
    },
    /* jointAxis: ankles, knees and neck bend about z; the hips' axis runs
     * front to back (the rider leans sideways); the shoulders' is z turned
     * forwards a little, so an elbow swings out as its arm goes back */
    {
        {0, 0, 1},
        {0, 0, 1},
        {1, 0, 0},
        {0, 0, 1},
        {(MeReal)0.2, 0, (MeReal)0.98},
        {0, 0, 0},
        {0, 0, 0},
        {(MeReal)-0.2, 0, (MeReal)0.98},
        {0, 0, 0},
        {0, 0, 0},
    },
    /* jointBodies */
    {
        {LOWER_LEGS, -1}, /* ankles: to the chassis */
        {UPPER_LEGS, LOWER_LEGS},
        {TORSO, UPPER_LEGS},
        {HEAD, TORSO},
        {R_UPPER_ARM, TORSO},
        {R_LOWER_ARM, R_UPPER_ARM},
        {R_LOWER_ARM, -1}, /* wrists: to the handlebars */
        {L_UPPER_ARM, TORSO},
        {L_LOWER_ARM, L_UPPER_ARM},
        {L_LOWER_ARM, -1},
    },
    /* isHinge */
    1u << ANKLES | 1u << KNEES | 1u << HIPS | 1u << NECK | 1u << R_SHOULDER | 1u << L_SHOULDER,
    /* jointParam: limit stiffness (N m/rad), damping (N m s/rad) */
    {
        {1000, 20},
        {1000, 20},
        {600, 15},
        {400, 10},
        {0, 0},
        {0, 0},
        {0, 0},
        {0, 0},
        {0, 0},
        {0, 0},
    },
};

void InitialiseRider(Rider *rider, const MeVector3 startPos) {
#if QUADBIKE_STEP >= 16
  MeVector3 pos;
  MeMatrix3 R;
  int i, j;
#  if QUADBIKE_STEP >= 17
  MdtBodyID body1, body2;
  MdtHingeID hinge;
  MdtBSJointID bsj;
#  endif
#  if QUADBIKE_STEP >= 18
  MdtLimitID limit;
#  endif

  /* PASTE_16 */
  for (i = 0; i < NUM_LIMBS; i++) {
    rider->limbBody[i] = MdtBodyCreate(world);
    MeVector3Add(pos, startPos, rider->data->limbPos[i]);
    MdtBodySetPosition(rider->limbBody[i], pos[0], pos[1], pos[2]);
    MeMatrix3FromEulerAngles(R, rider->data->limbAng[i][0], rider->data->limbAng[i][1], rider->data->limbAng[i][2]);
    MdtBodySetOrientation(rider->limbBody[i], R);
    MdtBodyEnable(rider->limbBody[i]);
    /* Collision: a box per limb */
    rider->limbGeom[i] =
        McdBoxCreate(framework, rider->data->limbDim[i][0], rider->data->limbDim[i][1], rider->data->limbDim[i][2]);
    rider->limbCM[i] = McdModelCreate(rider->limbGeom[i]);
    McdModelSetBody(rider->limbCM[i], rider->limbBody[i]);
    McdSpaceInsertModel(space, rider->limbCM[i]);
    /* The limbs do not collide with each other */
    for (j = i - 1; j >= 0; j--) McdSpaceDisablePair(rider->limbCM[i], rider->limbCM[j]);
    /* nor with the bike */
    McdSpaceDisablePair(rider->limbCM[i], quadBike.chassisCM);
    for (j = 0; j < 4; j++) McdSpaceDisablePair(rider->limbCM[i], quadBike.wheelCM[j]);
  }
#endif

#if QUADBIKE_STEP >= 17
  /* PASTE_17 */
  for (i = 0; i < NUM_JOINTS; i++) {
    /* The two bodies */
    body1 = rider->limbBody[rider->data->jointBodies[i][0]];
    if (rider->data->jointBodies[i][1] == -1) {
      if (rider->data->jointBodies[i][0] == LOWER_LEGS) {
        body2 = quadBike.chassisBody;
      } else {
        body2 = quadBike.hBarBody;
      }
    } else {
      body2 = rider->limbBody[rider->data->jointBodies[i][1]];
    }
    /* The joint */
    if (rider->data->isHinge & 1 << i) {
      hinge = MdtHingeCreate(world);
      MdtHingeSetBodies(hinge, body1, body2);
      MeVector3Add(pos, startPos, rider->data->jointPos[i]);
      MdtHingeSetPosition(hinge, pos[0], pos[1], pos[2]);
      MdtHingeSetAxis(hinge, rider->data->jointAxis[i][0], rider->data->jointAxis[i][1], rider->data->jointAxis[i][2]);
      rider->joint[i] = MdtHingeQuaConstraint(hinge);
      /* Add hinge joint limit code here */
#  if QUADBIKE_STEP >= 18
      /* PASTE_18 */
      if (rider->data->jointParam[i][0]) {
        /* Both stops at 0, the present angle: a stiff, damped spring
         * holding the posture */
        limit = MdtHingeGetLimit(hinge);
        MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(limit), rider->data->jointParam[i][0]);
        MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(limit), rider->data->jointParam[i][0]);
        MdtSingleLimitSetDamping(MdtLimitGetUpperLimit(limit), rider->data->jointParam[i][1]);
        MdtSingleLimitSetDamping(MdtLimitGetLowerLimit(limit), rider->data->jointParam[i][1]);
        MdtLimitActivateLimits(limit, 1);
      }
#  endif
    } else {
      bsj = MdtBSJointCreate(world);
      MdtBSJointSetBodies(bsj, body1, body2);
      MeVector3Add(pos, startPos, rider->data->jointPos[i]);
      MdtBSJointSetPosition(bsj, pos[0], pos[1], pos[2]);
      rider->joint[i] = MdtBSJointQuaConstraint(bsj);
    }
    MdtConstraintEnable(rider->joint[i]);
  }
#endif
  (void)rider, (void)startPos;
}

void UpdateRiderControls(Rider *rider) {
#if QUADBIKE_STEP >= 19
  const MeReal maxAng = (MeReal)0.3; /* the most the rider leans (radians) */
  MeVector3 vel;
  MeVector3Ptr xAxis;
  MeReal speed, angle;
  MdtLimitID limit;
  /* PASTE_19 */
  /* The faster the bike goes forwards, the more the rider leans */
  MdtBodyGetLinearVelocity(quadBike.chassisBody, vel);
  xAxis = (MeVector3Ptr)MdtBodyGetTransformPtr(quadBike.chassisBody);
  speed = max(0, MeVector3Dot(xAxis, vel));
  angle = speed * 0.035f;
  angle = min(angle, maxAng);
  angle = -quadBike.steeringInput * angle;
  /* Move the hips' stops: the rider leans into the turn */
  limit = MdtHingeGetLimit(MdtConstraintDCastHinge(rider->joint[HIPS]));
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(limit), angle);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(limit), angle);
  /* and bends the knees (and ankles) to crouch lower */
  angle = MeFabs(angle);
  limit = MdtHingeGetLimit(MdtConstraintDCastHinge(rider->joint[KNEES]));
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(limit), angle * 2);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(limit), angle * 2);
  limit = MdtHingeGetLimit(MdtConstraintDCastHinge(rider->joint[ANKLES]));
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(limit), -angle * 1.2);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(limit), -angle * 1.2);
#else
  (void)rider;
#endif
}
