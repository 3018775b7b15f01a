/* spring_boxes: the guide's spring between two boxes. Two 100 kg boxes
 * float without gravity; a spring joins a point 1 m below the upper box to
 * a point 1 m above the lower one. Its natural length (4 m) is longer than
 * the 2 m between those points, so it pushes the boxes apart; with no
 * damping they oscillate about the natural length. */
#include "sample.h"

#include <stdio.h>

static MdtSpringID spring_;
static RGraphic *coil_;
static int steps_;

static void Follow(void) {
  MeVector3 p0, p1;
  AcmeReal a[3], b[3];
  MdtSpringGetPosition(spring_, p0, 0);
  MdtSpringGetPosition(spring_, p1, 1);
  a[0] = p0[0], a[1] = p0[1], a[2] = p0[2];
  b[0] = p1[0], b[1] = p1[1], b[2] = p1[2];
  RGraphicLineMoveEnds(coil_, a, b);
  if (++steps_ % 30 == 0)
    printf("t = %.1f s: spring length %.3f m (natural 4)\n", steps_ / 60.0, (double)MdtSpringGetLength(spring_));
}

int main(int argc, const char *argv[]) {
  const float red[4] = {0.85f, 0.2f, 0.2f, 1}, blue[4] = {0.2f, 0.35f, 0.85f, 1}, white[4] = {1, 1, 1, 1};
  /* An inertia tensor of the right order of magnitude for the mass. */
  const MeReal mass = (MeReal)100.0;
  MeMatrix3 boxInertia = {{mass, 0, 0}, {0, mass, 0}, {0, 0, mass}};
  MeVector3 boxPosition;
  AcmeReal a[3] = {0, 1, 0}, b[3] = {0, -1, 0};
  RRender *rc = SampleOpen(argc, argv, "spring between boxes: natural length 4 m, stiffness 10");
  MdtWorldID world = SampleWorld(2, 1);
  MdtBodyID boxOne, boxTwo;

  /* Auto-disable (on by default) would put the boxes to sleep where they
   * stop for an instant, at the ends of each swing. */
  MdtWorldSetAutoDisable(world, 0);
  boxOne = MdtBodyCreate(world);
  boxTwo = MdtBodyCreate(world);
  MdtBodySetMass(boxOne, mass);
  MdtBodySetMass(boxTwo, mass);
  MdtBodySetInertiaTensor(boxOne, boxInertia);
  MdtBodySetInertiaTensor(boxTwo, boxInertia);
  MdtBodySetLinearVelocityDamping(boxOne, 0);
  MdtBodySetLinearVelocityDamping(boxTwo, 0);
  MdtBodySetPosition(boxOne, 0, 2, 0);
  MdtBodySetPosition(boxTwo, 0, -2, 0);
  MdtBodyEnable(boxOne);
  MdtBodyEnable(boxTwo);

  spring_ = MdtSpringCreate(world);
  MdtSpringSetBodies(spring_, boxOne, boxTwo);
  /* Attach 1 m below the upper box and 1 m above the lower one. */
  MdtBodyGetPosition(boxOne, boxPosition);
  MdtSpringSetPosition(spring_, 0, boxPosition[0], boxPosition[1] - 1, boxPosition[2]);
  MdtBodyGetPosition(boxTwo, boxPosition);
  MdtSpringSetPosition(spring_, 1, boxPosition[0], boxPosition[1] + 1, boxPosition[2]);
  MdtSpringSetNaturalLength(spring_, 4);
  MdtSpringSetStiffness(spring_, 10);
  /* No damping: the spring keeps bouncing. */
  MdtSpringSetDamping(spring_, 0);
  MdtSpringEnable(spring_);

  RGraphicBoxCreate(rc, 1, 1, 1, red, MdtBodyGetTransformPtr(boxOne));
  RGraphicBoxCreate(rc, 1, 1, 1, blue, MdtBodyGetTransformPtr(boxTwo));
  coil_ = RGraphicLineCreate(rc, a, b, white, NULL);
  SampleGround(rc, 20, (MeReal)-8);

  SampleCamera(rc, 0, 0, 0, 15, (MeReal)0.5, (MeReal)0.15);
  SampleRecordBody(boxOne);
  SampleRecordBody(boxTwo);
  SampleRun(argc, argv, "spring_boxes", (MeReal)1 / 60, NULL, Follow);
  return 0;
}
