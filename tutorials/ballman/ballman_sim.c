/* ballman_sim.c: Ballman's world. See ballman_sim.h. */
#include "ballman_sim.h"
#include "joint_gap.h"

#include <stdlib.h>
#include <string.h>

const MeReal kBallmanStep = (MeReal)1 / 60;
const int kBallmanProjection = 2;
/* The guide's VISCOCITY: the cheap materials' slip, sliding speed (m/s)
 * per newton of friction force. */
const MeReal kBallmanViscosity = (MeReal)0.05;
const MeReal kBallmanPropelTime = (MeReal)0.5;

/* ---- the rag doll, standing, facing +x, feet at y = 0, centred on x = z = 0 */

typedef struct PartDef {
  BallmanShape shape;
  MeReal a, b, c; /* see BallmanPartShape */
  MeReal mass;
  MeReal x, y, z; /* centre */
  int axis;       /* capsules: the world axis the capsule lies along (1 y, 2 z) */
} PartDef;

static const PartDef kParts[BALLMAN_PARTS] = {
    {BallmanBox, (MeReal)0.22, (MeReal)0.56, (MeReal)0.38, 30, 0, (MeReal)1.22, 0, 0},                 /* torso */
    {BallmanSphere, (MeReal)0.12, 0, 0, 5, 0, (MeReal)1.64, 0, 0},                                     /* head */
    {BallmanCapsule, (MeReal)0.055, (MeReal)0.22, 0, (MeReal)2.5, 0, (MeReal)1.42, (MeReal)0.355, 2},  /* upper arm L */
    {BallmanCapsule, (MeReal)0.055, (MeReal)0.22, 0, (MeReal)2.5, 0, (MeReal)1.42, -(MeReal)0.355, 2}, /* upper arm R */
    {BallmanCapsule, (MeReal)0.045, (MeReal)0.22, 0, (MeReal)1.5, 0, (MeReal)1.42, (MeReal)0.655, 2},  /* forearm L */
    {BallmanCapsule, (MeReal)0.045, (MeReal)0.22, 0, (MeReal)1.5, 0, (MeReal)1.42, -(MeReal)0.655, 2}, /* forearm R */
    {BallmanCapsule, (MeReal)0.075, (MeReal)0.32, 0, 8, 0, (MeReal)0.715, (MeReal)0.1, 1},             /* thigh L */
    {BallmanCapsule, (MeReal)0.075, (MeReal)0.32, 0, 8, 0, (MeReal)0.715, -(MeReal)0.1, 1},            /* thigh R */
    {BallmanCapsule, (MeReal)0.06, (MeReal)0.33, 0, 4, 0, (MeReal)0.255, (MeReal)0.1, 1},              /* calf L */
    {BallmanCapsule, (MeReal)0.06, (MeReal)0.33, 0, 4, 0, (MeReal)0.255, -(MeReal)0.1, 1},             /* calf R */
};

typedef struct JointDef {
  int parent, child;
  MeReal x, y, z;     /* the joint point, standing */
  MeReal ax, ay, az;  /* the cone axis: from the joint towards the child, standing */
  MeReal cone, twist; /* swing half-angle, twist limit (rad) */
} JointDef;

