/* pendulum_scene.c: an example of a user's scene for karma-tradeoff
 * (karma/KarmaTradeoffScene.h): a double pendulum of two 1 kg spheres on
 * hinges, released level, no collision (an MdtWorld alone). Its check:
 * the lower bob stays within the pendulum's reach of the pivot (2 m plus
 * 5 cm), so a run that comes apart fails.
 *
 *   cc -shared -fPIC -I<prefix>/include -I<prefix>/include/karma \
 *      pendulum_scene.c -o libpendulum.so
 *   karma-tradeoff --scene ./libpendulum.so --sweep "solver=exact,iterative:10 h=1/60..1/240"
 *
 * The library links no Karma library: its calls resolve against the
 * karma-tradeoff that opens it. */
#include <stdlib.h>

#include "KarmaTradeoffScene.h"

typedef struct Pendulum {
  MdtWorldID world;
  MdtBodyID bodies[2];
  MdtConstraintID joints[2];
} Pendulum;

static int Check(void *user) {
  const Pendulum *p = (const Pendulum *)user;
  MeVector3 x;
  MdtBodyGetPosition(p->bodies[1], x);
  return MeSqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) < (MeReal)2.05;
}

static void Destroy(void *user) {
  Pendulum *p = (Pendulum *)user;
  MdtWorldDestroy(p->world);
  free(p);
}

/* A 1 kg sphere of radius 0.1 m at (x, 0, 0). */
static MdtBodyID Bob(MdtWorldID world, MeReal x) {
  MeMatrix3 I = {{(MeReal)0.004, 0, 0}, {0, (MeReal)0.004, 0}, {0, 0, (MeReal)0.004}};
  MdtBodyID b = MdtBodyCreate(world);
  MdtBodySetMass(b, 1);
  MdtBodySetInertiaTensor(b, I);
  MdtBodySetPosition(b, x, 0, 0);
  MdtBodyEnable(b);
  return b;
}

/* A hinge about z at (x, 0, 0) between a and b (NULL: the world). */
static MdtConstraintID Hinge(MdtWorldID world, MdtBodyID a, MdtBodyID b, MeReal x) {
  MdtHingeID h = MdtHingeCreate(world);
  MdtHingeSetBodies(h, a, b);
  MdtHingeSetPosition(h, x, 0, 0);
  MdtHingeSetAxis(h, 0, 0, 1);
  MdtHingeEnable(h);
  return MdtHingeQuaConstraint(h);
}

int KarmaTradeoffBuildScene(KarmaTradeoffScene *scene) {
  Pendulum *p = (Pendulum *)calloc(1, sizeof *p);
  if (!p) return 0;
  p->world = MdtWorldCreate(2, 2, 1, 1);
  if (!p->world) {
    free(p);
    return 0;
  }
  MdtWorldSetGravity(p->world, 0, (MeReal)-9.81, 0);
  MdtWorldSetAutoDisable(p->world, 0);
  p->bodies[0] = Bob(p->world, 1);
  p->bodies[1] = Bob(p->world, 2);
  p->joints[0] = Hinge(p->world, p->bodies[0], NULL, 0);
  p->joints[1] = Hinge(p->world, p->bodies[1], p->bodies[0], 1);
  scene->version = KARMA_TRADEOFF_SCENE_VERSION;
  scene->realSize = (int)sizeof(MeReal);
  scene->name = "pendulum";
  scene->world = p->world;
  scene->seconds = 2;
  scene->bodies = p->bodies;
  scene->bodyCount = 2;
  scene->joints = p->joints;
  scene->jointCount = 2;
  scene->user = p;
  scene->check = Check;
  scene->destroy = Destroy;
  return 1;
}
