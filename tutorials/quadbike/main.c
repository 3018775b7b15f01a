/* main.c: the QuadBike tutorial's Karma world (the guide's main.c): the
 * universe and its world properties (PASTE_01), the materials (PASTE_02,
 * PASTE_14) and the tick, one step of collision and dynamics (PASTE_03,
 * PASTE_04). The window, graphics and keys are in viewer.c, which calls
 * tick() once per frame. */
#include "quadbike.h"
#include "joint_gap.h"

#include <stddef.h>

MstUniverseID universe;
MdtWorldID world;
McdSpaceID space;
MstBridgeID bridge;
McdFrameworkID framework;
MstMaterialID groundMat, wheelMat, chassisMat;
const MeReal timeStep = (MeReal)1 / (MeReal)60;

Vehicle quadBike;
Rider rider;

static QuadBikeOptions runOptions;
static long ticks;

/* The universe: pools sized for this application, the world's properties. */
int InitialiseMEWorld(void) {
#if QUADBIKE_STEP >= 1
  MstUniverseSizes sizes;
  /* PASTE_01 */
  /* Start from the default universe pool sizes */
  sizes = MstUniverseDefaultSizes;
  /* and size the pools for one bike, one rider and the terrain */
  sizes.dynamicBodiesMaxCount = 20;
  sizes.dynamicConstraintsMaxCount = 1000;
  sizes.materialsMaxCount = 10;
  sizes.collisionModelsMaxCount = 300;
  sizes.collisionPairsMaxCount = 1000;
  sizes.collisionUserGeometryTypesMaxCount = 0;
  sizes.collisionGeometryInstancesMaxCount = 0;
  /* One call makes the world, the collision space, the framework and the
   * bridge between them */
  universe = MstUniverseCreate(&sizes);
  if (!universe) return 0;
  world = MstUniverseGetWorld(universe);
  space = MstUniverseGetSpace(universe);
  bridge = MstUniverseGetBridge(universe);
  framework = MstUniverseGetFramework(universe);
  /* The world's properties: constraint softness, error correction, gravity
   * along -y */
  MdtWorldSetEpsilon(world, 0.0001f);
  MdtWorldSetGamma(world, timeStep * 10);
  MdtWorldSetGravity(world, 0, (MeReal)-20, 0);
#endif
  return 1;
}

/* Materials and the contact parameters between them. */
void InitialiseMaterials(void) {
#if QUADBIKE_STEP >= 2
  MdtContactParamsID params;
  /* PASTE_02 */
  groundMat = MstBridgeGetDefaultMaterial();
  wheelMat = MstBridgeGetNewMaterial(bridge);
  chassisMat = MstBridgeGetNewMaterial(bridge);
  /* Wheels on the ground: friction in two directions, little slip */
  params = MstBridgeGetContactParams(bridge, groundMat, wheelMat);
  MdtContactParamsSetType(params, MdtContactTypeFriction2D);
  MdtContactParamsSetPrimarySlip(params, 0.0001f);
  MdtContactParamsSetSecondarySlip(params, 0.005f);
  MdtContactParamsSetSoftness(params, 0.0001f);
  /* The chassis on the ground */
  params = MstBridgeGetContactParams(bridge, groundMat, chassisMat);
  MdtContactParamsSetType(params, MdtContactTypeFriction2D);
  MdtContactParamsSetSoftness(params, 0.0001f);
#endif
#if QUADBIKE_STEP >= 14
  /* PASTE_14 */
  MstBridgeSetPerContactCB(bridge, wheelMat, groundMat, WheelGroundCB);
#endif
}

void QuadBikeRideInputs(MeReal t, MeReal *throttle, MeReal *brake, MeReal *steering) {
  *throttle = t >= 1 && t < (MeReal)4.5 ? (MeReal)0.4 : 0;
  *steering = t >= (MeReal)2.5 && t < (MeReal)4.5 ? (MeReal)0.4 : 0;
  *brake = t >= (MeReal)4.5 ? 1 : 0;
}