static const JointDef kJoints[BALLMAN_JOINTS] = {
    {BallmanTorso, BallmanHead, 0, (MeReal)1.51, 0, 0, 1, 0, (MeReal)0.6, (MeReal)0.8},
    {BallmanTorso, BallmanUpperArmL, 0, (MeReal)1.42, (MeReal)0.19, 0, 0, 1, (MeReal)1.4, (MeReal)0.8},
    {BallmanTorso, BallmanUpperArmR, 0, (MeReal)1.42, -(MeReal)0.19, 0, 0, -1, (MeReal)1.4, (MeReal)0.8},
    {BallmanUpperArmL, BallmanForearmL, 0, (MeReal)1.42, (MeReal)0.505, 0, 0, 1, (MeReal)1.2, (MeReal)0.5},
    {BallmanUpperArmR, BallmanForearmR, 0, (MeReal)1.42, -(MeReal)0.505, 0, 0, -1, (MeReal)1.2, (MeReal)0.5},
    {BallmanTorso, BallmanThighL, 0, (MeReal)0.94, (MeReal)0.1, 0, -1, 0, (MeReal)1.0, (MeReal)0.5},
    {BallmanTorso, BallmanThighR, 0, (MeReal)0.94, -(MeReal)0.1, 0, -1, 0, (MeReal)1.0, (MeReal)0.5},
    {BallmanThighL, BallmanCalfL, 0, (MeReal)0.49, (MeReal)0.1, 0, -1, 0, (MeReal)1.0, (MeReal)0.3},
    {BallmanThighR, BallmanCalfR, 0, (MeReal)0.49, -(MeReal)0.1, 0, -1, 0, (MeReal)1.0, (MeReal)0.3},
};

/* The starting pose: the standing doll turned by kLean about z (tipping
 * forwards, towards +x and the stairs), then moved by kPlace; with
 * kStartVelocity it steps off the landing. */
static const MeReal kLean = (MeReal)0.35;
static const MeReal kPlace[3] = {-(MeReal)0.55, (MeReal)1.5, 0};
static const MeReal kStartVelocity[3] = {(MeReal)1.2, 0, 0};

/* ---- the staircase: a landing 1.5 m high and five steps down along +x */

static const MeReal kRise = (MeReal)0.25, kTread = (MeReal)0.5, kStairWidth = 3, kLandingLength = 2;

/* ---- the boxes: rows of 3, 2, 1 across z, at x = kBoxX on the floor */

static const MeReal kBoxX = (MeReal)5.0, kBoxSide = (MeReal)0.5, kBoxMass = 6;

/* Rotation about z by angle a, as body axes (rows) in world. */
static void LeanRows(MeReal a, MeMatrix3 R) {
  MeReal c = MeCos(a), s = MeSin(a);
  memset(R, 0, sizeof(MeMatrix3));
  /* turning +y towards +x: x' = c x + s y, y' = -s x + c y */
  R[0][0] = c, R[0][1] = -s;
  R[1][0] = s, R[1][1] = c;
  R[2][2] = 1;
}

/* out = R^T-free: rows are the body axes, so a body-frame vector v goes to
 * world as sum v[i] R[i]. */
static void ToWorld(const MeMatrix3 R, const MeReal v[3], MeReal out[3]) {
  int k;
  for (k = 0; k < 3; ++k) out[k] = v[0] * R[0][k] + v[1] * R[1][k] + v[2] * R[2][k];
}

static void Posed(const MeReal standing[3], MeReal out[3]) {
  MeMatrix3 L;
  LeanRows(kLean, L);
  ToWorld(L, standing, out);
  out[0] += kPlace[0], out[1] += kPlace[1], out[2] += kPlace[2];
}

static void BoxStart(int i, MeReal out[3]) {
  /* row 0: z = -0.6, 0, 0.6; row 1: -0.3, 0.3; row 2: 0 */
  static const int row[BALLMAN_BOXES] = {0, 0, 0, 1, 1, 2};
  static const MeReal z[BALLMAN_BOXES] = {-(MeReal)0.6, 0, (MeReal)0.6, -(MeReal)0.3, (MeReal)0.3, 0};
  out[0] = kBoxX;
  out[1] = kBoxSide * ((MeReal)row[i] + (MeReal)0.5);
  out[2] = z[i];
}

