/* hinge_limit_motor: the door of door_hinge, now with hard stops at +-0.5
 * rad that do not bounce (restitution 0) and a force-limited motor: it
 * tries to reach 10 rad/s with at most 5 N m. Every 1.5 s the motor's
 * direction is reversed, so the door swings from one stop to the other. */
#include "sample.h"

#include <stdio.h>

#define REVERSE_EVERY 90 /* steps of 1/60 s */

static MdtHingeID hinge_;
static int steps_;
static MeReal direction_ = 1;

static void Drive(void) {
  MdtLimitID limit = MdtHingeGetLimit(hinge_);
  if (steps_ > 0 && steps_ % REVERSE_EVERY == 0) {
    printf("t = %.1f s: angle %+.3f rad (stop at %+.1f); motor reversed\n", steps_ / 60.0,
           (double)MdtHingeGetAngle(hinge_), 0.5 * (double)direction_);
    direction_ = -direction_;
    MdtLimitSetLimitedForceMotor(limit, 10 * direction_, 5);
  }
  ++steps_;
}

int main(int argc, const char *argv[]) {
  const float wood[4] = {0.3f, 0.55f, 0.8f, 1}, grey[4] = {0.5f, 0.5f, 0.55f, 1};
  const MeReal doorSize[3] = {(MeReal)0.8, (MeReal)2.0, (MeReal)0.04};
  static MeMatrix4 postTM;
  RRender *rc = SampleOpen(argc, argv, "hinge limit and motor: driven between stops at +-0.5 rad");
  MdtWorldID world = SampleWorld(1, 1);
  MdtBodyID door;
  MdtLimitID hingeLimit;
  MeVector3 p;
  MeMatrix3 I;
  const MeReal m = 2;

  MdtWorldSetGravity(world, 0, (MeReal)-9.81, 0);
  door = MdtBodyCreate(world);
  MdtBodySetPosition(door, 0, 0, -7);
  MdtBodySetMass(door, m);
  SampleBoxInertia(m, doorSize, I);
  MdtBodySetInertiaTensor(door, I);
  MdtBodyEnable(door);

  hinge_ = MdtHingeCreate(world);
  MdtHingeSetBodies(hinge_, door, 0);
  MdtBodyGetPosition(door, p);
  MdtHingeSetPosition(hinge_, p[0] - doorSize[0] / 2, p[1], p[2]);
  MdtHingeSetAxis(hinge_, 0, 1, 0);

  /* The stops: +-0.5 rad, as hard as the platform allows, no rebound. */
  hingeLimit = MdtHingeGetLimit(hinge_);
  MdtSingleLimitSetStop(MdtLimitGetLowerLimit(hingeLimit), (MeReal)-0.5);
  MdtSingleLimitSetStop(MdtLimitGetUpperLimit(hingeLimit), (MeReal)0.5);
  MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(hingeLimit), MEINFINITY);
  MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(hingeLimit), MEINFINITY);
  MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(hingeLimit), 0);
  MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(hingeLimit), 0);
  /* Limits start inactive; this turns them on. */
  MdtLimitActivateLimits(hingeLimit, !MdtLimitIsActive(hingeLimit));
  /* The motor: desired speed 10 rad/s, torque at most 5 N m (it turns the
   * motor on). */
  MdtLimitSetLimitedForceMotor(hingeLimit, 10, 5);
  MdtHingeEnable(hinge_);

  RGraphicBoxCreate(rc, doorSize[0], doorSize[1], doorSize[2], wood, MdtBodyGetTransformPtr(door));
  MeMatrix4TMMakeIdentity(postTM);
  MeMatrix4TMSetPosition(postTM, p[0] - doorSize[0] / 2 - (MeReal)0.05, 0, -7);
  RGraphicBoxCreate(rc, (MeReal)0.1, (MeReal)2.4, (MeReal)0.1, grey, postTM);
  SampleGround(rc, 20, (MeReal)-1.2);

  SampleCamera(rc, 0, 0, -7, (MeReal)4.5, (MeReal)0.2, (MeReal)0.8);
  SampleRecordBody(door);
  SampleRun(argc, argv, "hinge_limit_motor", (MeReal)1 / 60, Drive, NULL);
  return 0;
}
