/* basic_steps: the guide's first dynamics program ("The Basic Steps
 * Involved in Creating a Karma Dynamics Program"): a world, one body drawn
 * as a sphere of radius 1.2, gravity of equal strength along -x and -y, and
 * a tick that steps the world by 0.01 s. No collision: the body just
 * accelerates along the diagonal. The checkerboard below it is only there
 * to show the motion. */
#include "sample.h"

int main(int argc, const char *argv[]) {
  const float red[4] = {1, 0, 0, 1};
  RRender *rc = SampleOpen(argc, argv, "basic steps: one body under gravity (-0.3, -0.3, 0)");
  /* Room for one body and no constraints. */
  MdtWorldID world = SampleWorld(1, 0);
  MdtBodyID sphere;

  MdtWorldSetGravity(world, (MeReal)-0.3, (MeReal)-0.3, 0);
  /* The body starts at the origin, at rest; enabling it lets the world move it. */
  sphere = MdtBodyCreate(world);
  MdtBodyEnable(sphere);
  /* The graphic follows the body's transform: nothing to copy each frame. */
  RGraphicSphereCreate(rc, (MeReal)1.2, red, MdtBodyGetTransformPtr(sphere));
  SampleGround(rc, 16, (MeReal)-4);

  SampleCamera(rc, -1, -1, 0, 12, (MeReal)0.3, (MeReal)0.35);
  SampleRecordBody(sphere);
  SampleRun(argc, argv, "basic_steps", (MeReal)0.01, NULL, NULL);
  return 0;
}