static void StartPose(Ballman *b) {
  MeMatrix3 L;
  int i;
  LeanRows(kLean, L);
  for (i = 0; i < BALLMAN_PARTS; ++i) {
    MdtBodyID body = McdModelGetBody(b->part[i]);
    const MeReal standing[3] = {kParts[i].x, kParts[i].y, kParts[i].z};
    MeReal at[3];
    MeMatrix3 R, A;
    int r;
    /* Capsules lie along their local z: legs turn z onto y. */
    memset(A, 0, sizeof A);
    if (kParts[i].shape == BallmanCapsule && kParts[i].axis == 1) {
      A[0][0] = 1, A[1][2] = -1, A[2][1] = 1;
    } else {
      A[0][0] = A[1][1] = A[2][2] = 1;
    }
    for (r = 0; r < 3; ++r) ToWorld(L, A[r], R[r]);
    Posed(standing, at);
    MdtBodySetPosition(body, at[0], at[1], at[2]);
    MdtBodySetOrientation(body, R);
    MdtBodySetLinearVelocity(body, kStartVelocity[0], kStartVelocity[1], kStartVelocity[2]);
    MdtBodySetAngularVelocity(body, 0, 0, 0);
    MdtBodyEnable(body);
  }
  for (i = 0; i < BALLMAN_BOXES; ++i) {
    MdtBodyID body = McdModelGetBody(b->box[i]);
    MeReal at[3];
    BoxStart(i, at);
    MdtBodySetPosition(body, at[0], at[1], at[2]);
    MdtBodySetQuaternion(body, 1, 0, 0, 0);
    MdtBodySetLinearVelocity(body, 0, 0, 0);
    MdtBodySetAngularVelocity(body, 0, 0, 0);
    MdtBodyEnable(body);
  }
  b->propelSteps = 0;
}

static McdModelID Body(Ballman *b, McdGeometryID g, MeReal mass, MstMaterialID m) {
  McdModelID model = MstModelAndBodyCreate(b->universe, g, mass / McdGeometryGetVolume(g));
  McdModelSetMaterial(model, m);
  return model;
}

static void DisablePair(Ballman *b, McdModelID m1, McdModelID m2) {
  McdSpaceID space = b->universe->space;
  const int open = !McdSpaceIsChanging(space);
  if (open) McdSpaceBeginChanges(space);
  McdSpaceDisablePair(m1, m2);
  if (open) McdSpaceEndChanges(space);
}

