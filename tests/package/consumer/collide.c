/* collide.c: a C program that collides through an installed Karma, as a
 * user would write it: a sphere of radius 0.5 m dropped from 2 m onto a
 * plane (Mst: McdPlane fixed model, McdSphere model with a body), 2 s at
 * 60 steps/s. At rest the sphere's centre must be at the radius above the
 * plane (|y - 0.5| < 0.02 m) and its speed small (< 0.05 m/s).
 *
 * With -trajectory FILE it writes every 10th frame (and the last) as a
 * trajectory for karma_add_golden_test, naming the platform backend the
 * world ran on (-platform NAME picks it, as the golden driver passes); with
 * -drop H it starts from H m (the consumer test's "changed program"). Both
 * include styles are used. */
#include "Mst.h"
#include <karma/golden/KarmaTrajectory.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STEPS 120

static void WriteFrame(KarmaTrajectoryWriter *w, long frame, MeReal h, MdtBodyID body) {
  MeVector3 p, v, omega;
  MeVector4 q;
  MdtBodyGetPosition(body, p);
  MdtBodyGetQuaternion(body, q);
  MdtBodyGetLinearVelocity(body, v);
  MdtBodyGetAngularVelocity(body, omega);
  KarmaTrajectoryWriterBeginFrame(w, frame, h * (MeReal)frame);
  KarmaTrajectoryWriterAddBody(w, p, q, v, omega);
  KarmaTrajectoryWriterEndFrame(w);
}

int main(int argc, char **argv) {
  const MeReal h = (MeReal)1 / 60, radius = (MeReal)0.5;
  MeReal drop = 2;
  const char *trajectory = NULL;
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  MstUniverseID universe;
  MeMatrix4 groundTM;
  McdModelID ball;
  MdtBodyID body;
  KarmaTrajectoryWriter *writer;
  KarmaTrajectoryInfo info = {"collide", "main", NULL, "every 10th frame and the last", 0, 1};
  MeVector3 p, v;
  char hash[KARMA_GOLDEN_HASH_TEXT_SIZE];
  long frame;
  int i;

  for (i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "-trajectory"))
      trajectory = argv[i + 1];
    else if (!strcmp(argv[i], "-drop"))
      drop = (MeReal)atof(argv[i + 1]);
    else if (!strcmp(argv[i], "-platform"))
      MdtPlatformSetDefault(argv[i + 1]); /* for the worlds created from here on */
  }
  sizes.dynamicBodiesMaxCount = 1;
  sizes.collisionModelsMaxCount = 2;
  universe = MstUniverseCreate(&sizes);
  if (!universe) return 1;
  MdtWorldSetGravity(universe->world, 0, (MeReal)-9.81, 0);

  /* McdPlane's normal is its local z; turned onto world y. */
  MeMatrix4TMMakeIdentity(groundTM);
  groundTM[1][1] = 0, groundTM[1][2] = -1;
  groundTM[2][1] = 1, groundTM[2][2] = 0;
  MstFixedModelCreate(universe, McdPlaneCreate(universe->frame), groundTM);
  ball = MstModelAndBodyCreate(universe, McdSphereCreate(universe->frame, radius), 1);
  body = McdModelGetBody(ball);
  MdtBodySetPosition(body, 0, drop, 0);

  info.timeStep = h;
  info.backend = MdtWorldGetPlatformName(universe->world);
  writer = KarmaTrajectoryWriterCreate(trajectory, &info);
  for (frame = 0; frame <= STEPS; ++frame) {
    if (frame % 10 == 0) WriteFrame(writer, frame, h, body);
    if (frame < STEPS) MstUniverseStep(universe, h);
  }
  KarmaGoldenFormatHash(KarmaTrajectoryWriterHash(writer), hash);
  if (!KarmaTrajectoryWriterDestroy(writer)) return 2;

  MdtBodyGetPosition(body, p);
  MdtBodyGetLinearVelocity(body, v);
  MstUniverseDestroy(universe);
  printf("state hash: %s\n", hash);
  if (fabs((double)p[1] - (double)radius) > 0.02 || sqrt((double)MeVector3Dot(v, v)) > 0.05) {
    printf("collide: the sphere is not at rest on the plane: y = %g, v = (%g, %g, %g)\n", (double)p[1], (double)v[0],
           (double)v[1], (double)v[2]);
    return 3;
  }
  printf("karma consumer ok (C collide, MeReal is %u bytes): the sphere rests at y = %.4f m\n",
         (unsigned)sizeof(MeReal), (double)p[1]);
  return 0;
}