MeReal QuadBikeTime(void) { return (MeReal)ticks * timeStep; }

void tick(void) {
  if (runOptions.ride)
    QuadBikeRideInputs(QuadBikeTime(), &quadBike.throttleInput, &quadBike.brakeInput, &quadBike.steeringInput);
  if (quadBike.chassisBody) UpdateVehicleControls(&quadBike);
  if (rider.limbBody[0]) UpdateRiderControls(&rider);
#if QUADBIKE_STEP >= 3
  /* PASTE_03 */
  /* Collision: the farfield's overlapping pairs, then the contacts of the
   * pairs that touch */
  McdSpaceUpdateAll(space);
  MstBridgeUpdateContacts(bridge, space, world);
#endif
#if QUADBIKE_STEP >= 4
  /* PASTE_04 */
  /* Dynamics: one fixed step */
  MdtWorldStep(world, timeStep);
#endif
  ++ticks;
}

void QuadBikeStartPosition(MeVector3 startPos) {
  /* Above the ground under the bike, with the wheels just clear of it. */
  const MeReal x = 0, z = 0;
  MeReal ground = TerrainHeightAt(x, z), h;
  int i;
  for (i = 0; i < 4; ++i) {
    h = TerrainHeightAt(x + quadBikeData.wheelOffset[i][0], z + quadBikeData.wheelOffset[i][2]);
    if (h > ground) ground = h;
  }
  startPos[0] = x;
  startPos[1] = ground + quadBikeData.wheelRadius - quadBikeData.wheelOffset[0][1] + (MeReal)0.05;
  startPos[2] = z;
}

int QuadBikeCreate(const QuadBikeOptions *options) {
  MeVector3 startPos;
  runOptions = *options;
  landscape.useTriList = options->useTriList;
  ticks = 0;
  if (!InitialiseMEWorld()) return 0;
  if (!world) return 1; /* before PASTE_01: an empty application */
  InitialiseMaterials();
  InitialiseTerrain();
  QuadBikeStartPosition(startPos);
  quadBike.data = &quadBikeData;
  InitialiseVehicle(&quadBike, startPos);
  rider.data = &riderData;
  InitialiseRider(&rider, startPos);
  return 1;
}

void QuadBikeDestroy(void) {
  if (universe) MstUniverseDestroy(universe);
  HeightFieldDestroy(&landscape.heightField);
  universe = NULL, world = NULL, space = NULL, bridge = NULL, framework = NULL;
  {
    const Vehicle noVehicle = {0};
    const Rider noRider = {0};
    const Landscape noLandscape = {0};
    quadBike = noVehicle;
    rider = noRider;
    landscape = noLandscape;
  }
}

int QuadBikeBodies(MdtBodyID bodies[14]) {
  int n = 0, i;
  if (quadBike.chassisBody) bodies[n++] = quadBike.chassisBody;
  for (i = 0; i < 4; ++i)
    if (quadBike.wheelBody[i]) bodies[n++] = quadBike.wheelBody[i];
  if (quadBike.hBarBody) bodies[n++] = quadBike.hBarBody;
  for (i = 0; i < NUM_LIMBS; ++i)
    if (rider.limbBody[i]) bodies[n++] = rider.limbBody[i];
  return n;
}

MeReal QuadBikeRiderJointError(void) {
  MeReal worst = 0, e;
  int i;
  for (i = 0; i < NUM_JOINTS; ++i) {
    if (!rider.joint[i]) continue;
    e = TutorialJointGap(rider.joint[i]);
    if (e > worst) worst = e;
  }
  if (quadBike.hBarJoint) {
    e = TutorialJointGap(MdtHingeQuaConstraint(quadBike.hBarJoint));
    if (e > worst) worst = e;
  }
  return worst;
}