Ballman *BallmanCreate(void) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  Ballman *b = (Ballman *)calloc(1, sizeof *b);
  McdFrameworkID fw;
  int i, j;
  if (!b) return NULL;
  sizes.dynamicBodiesMaxCount = BALLMAN_PARTS + BALLMAN_BOXES;
  sizes.collisionModelsMaxCount = BALLMAN_PARTS + BALLMAN_BOXES + BALLMAN_STEPS + 1;
  sizes.collisionPairsMaxCount = 400;
  sizes.dynamicConstraintsMaxCount = 400;
  b->universe = MstUniverseCreate(&sizes);
  if (!b->universe) {
    free(b);
    return NULL;
  }
  fw = b->universe->frame;
  MdtWorldSetGravity(b->universe->world, 0, -(MeReal)9.81, 0);
  /* One world step per frame. The doll's limbs whip round at 20-25 rad/s
     * when it lands on the stairs face first (the sphere of a head rolls on
     * the step), and a joint linearised over a 1/60 s step lets its two
     * halves drift apart by centimetres at that rate; the joint projection
     * (MdtWorldSetJointProjection) closes them after every step. */
  MdtWorldSetJointProjection(b->universe->world, kBallmanProjection);

  b->dollMaterial = MstBridgeGetNewMaterial(b->universe->bridge);
  b->stairMaterial = MstBridgeGetNewMaterial(b->universe->bridge);
  b->boxMaterial = MstBridgeGetNewMaterial(b->universe->bridge);

  /* The floor: McdPlane's normal is its local z; turn it onto world y. */
  MeMatrix4TMMakeIdentity(b->groundTM);
  b->groundTM[1][1] = 0, b->groundTM[1][2] = -1;
  b->groundTM[2][1] = 1, b->groundTM[2][2] = 0;
  b->ground = MstFixedModelCreate(b->universe, McdPlaneCreate(fw), b->groundTM);
  McdModelSetMaterial(b->ground, b->stairMaterial);

  /* The stairs: fixed boxes standing on the floor, the landing first. */
  for (i = 0; i < BALLMAN_STEPS; ++i) {
    MeReal x0 = i == 0 ? -kLandingLength : kTread * (MeReal)(i - 1), x1 = kTread * (MeReal)i;
    MeReal top = kRise * (MeReal)(BALLMAN_STEPS - i);
    b->stairSize[i][0] = x1 - x0, b->stairSize[i][1] = top, b->stairSize[i][2] = kStairWidth;
    MeMatrix4TMMakeIdentity(b->stairTM[i]);
    MeMatrix4TMSetPosition(b->stairTM[i], (x0 + x1) / 2, top / 2, 0);
    b->stair[i] = MstFixedModelCreate(b->universe, McdBoxCreate(fw, x1 - x0, top, kStairWidth), b->stairTM[i]);
    McdModelSetMaterial(b->stair[i], b->stairMaterial);
  }

  /* The rag doll. */
  for (i = 0; i < BALLMAN_PARTS; ++i) {
    const PartDef *p = &kParts[i];
    McdGeometryID g = p->shape == BallmanBox      ? McdBoxCreate(fw, p->a, p->b, p->c)
                      : p->shape == BallmanSphere ? McdSphereCreate(fw, p->a)
                                                  : McdSphylCreate(fw, p->a, p->b);
    b->partShape[i].shape = p->shape;
    b->partShape[i].a = p->a, b->partShape[i].b = p->b, b->partShape[i].c = p->c;
    b->part[i] = Body(b, g, p->mass, b->dollMaterial);
  }
  /* Its parts do not collide with one another; the joint limits keep the
     * limbs apart. */
  for (i = 0; i < BALLMAN_PARTS; ++i)
    for (j = 0; j < i; ++j) DisablePair(b, b->part[i], b->part[j]);

  /* The boxes: one geometry for all six. */
  b->boxSide = kBoxSide;
  {
    McdGeometryID g = McdBoxCreate(fw, kBoxSide, kBoxSide, kBoxSide);
    for (i = 0; i < BALLMAN_BOXES; ++i) b->box[i] = Body(b, g, kBoxMass, b->boxMaterial);
  }

  StartPose(b);

  /* Nine limited ball-and-socket joints, set up in the starting pose. */
  for (i = 0; i < BALLMAN_JOINTS; ++i) {
    const JointDef *d = &kJoints[i];
    const MeReal standing[3] = {d->x, d->y, d->z}, axis[3] = {d->ax, d->ay, d->az};
    const MeReal across[3] = {1, 0, 0}; /* x (forwards) is across every limb axis here */
    MeReal at[3], a[3], o[3];
    MeMatrix3 L;
    LeanRows(kLean, L);
    Posed(standing, at);
    ToWorld(L, axis, a);
    ToWorld(L, across, o);
    b->joint[i] = MdtSkeletalCreate(b->universe->world);
    MdtSkeletalSetBodies(b->joint[i], McdModelGetBody(b->part[d->parent]), McdModelGetBody(b->part[d->child]));
    MdtSkeletalSetPosition(b->joint[i], at[0], at[1], at[2]);
    MdtSkeletalSetAxes(b->joint[i], a[0], a[1], a[2], o[0], o[1], o[2]);
    MdtSkeletalSetConePrimaryLimitAngle(b->joint[i], d->cone);
    MdtSkeletalSetConeSecondaryLimitAngle(b->joint[i], d->cone);
    MdtSkeletalSetTwistLimitAngle(b->joint[i], d->twist);
    MdtSkeletalEnable(b->joint[i]);
  }

  BallmanSetHighQualityFriction(b, 0);
  return b;
}

void BallmanDestroy(Ballman *b) {
  if (!b) return;
  MstUniverseDestroy(b->universe);
  free(b);
}

void BallmanReset(Ballman *b) { StartPose(b); }

/* The contact parameters of one pair of materials. `mu` is the Coulomb
 * coefficient of the high-quality model. */
