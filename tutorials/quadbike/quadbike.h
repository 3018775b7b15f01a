/* quadbike.h: what the QuadBike tutorial's files share.
 *
 * The tutorial builds, step by step, a rider on a quad bike on a height
 * field terrain (the guide's QuadBike chapter). Each of the guide's code
 * sections PASTE_01 .. PASTE_19 sits in the function the guide names and is
 * compiled in only from its step on: QUADBIKE_STEP is defined per target
 * (0 .. 19; the whole tutorial is step 19).
 *
 * Files, as the guide splits them:
 *   main.c     the Karma world: universe, materials, the tick (one step);
 *              the scripted ride
 *   terrain.c  the terrain: a height field (triangle list) or a flat plane
 *   vehicle.c  the quad bike: chassis, wheels, suspension, handlebars,
 *              throttle, brake, steering, the wheel-ground contact callback
 *   rider.c    the rider: limbs, joints, posture, leaning and crouching
 *   viewer.c   main(): the window (MeViewer), camera, graphics and keys
 * Everything but viewer.c is the simulation (the library quadbike_sim that
 * the behaviour tests link); it draws nothing.
 *
 * Coordinates: right handed, y up, metres and kilograms. The bike starts
 * facing +x, so +z is its right-hand side. */
#ifndef QUADBIKE_H
#define QUADBIKE_H

#include "Mst.h"
#include "heightfield.h"

#ifndef QUADBIKE_STEP
#  define QUADBIKE_STEP 19
#endif

/* 1: the terrain is the height field read from terrain2.bmp; 0: a flat
 * plane. The guide picks this in terrain.c at compile time; here it is the
 * default, and the run-time options -flat / -terrain override it
 * (QuadBikeOptions.useTriList). */
#ifndef USE_TRI_LIST
#  define USE_TRI_LIST 1
#endif

#ifndef max
#  define max(a, b) ((a) > (b) ? (a) : (b))
#endif
#ifndef min
#  define min(a, b) ((a) < (b) ? (a) : (b))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- main.c: the Karma world ------------------------------------------ */

extern MstUniverseID universe;
extern MdtWorldID world;
extern McdSpaceID space;
extern MstBridgeID bridge;
extern McdFrameworkID framework;
extern MstMaterialID groundMat, wheelMat, chassisMat;
extern const MeReal timeStep; /* seconds per tick (1/60) */

int InitialiseMEWorld(void);
void InitialiseMaterials(void);
/* One simulation step: the controls, collision, dynamics. */
void tick(void);

/* ---- terrain.c ----------------------------------------------------------- */

typedef struct Landscape {
  HeightField heightField; /* the terrain's grid (empty on the flat plane) */
  McdGeometryID collGeom;  /* triangle list or plane */
  McdModelID collModel;
  MeMatrix4 transform; /* the model's TM (it has no body) */
  int useTriList;      /* which of the two this run uses */
} Landscape;

extern Landscape landscape;

void InitialiseTerrain(void);
/* Ground height under (x, z): the height field, or 0 on the flat plane. */
MeReal TerrainHeightAt(MeReal x, MeReal z);
int MEAPI TriListGeneratorCB(McdModelPair *modelPair, McdUserTriangle *triangles, MeVector3 pos, MeReal radius,
                             int maxTriangles);

/* ---- vehicle.c ----------------------------------------------------------- */

enum { FRONT_LEFT, FRONT_RIGHT, BACK_LEFT, BACK_RIGHT };

typedef struct VehicleData {
  MeReal chassisDims[3];      /* box: length (x), height (y), width (z) */
  MeReal chassisCOMOffset[3]; /* centre of mass relative to the box's centre */
  MeReal wheelRadius;
  MeReal wheelWidth;        /* drawn only: collision uses a sphere */
  MeVector3 wheelOffset[4]; /* wheel centres relative to the chassis */
  MeVector3 hBarOffset;     /* handlebar pivot relative to the chassis */
  MeReal hBarWidth;         /* grip to grip */
} VehicleData;

