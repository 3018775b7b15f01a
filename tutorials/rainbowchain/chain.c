/* chain.c: RainbowChain's world: a universe, a ground plane, ten balls on
 * one shared sphere geometry, eleven ball-and-socket joints. */
#include "chain.h"
#include "joint_gap.h"

#include <stdlib.h>

const MeReal kChainBallRadius = (MeReal)0.5;
const MeReal kChainLink = (MeReal)1.1;
const MeReal kChainStep = (MeReal)1 / 60;
const int kChainProjection = 2;

/* Where ball 0 hangs from (its centre), and the direction the straight
 * chain points at the start. */
static const MeReal kPivot[3] = {-4.5, 5.5, 2.5};
static const MeReal kDensity = (MeReal)1.5;

static void StartPose(RainbowChain *c) {
  int i;
  for (i = 0; i < RC_NBALLS; ++i) {
    MdtBodyID b = McdModelGetBody(c->ball[i]);
    MdtBodySetPosition(b, kPivot[0] + kChainLink * (MeReal)i, kPivot[1], kPivot[2]);
    MdtBodySetQuaternion(b, 1, 0, 0, 0);
    MdtBodySetLinearVelocity(b, 0, 0, 0);
    MdtBodySetAngularVelocity(b, 0, 0, 0);
    MdtBodyEnable(b);
  }
  MeVector3Set(c->endForce, 0, 0, 0);
}

RainbowChain *RainbowChainCreate(void) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  RainbowChain *c = (RainbowChain *)calloc(1, sizeof *c);
  int i;
  if (!c) return NULL;
  sizes.dynamicBodiesMaxCount = RC_NBALLS;
  sizes.collisionModelsMaxCount = RC_NBALLS + 1;
  sizes.collisionPairsMaxCount = 100;
  sizes.dynamicConstraintsMaxCount = 200;
  c->universe = MstUniverseCreate(&sizes);
  if (!c->universe) {
    free(c);
    return NULL;
  }
  MdtWorldSetGravity(c->universe->world, 0, -(MeReal)9.81, 0);
  /* One world step per frame. Falling from the horizontal the chain whips
     * round, and a velocity step alone lets each joint drift open by
     * h^2 w^2 d / 2 a step; the joint projection (MdtWorldSetJointProjection)
     * closes the joints after every step, and a high gamma (the fraction
     * of a joint's error corrected per step) takes what is left. */
  MdtWorldSetJointProjection(c->universe->world, kChainProjection);
  MdtWorldSetGamma(c->universe->world, (MeReal)0.8);

  /* The ground: McdPlane's normal is its local z; turn it onto world y. */
  MeMatrix4TMMakeIdentity(c->groundTM);
  c->groundTM[1][1] = 0, c->groundTM[1][2] = -1;
  c->groundTM[2][1] = 1, c->groundTM[2][2] = 0;
  c->ground = MstFixedModelCreate(c->universe, McdPlaneCreate(c->universe->frame), c->groundTM);

  /* Friction between everything (the default material pair). */
  {
    MdtContactParamsID p =
        MstBridgeGetContactParams(c->universe->bridge, MstBridgeGetDefaultMaterial(), MstBridgeGetDefaultMaterial());
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFriction(p, 2);
    MdtContactParamsSetRestitution(p, (MeReal)0.2);
  }

  /* One sphere geometry shared by every ball's model. */
  c->ballGeometry = McdSphereCreate(c->universe->frame, kChainBallRadius);
  for (i = 0; i < RC_NBALLS; ++i) c->ball[i] = MstModelAndBodyCreate(c->universe, c->ballGeometry, kDensity);
  StartPose(c);

  /* Ball 0 to the world at its centre, then each ball to the one before
     * it halfway between their centres. */
  for (i = 0; i < RC_NBALLS; ++i) {
    MdtBodyID prev = i == 0 ? NULL : McdModelGetBody(c->ball[i - 1]);
    MdtBodyID self = McdModelGetBody(c->ball[i]);
    MeReal x = kPivot[0] + kChainLink * ((MeReal)i - (i == 0 ? 0 : (MeReal)0.5));
    c->joint[i] = MdtBSJointCreate(c->universe->world);
    if (i == 0)
      MdtBSJointSetBodies(c->joint[i], self, NULL);
    else
      MdtBSJointSetBodies(c->joint[i], prev, self);
    MdtBSJointSetPosition(c->joint[i], x, kPivot[1], kPivot[2]);
    MdtBSJointEnable(c->joint[i]);
  }
  return c;
}

void RainbowChainDestroy(RainbowChain *c) {
  if (!c) return;
  MstUniverseDestroy(c->universe);
  free(c);
}

void RainbowChainReset(RainbowChain *c) { StartPose(c); }

void RainbowChainSetEndForce(RainbowChain *c, MeReal fx, MeReal fy, MeReal fz) {
  MeVector3Set(c->endForce, fx, fy, fz);
}

void RainbowChainCollide(RainbowChain *c) {
  /* Each ball's box grown by how far it can move in the step, so that a
     * ball whipping down at 12 m/s has its ground contact before it
     * touches. */
  MstUniversePrepareStep(c->universe, kChainStep);
  McdSpaceUpdateAll(c->universe->space);
  MstBridgeUpdateContacts(c->universe->bridge, c->universe->space, c->universe->world);
}

void RainbowChainDynamics(RainbowChain *c) {
  if (c->endForce[0] != 0 || c->endForce[1] != 0 || c->endForce[2] != 0) {
    MdtBodyID end = McdModelGetBody(c->ball[RC_NBALLS - 1]);
    MdtBodyEnable(end);
    MdtBodyAddForce(end, c->endForce[0], c->endForce[1], c->endForce[2]);
  }
  MdtWorldStep(c->universe->world, kChainStep);
}

void RainbowChainStep(RainbowChain *c) {
  RainbowChainCollide(c);
  RainbowChainDynamics(c);
}

MeReal RainbowChainJointError(const RainbowChain *c) {
  MeReal worst = 0;
  int i;
  for (i = 0; i < RC_NBALLS; ++i) {
    const MeReal d = TutorialJointGap(MdtBSJointQuaConstraint(c->joint[i]));
    if (d > worst) worst = d;
  }
  return worst;
}
