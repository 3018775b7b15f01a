/* wall_ball: the guide's per-pair callback. Two balls roll at a wall; the
 * callback on the (wall, ball) pair of materials lets a ball through when
 * it is faster than 8 m/s, halving its speed (the wall's resistance), and
 * keeps the contacts otherwise, so the slow ball bounces back. A ball that
 * has started through the wall is let through until it is out on the other
 * side (the side it came from, in its body's user data), or it would be
 * stopped half-way. Contacts come a little before the touch (they are
 * reported as far apart as the ball can close in a step), so "out" means
 * past the wall on the far side, not merely clear of it. */
#include "sample.h"

#include <stdio.h>

#define BALLS 2
#define THRESH ((MeReal)8)

static const MeReal wallHalf = (MeReal)0.1, radius = (MeReal)0.3;
static MstMaterialID mat_Wall, mat_Ball;
static MdtBodyID ball_[BALLS];
static int passing_[BALLS];
static int steps_;

static MeBool MEAPI WallCollisionCB(McdIntersectResult *c, MdtContactGroupID cg) {
  MeVector3 vel;
  MdtBodyID ball;
  int *passing;
  (void)cg;
  /* First find which of the models is the ball. */
  if (McdModelGetMaterial(c->pair->model1) == mat_Ball)
    ball = McdModelGetBody(c->pair->model1);
  else
    ball = McdModelGetBody(c->pair->model2);
  passing = (int *)MdtBodyGetUserData(ball);
  if (*passing) return 0; /* on its way through: no contacts */
  MdtBodyGetLinearVelocity(ball, vel);
  if (MeVector3Magnitude(vel) > THRESH) {
    /* Fast enough to pass through: slow it down, delete the contacts. */
    MeVector3 p;
    printf("step %d: a ball hits the wall at %.2f m/s and goes through\n", steps_, (double)MeVector3Magnitude(vel));
    MeVector3Scale(vel, (MeReal)0.5);
    MdtBodySetLinearVelocity(ball, vel[0], vel[1], vel[2]);
    MdtBodyGetPosition(ball, p);
    *passing = p[0] < 0 ? -1 : 1; /* the side it comes from */
    return 0;
  }
  /* Keep the contacts: the ball bounces off (reported while it still
   * moves towards the wall). */
  {
    MeVector3 p;
    MdtBodyGetPosition(ball, p);
    if (vel[0] * p[0] < 0)
      printf("step %d: a ball hits the wall at %.2f m/s and bounces\n", steps_, (double)MeVector3Magnitude(vel));
  }
  return 1;
}

static void ClearPassing(void) {
  int i;
  ++steps_;
  for (i = 0; i < BALLS; ++i) {
    MeVector3 p;
    MdtBodyGetPosition(ball_[i], p);
    if (passing_[i] && p[0] * (MeReal)passing_[i] < 0 && MeFabs(p[0]) > wallHalf + radius) passing_[i] = 0;
  }
}

int main(int argc, const char *argv[]) {
  const float brick[4] = {0.7f, 0.3f, 0.25f, 1}, colour[BALLS][4] = {{0.2f, 0.8f, 0.3f, 1}, {0.3f, 0.5f, 0.95f, 1}};
  const MeReal speed[BALLS] = {12, 5}, laneZ[BALLS] = {-1, 1};
  static MeMatrix4 groundTM, wallTM;
  RRender *rc = SampleOpen(argc, argv, "ball and wall: faster than 8 m/s goes through");
  MstUniverseID universe = SampleUniverse(0);
  McdGeometryID ballGeometry = McdSphereCreate(universe->frame, radius);
  McdModelID wall;
  int i;

  MdtWorldSetGravity(universe->world, 0, (MeReal)-9.81, 0);
  mat_Wall = MstBridgeGetNewMaterial(universe->bridge);
  mat_Ball = MstBridgeGetNewMaterial(universe->bridge);
  MdtContactParamsSetRestitution(MstBridgeGetContactParams(universe->bridge, mat_Wall, mat_Ball), (MeReal)0.6);
  /* Set the callback between the wall and ball materials. */
  MstBridgeSetPerPairCB(universe->bridge, mat_Wall, mat_Ball, WallCollisionCB);

  MeMatrix4TMMakeIdentity(groundTM);
  groundTM[1][1] = 0, groundTM[1][2] = -1, groundTM[2][1] = 1, groundTM[2][2] = 0;
  MstFixedModelCreate(universe, McdPlaneCreate(universe->frame), groundTM);
  SampleGround(rc, 16, 0);

  MeMatrix4TMMakeIdentity(wallTM);
  MeMatrix4TMSetPosition(wallTM, 0, 1, 0);
  wall = MstFixedModelCreate(universe, McdBoxCreate(universe->frame, 2 * wallHalf, 2, 5), wallTM);
  McdModelSetMaterial(wall, mat_Wall);
  RGraphicBoxCreate(rc, 2 * wallHalf, 2, 5, brick, wallTM);

  for (i = 0; i < BALLS; ++i) {
    McdModelID m = MstModelAndBodyCreate(universe, ballGeometry, 1);
    ball_[i] = McdModelGetBody(m);
    McdModelSetMaterial(m, mat_Ball);
    MdtBodySetUserData(ball_[i], &passing_[i]);
    MdtBodySetPosition(ball_[i], -6, radius, laneZ[i]);
    MdtBodySetLinearVelocity(ball_[i], speed[i], 0, 0);
    MdtBodySetAngularVelocity(ball_[i], 0, 0, -speed[i] / radius); /* rolling */
    RGraphicSphereCreate(rc, radius, colour[i], MdtBodyGetTransformPtr(ball_[i]));
    SampleRecordBody(ball_[i]);
  }

  SampleCamera(rc, 1, 0, 0, 14, (MeReal)0.25, (MeReal)0.8);
  SampleRun(argc, argv, "wall_ball", (MeReal)1 / 60, NULL, ClearPassing);
  return 0;
}