typedef struct Vehicle {
  const VehicleData *data;
  MdtBodyID chassisBody;
  McdGeometryID chassisGeom;
  McdModelID chassisCM;
  MdtBodyID wheelBody[4];
  McdGeometryID wheelGeom[4];
  McdModelID wheelCM[4];
  MdtCarWheelID wheelJoint[4];
  MdtBodyID hBarBody;
  MdtHingeID hBarJoint;
  /* Control inputs: throttle and brake in [0, 1], steering in [-1, 1]
   * (positive turns left). */
  MeReal throttleInput, brakeInput, steeringInput;
} Vehicle;

extern const VehicleData quadBikeData;
extern Vehicle quadBike;

void InitialiseVehicle(Vehicle *veh, const MeVector3 startPos);
void UpdateVehicleControls(Vehicle *veh);
MeBool MEAPI WheelGroundCB(McdIntersectResult *result, McdContact *colC, MdtContactID dynC);

/* ---- rider.c ------------------------------------------------------------- */

/* The limbs. The legs are one body per pair: the rider is not meant to
 * fall off. */
enum { LOWER_LEGS, UPPER_LEGS, TORSO, HEAD, R_UPPER_ARM, R_LOWER_ARM, L_UPPER_ARM, L_LOWER_ARM, NUM_LIMBS };
/* The joints. */
enum { ANKLES, KNEES, HIPS, NECK, R_SHOULDER, R_ELBOW, R_WRIST, L_SHOULDER, L_ELBOW, L_WRIST, NUM_JOINTS };

typedef struct RiderData {
  MeVector3 limbPos[NUM_LIMBS]; /* centres relative to the bike's start position */
  MeReal limbAng[NUM_LIMBS][3]; /* Euler angles (MeMatrix3FromEulerAngles) */
  MeReal limbDim[NUM_LIMBS][3]; /* box sides: length (x), thickness (y), width (z) */
  MeVector3 jointPos[NUM_JOINTS];
  MeVector3 jointAxis[NUM_JOINTS];  /* hinges only */
  int jointBodies[NUM_JOINTS][2];   /* limb, other limb (-1: the bike) */
  unsigned isHinge;                 /* bit i: joint i is a hinge (else ball and socket) */
  MeReal jointParam[NUM_JOINTS][2]; /* hinge limit stiffness, damping (0: no limit) */
} RiderData;

typedef struct Rider {
  const RiderData *data;
  MdtBodyID limbBody[NUM_LIMBS];
  McdGeometryID limbGeom[NUM_LIMBS];
  McdModelID limbCM[NUM_LIMBS];
  MdtConstraintID joint[NUM_JOINTS];
} Rider;

extern const RiderData riderData;
extern Rider rider;

void InitialiseRider(Rider *rider, const MeVector3 startPos);
void UpdateRiderControls(Rider *rider);

/* ---- the tutorial as a whole (main.c) ------------------------------------ */

typedef struct QuadBikeOptions {
  int useTriList; /* 1: height field, 0: flat plane */
  int ride;       /* 1: the scripted ride drives the bike */
} QuadBikeOptions;

/* Builds everything this step has: world, materials, terrain, bike, rider.
 * Returns 0 when the world could not be made (before PASTE_01 there is no
 * world at all: that is not a failure, the function returns 1). */
int QuadBikeCreate(const QuadBikeOptions *options);
void QuadBikeDestroy(void);
/* The bike's start position: above the ground at the start. */
void QuadBikeStartPosition(MeVector3 startPos);
/* Seconds simulated so far (ticks x timeStep). */
MeReal QuadBikeTime(void);

/* The scripted ride, as a function of time:
 *   0 - 1 s    standing still (the suspension settles)
 *   1 - 4.5 s  throttle 0.4
 *   2.5 - 4.5 s  steering 0.4 to the left (the front wheels turn 0.2 rad)
 *   4.5 s on   brake 1
 * The goldens keep frames 0, 120, 240, 360: the start, driving straight at
 * 2 s, turning at 4 s, stopped at 6 s. */
void QuadBikeRideInputs(MeReal t, MeReal *throttle, MeReal *brake, MeReal *steering);

/* Every body this step has, in a fixed order (chassis, wheels, handlebars,
 * limbs); returns how many (at most 14). */
int QuadBikeBodies(MdtBodyID bodies[14]);

/* The largest distance between the two bodies' attachment points over the
 * rider's joints (and the handlebar hinge), in metres; 0 before step 17. */
MeReal QuadBikeRiderJointError(void);

#ifdef __cplusplus
}
#endif

#endif
