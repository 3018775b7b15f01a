/* carterrain.h: the simulation side of CarTerrain (no drawing), so that
 * the behaviour tests can drive the car without MeViewer.
 *
 * A car of a chassis and four sphere wheels on CarWheel joints drives over
 * the height-field terrain "terrain2" (heightfield.h), served to collision
 * through a triangle list. Frame: y up; the car starts at the centre of
 * the map facing +x. Each wheel-ground contact gets its friction direction
 * from a per-contact callback (the contact normal crossed with the wheel's
 * hinge axis: the rolling direction), and every wheel's fast-spin axis is
 * set to its hinge axis before each step, as the guide advises.
 *
 *   CarTerrain car;
 *   if (!CarTerrainCreate(&car, "terrain2")) ...;
 *   for (...) { CarTerrainScript(&car); (or set car.throttle / car.steering)
 *               CarTerrainStep(&car); }
 *   CarTerrainDestroy(&car);
 *
 * Only one CarTerrain may exist at a time (the bridge's callbacks find it
 * through a file-scope pointer). */
#ifndef KARMA_TUTORIAL_CARTERRAIN_H
#define KARMA_TUTORIAL_CARTERRAIN_H

#include "Mst.h"
#include "heightfield.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The car's figures (metres, kilograms, seconds). */
#define CAR_STEP ((MeReal)1 / 60)
#define CAR_TERRAIN_SCALE ((MeReal)15)   /* height of grey level 255 */
#define CAR_CHASSIS_LENGTH ((MeReal)3.2) /* along x */
#define CAR_CHASSIS_HEIGHT ((MeReal)0.5)
#define CAR_CHASSIS_WIDTH ((MeReal)1.6) /* along z */
#define CAR_CHASSIS_MASS ((MeReal)800)
#define CAR_WHEEL_RADIUS ((MeReal)0.4)
#define CAR_WHEEL_MASS ((MeReal)25)
#define CAR_WHEEL_X ((MeReal)1.25)     /* front (+) and rear (-) axle, from the chassis centre */
#define CAR_WHEEL_Z ((MeReal)0.95)     /* left (-) and right (+) wheel */
#define CAR_WHEEL_DROP ((MeReal)0.45)  /* wheel centre below the chassis centre, unloaded */
#define CAR_SPRING ((MeReal)40000)     /* suspension stiffness, N/m */
#define CAR_DAMPER ((MeReal)3000)      /* suspension damping, N s/m */
#define CAR_TRAVEL ((MeReal)0.2)       /* suspension travel each way from the reference */
#define CAR_TOP_SPEED ((MeReal)12)     /* m/s at full throttle */
#define CAR_DRIVE_TORQUE ((MeReal)600) /* per driven wheel, N m */
#define CAR_BRAKE_TORQUE ((MeReal)1500)
#define CAR_MAX_STEER ((MeReal)0.5)   /* rad */
#define CAR_EPSILON ((MeReal)0.001)   /* the world's constraint softness */
#define CAR_GRIP_ALONG ((MeReal)1.2)  /* tyre friction coefficients along */
#define CAR_GRIP_ACROSS ((MeReal)1.0) /* and across the tyre */
/* The static load on one wheel, N. */
#define CAR_WHEEL_LOAD ((CAR_CHASSIS_MASS / 4 + CAR_WHEEL_MASS) * (MeReal)9.81)

enum { CAR_FRONT_LEFT, CAR_FRONT_RIGHT, CAR_REAR_LEFT, CAR_REAR_RIGHT, CAR_WHEELS };

typedef struct CarTerrain {
  MstUniverseID universe;
  HeightField terrain;
  McdModelID ground, chassis, wheel[CAR_WHEELS];
  MdtBodyID chassisBody, wheelBody[CAR_WHEELS];
  MdtCarWheelID joint[CAR_WHEELS];
  MeMatrix4 groundTM; /* the terrain model's transform (kept by pointer) */
  MstMaterialID groundMaterial, wheelMaterial, chassisMaterial;
  /* Controls: throttle in [-1, 1] (negative: reverse), steering in [-1, 1]
   * (positive: left), brake 0 or 1. */
  MeReal throttle, steering;
  int brake;
  long steps;
  /* Figures for tests and the caption. */
  long wheelContacts;       /* per-contact callbacks so far */
  MeReal worstDirectionDot; /* largest |direction . normal| or |direction . hinge| seen */
  MeReal distance;          /* path length of the chassis, m */
} CarTerrain;

/* Loads the terrain (HeightFieldFromBMP(name, CAR_TERRAIN_SCALE)) and
 * builds the universe and the car at rest, its wheels just touching the
 * ground at the map's centre. Returns 1, or 0 with a message. */
int CarTerrainCreate(CarTerrain *car, const char *terrainName);
void CarTerrainDestroy(CarTerrain *car);

/* The scripted drive used when nobody drives, by the time since the start:
 * standing for 1 s, then throttle 0.5 (6 m/s) straight on, from 3 s a
 * steady left turn (steering 0.35) through the hills, braking from 18 s. */
void CarTerrainScript(CarTerrain *car);

/* Applies the controls to the joints' motors, sets the fast-spin axes and
 * steps the universe by CAR_STEP. */
void CarTerrainStep(CarTerrain *car);

/* The chassis's speed along its own forward axis, m/s. */
MeReal CarTerrainForwardSpeed(const CarTerrain *car);

#ifdef __cplusplus
}
#endif

#endif
