/* cone_universal: the guide's cone-limited universal joint. A body 4 m
 * from a universal joint fixed to the world falls under gravity; a cone
 * limit of half-angle 60 degrees about the world x axis (the body's
 * starting direction) stops it on the side of the cone, drawn here as a
 * wire frame. */
#include "sample.h"

#include <stdio.h>

static MdtBodyID body_;
static MdtConeLimitID cone_;
static RNativeLine *rod_;
static int steps_;

static void Follow(void) {
  AcmeReal joint[3] = {-2, 0, 0}, end[3];
  MeVector3 p;
  MdtBodyGetPosition(body_, p);
  end[0] = p[0], end[1] = p[1], end[2] = p[2];
  RNLineMoveEnds(rod_, joint, end);
  if (++steps_ % 30 == 0)
    printf("t = %.1f s: angle from the cone axis %.1f deg (limit 60)\n", steps_ / 60.0,
           (double)MdtConeLimitGetAngle(cone_) * 180 / ME_PI);
}

int main(int argc, const char *argv[]) {
  const float orange[4] = {0.95f, 0.55f, 0.1f, 1}, cyan[4] = {0.3f, 0.8f, 0.9f, 1};
  const AcmeReal white[4] = {1, 1, 1, 1};
  static MeMatrix4 coneTM;
  MeMatrix3 R;
  AcmeReal a[3] = {-2, 0, 0}, b[3] = {2, 0, 0};
  RRender *rc = SampleOpen(argc, argv, "cone-limited universal joint: falls to the 60 deg cone");
  MdtWorldID world = SampleWorld(1, 2);
  MdtUniversalID univ;

  MdtWorldSetGravity(world, 0, (MeReal)-9.81, 0);
  body_ = MdtBodyCreate(world);
  MdtBodySetPosition(body_, 2, 0, 0);
  MdtBodyEnable(body_);

  /* The joint 4 m from the body, its axes z (on the body) and y (on the
   * world). */
  univ = MdtUniversalCreate(world);
  MdtUniversalSetBodies(univ, body_, 0);
  MdtUniversalSetPosition(univ, -2, 0, 0);
  MdtUniversalSetAxis(univ, 0, 0, 0, 1);
  MdtUniversalSetAxis(univ, 1, 0, 1, 0);
  MdtUniversalEnable(univ);

  /* The cone axis is each body's x axis as placed (the world x axis). */
  cone_ = MdtConeLimitCreate(world);
  MdtConeLimitSetBodies(cone_, body_, 0);
  MdtConeLimitSetConeHalfAngle(cone_, (MeReal)(ME_PI / 3.));
  MdtConeLimitEnable(cone_);

  RGraphicSphereCreate(rc, (MeReal)0.4, orange, MdtBodyGetTransformPtr(body_));
  rod_ = RNLineCreate(rc, a, b, white, NULL);
  /* The cone: apex at the joint, opening along +x, 2 m long. The
   * graphic's axis is z, apex up: turn z onto -x. */
  MeMatrix3MakeRotationY(R, (MeReal)(-ME_PI / 2));
  MeMatrix4TMMakeFromRotationAndPosition(coneTM, R, -2, 0, 0);
  RGraphicSetWireframe(RGraphicConeCreate(rc, 2 * MeSqrt(3), 0, 2, cyan, coneTM), 1);
  SampleGround(rc, 16, (MeReal)-5.5);

  SampleCamera(rc, 0, (MeReal)-1.5, 0, 12, (MeReal)0.1, (MeReal)0.25);
  SampleRecordBody(body_);
  SampleRun(argc, argv, "cone_universal", (MeReal)1 / 60, NULL, Follow);
  return 0;
}
