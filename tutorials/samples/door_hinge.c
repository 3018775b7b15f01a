/* door_hinge: the guide's door hinged to the world. A 0.8 x 2 x 0.04 m door
 * of 2 kg, kicked at 5 rad/s about the vertical, swings on a hinge along
 * its left edge while angular damping 0.2 slows it down. Gravity pulls it
 * down; the hinge holds it up. */
#include "sample.h"

#include <stdio.h>

static MdtHingeID hinge_;
static int steps_;

static void Report(void) {
  if (++steps_ % 60 == 0)
    printf("t = %.0f s: door angle %+.3f rad, rate %+.3f rad/s\n", steps_ / 60.0, (double)MdtHingeGetAngle(hinge_),
           (double)MdtHingeGetAngleRate(hinge_));
}

int main(int argc, const char *argv[]) {
  const float wood[4] = {0.75f, 0.5f, 0.25f, 1}, grey[4] = {0.5f, 0.5f, 0.55f, 1};
  const MeReal doorSize[3] = {(MeReal)0.8, (MeReal)2.0, (MeReal)0.04};
  static MeMatrix4 postTM;
  RRender *rc = SampleOpen(argc, argv, "door hinge: a kicked door swings on its hinge");
  MdtWorldID world = SampleWorld(1, 1);
  MdtBodyID door;
  MeVector3 doorPosition;
  MeMatrix3 I;
  const MeReal m = 2;

  MdtWorldSetGravity(world, 0, (MeReal)-9.81, 0);
  door = MdtBodyCreate(world);
  MdtBodySetPosition(door, 0, 0, -7);
  MdtBodySetMass(door, m);
  SampleBoxInertia(m, doorSize, I);
  MdtBodySetInertiaTensor(door, I);
  /* The kick: 5 rad/s about y; damping slows the swing. */
  MdtBodySetAngularVelocity(door, 0, 5, 0);
  MdtBodySetAngularVelocityDamping(door, (MeReal)0.2);
  MdtBodyEnable(door);

  /* Bodies first, then the position (the joint works out each body's
   * attachment from it): the hinge runs up the door's left edge. */
  hinge_ = MdtHingeCreate(world);
  MdtHingeSetBodies(hinge_, door, 0);
  MdtBodyGetPosition(door, doorPosition);
  MdtHingeSetPosition(hinge_, doorPosition[0] - doorSize[0] / 2, doorPosition[1], doorPosition[2]);
  MdtHingeSetAxis(hinge_, 0, 1, 0);
  MdtHingeEnable(hinge_);

  RGraphicBoxCreate(rc, doorSize[0], doorSize[1], doorSize[2], wood, MdtBodyGetTransformPtr(door));
  MeMatrix4TMMakeIdentity(postTM);
  MeMatrix4TMSetPosition(postTM, doorPosition[0] - doorSize[0] / 2 - (MeReal)0.05, 0, -7);
  RGraphicBoxCreate(rc, (MeReal)0.1, (MeReal)2.4, (MeReal)0.1, grey, postTM);
  SampleGround(rc, 20, (MeReal)-1.2);

  SampleCamera(rc, 0, 0, -7, (MeReal)4.5, (MeReal)0.4, (MeReal)0.3);
  SampleRecordBody(door);
  SampleRun(argc, argv, "door_hinge", (MeReal)1 / 60, NULL, Report);
  return 0;
}