static void SetPair(Ballman *b, MstMaterialID m1, MstMaterialID m2, MeReal mu) {
  MdtContactParamsID p = MstBridgeGetContactParams(b->universe->bridge, m1, m2);
  MdtContactParamsSetType(p, MdtContactTypeFriction2D);
  MdtContactParamsSetRestitution(p, 0);
  if (b->highQuality) {
    MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoefficient(p, mu);
    MdtContactParamsSetSlip(p, 0);
    MdtContactParamsSetMaxAdhesiveForce(p, 0);
  } else {
    /* The guide's low-cost material: viscous friction (an unbounded
         * friction force, the sliding given by slip) and adhesion. */
    MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelBox);
    MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelBox);
    MdtContactParamsSetFriction(p, MEINFINITY);
    MdtContactParamsSetSlip(p, kBallmanViscosity);
    MdtContactParamsSetMaxAdhesiveForce(p, MEINFINITY);
  }
}

void BallmanSetHighQualityFriction(Ballman *b, MeBool on) {
  b->highQuality = on ? 1 : 0;
  SetPair(b, b->dollMaterial, b->stairMaterial, (MeReal)0.8);
  SetPair(b, b->dollMaterial, b->boxMaterial, (MeReal)0.6);
  SetPair(b, b->boxMaterial, b->stairMaterial, (MeReal)0.6);
  SetPair(b, b->boxMaterial, b->boxMaterial, (MeReal)0.5);
}

void BallmanPropel(Ballman *b) {
  b->propelSteps = (int)(kBallmanPropelTime / kBallmanStep + (MeReal)0.5);
}

void BallmanCollide(Ballman *b) {
  /* Each model's box grown by how far it can move in the step (a limb
     * whipping round, the doll pushed at the boxes), so that its contacts
     * are found before it touches. */
  MstUniversePrepareStep(b->universe, kBallmanStep);
  McdSpaceUpdateAll(b->universe->space);
  MstBridgeUpdateContacts(b->universe->bridge, b->universe->space, b->universe->world);
}

/* The push: every part accelerated alike (so the push itself strains no
 * joint), horizontally towards the stack and a little upwards. */
static void Push(Ballman *b) {
  static const MeReal kAlong = 12, kUp = 12;
  MeVector3 torso;
  MeReal dx, dz, len;
  int i;
  BallmanTorsoPosition(b, torso);
  dx = kBoxX - torso[0], dz = 0 - torso[2];
  len = MeSqrt(dx * dx + dz * dz);
  if (len < (MeReal)1e-3) dx = 1, dz = 0, len = 1;
  for (i = 0; i < BALLMAN_PARTS; ++i) {
    MdtBodyID body = McdModelGetBody(b->part[i]);
    MeReal m = MdtBodyGetMass(body);
    MdtBodyEnable(body);
    MdtBodyAddForce(body, m * kAlong * dx / len, m * kUp, m * kAlong * dz / len);
  }
}

void BallmanDynamics(Ballman *b) {
  if (b->propelSteps > 0) {
    Push(b);
    --b->propelSteps;
  }
  MdtWorldStep(b->universe->world, kBallmanStep);
}

void BallmanStep(Ballman *b) {
  BallmanCollide(b);
  BallmanDynamics(b);
}

MeReal BallmanJointError(const Ballman *b) {
  MeReal worst = 0;
  int i;
  for (i = 0; i < BALLMAN_JOINTS; ++i) {
    const MeReal d = TutorialJointGap(MdtSkeletalQuaConstraint(b->joint[i]));
    if (d > worst) worst = d;
  }
  return worst;
}

void BallmanStepStats(const Ballman *b, MdtWorldStepStats *stats) { MdtWorldGetStepStats(b->universe->world, stats); }

void BallmanTorsoPosition(const Ballman *b, MeVector3 x) {
  MdtBodyGetPosition(McdModelGetBody(b->part[BallmanTorso]), x);
}
