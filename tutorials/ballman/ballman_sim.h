/* ballman_sim.h: the simulation half of Ballman (no drawing).
 *
 * The guide's human falling down stairs (its "Frame time" example 4 and its
 * PlayStation 2 analysis): a rag doll of ten bodies -- head, torso, two
 * upper arms, two forearms, two thighs, two calves -- held together by nine
 * limited ball-and-socket joints (MdtSkeletal: a ball and socket with a
 * swing cone and a twist limit), a staircase, and a stack of boxes at the
 * foot of the stairs.
 *
 * Two friction models for every pair of materials, switched at any time:
 *   cheap (the default)  the guide's low-cost materials: 2D friction with
 *                        an infinite friction bound, the sliding given by
 *                        slip (viscous friction: sliding speed = slip x
 *                        friction force), and infinitely adhesive contacts,
 *                        so that no contact row has a bound Kea must find;
 *   high quality         Coulomb friction approximated by the normal-force
 *                        model (bound = coefficient x normal force), no
 *                        adhesion, no slip.
 * Units: metres, kilograms, seconds; y up; the stairs go down along +x. */
#ifndef BALLMAN_SIM_H
#define BALLMAN_SIM_H

#include "Mst.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BALLMAN_PARTS 10
#define BALLMAN_JOINTS 9
#define BALLMAN_STEPS 6 /* stair blocks: the landing and five steps */
#define BALLMAN_BOXES 6 /* the stack: rows of 3, 2, 1 */

typedef enum BallmanPart {
  BallmanTorso,
  BallmanHead,
  BallmanUpperArmL,
  BallmanUpperArmR,
  BallmanForearmL,
  BallmanForearmR,
  BallmanThighL,
  BallmanThighR,
  BallmanCalfL,
  BallmanCalfR
} BallmanPart;

typedef enum BallmanShape { BallmanBox, BallmanSphere, BallmanCapsule } BallmanShape;

/* A part's shape and size: a box's sides (a, b, c); a sphere's radius (a);
 * a capsule's radius (a) and the length of its cylinder (b), along its
 * local z. */
typedef struct BallmanPartShape {
  BallmanShape shape;
  MeReal a, b, c;
} BallmanPartShape;

typedef struct Ballman {
  MstUniverseID universe;
  McdModelID part[BALLMAN_PARTS];
  BallmanPartShape partShape[BALLMAN_PARTS];
  MdtSkeletalID joint[BALLMAN_JOINTS];
  McdModelID stair[BALLMAN_STEPS];
  MeMatrix4 stairTM[BALLMAN_STEPS];
  MeReal stairSize[BALLMAN_STEPS][3];
  McdModelID box[BALLMAN_BOXES];
  MeReal boxSide;
  McdModelID ground;
  MeMatrix4 groundTM;
  MstMaterialID dollMaterial, stairMaterial, boxMaterial;
  MeBool highQuality;
  int propelSteps; /* steps of push left */
} Ballman;

extern const MeReal kBallmanStep;       /* 1/60 s: one frame, one world step */
extern const int kBallmanProjection;    /* joint projection sweeps per step */
extern const MeReal kBallmanViscosity;  /* the cheap materials' slip */
extern const MeReal kBallmanPropelTime; /* how long one press pushes, s */

/* Builds everything in the starting pose (cheap friction). NULL if the
 * universe cannot be made. */
Ballman *BallmanCreate(void);
void BallmanDestroy(Ballman *b);
/* Back to the starting pose: doll and boxes, at rest; no push. */
void BallmanReset(Ballman *b);
/* Chooses the friction model of every material pair (see the top). */
void BallmanSetHighQualityFriction(Ballman *b, MeBool on);
/* Pushes the rag doll towards the boxes for kBallmanPropelTime. */
void BallmanPropel(Ballman *b);
/* A frame is one step of kBallmanStep in two halves, so that the viewer
 * and the benchmark can time them apart: collision (farfield, nearfield,
 * contacts), then dynamics (the push, Kea's solve, integration, joint
 * projection). BallmanStep runs a whole frame. */
void BallmanCollide(Ballman *b);
void BallmanDynamics(Ballman *b);
void BallmanStep(Ballman *b);
/* The largest joint error now: the distance between a joint's point as
 * carried by its two bodies (m). */
MeReal BallmanJointError(const Ballman *b);
/* What the last dynamics half did: rows solved, Kea's iterations, ... */
void BallmanStepStats(const Ballman *b, MdtWorldStepStats *stats);
/* The torso's centre. */
void BallmanTorsoPosition(const Ballman *b, MeVector3 x);

#ifdef __cplusplus
}
#endif

#endif
