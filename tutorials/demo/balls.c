#include "balls.h"

static void InitBall(DemoBall *b, MeReal radius, MeReal x, MeReal y, MeReal vx, MeReal vy, MeReal wx, MeReal wy,
                     MeReal wz, unsigned char r, unsigned char g, unsigned char bl) {
  b->radius = radius;
  b->position[0] = x, b->position[1] = y, b->position[2] = 0;
  b->quaternion[0] = 1, b->quaternion[1] = 0, b->quaternion[2] = 0, b->quaternion[3] = 0;
  b->linearVelocity[0] = vx, b->linearVelocity[1] = vy, b->linearVelocity[2] = 0;
  b->angularVelocity[0] = wx, b->angularVelocity[1] = wy, b->angularVelocity[2] = wz;
  b->colour[0] = r, b->colour[1] = g, b->colour[2] = bl;
}

void DemoWorldInit(DemoWorld *world) {
  world->gravity = (MeReal)9.81;
  world->restitution = (MeReal)0.7;
  world->friction = (MeReal)0.9;
  /* A slow high lob, a fast flat throw, and a small ball spinning about a tilted axis. */
  InitBall(&world->balls[0], (MeReal)0.25, (MeReal)0.5, (MeReal)1.0, (MeReal)1.5, (MeReal)6.0, 0, 0, (MeReal)-4.0, 220,
           60, 50);
  InitBall(&world->balls[1], (MeReal)0.35, (MeReal)0.5, (MeReal)0.35, (MeReal)2.5, (MeReal)3.0, 0, 0, (MeReal)-7.0, 50,
           110, 210);
  InitBall(&world->balls[2], (MeReal)0.2, (MeReal)1.0, (MeReal)2.0, (MeReal)0.8, (MeReal)7.0, (MeReal)3.0, 0,
           (MeReal)4.0, 240, 190, 40);
}

/* q += (h/2) (0, w) q; |q| = 1 afterwards. */
static void IntegrateOrientation(MeReal *q, const MeReal *w, MeReal h) {
  const MeReal k = h * (MeReal)0.5;
  const MeReal dw = -(w[0] * q[1] + w[1] * q[2] + w[2] * q[3]);
  const MeReal dx = w[0] * q[0] + (w[1] * q[3] - w[2] * q[2]);
  const MeReal dy = w[1] * q[0] + (w[2] * q[1] - w[0] * q[3]);
  const MeReal dz = w[2] * q[0] + (w[0] * q[2] - w[1] * q[1]);
  MeReal n;
  q[0] += k * dw, q[1] += k * dx, q[2] += k * dy, q[3] += k * dz;
  n = MeRecip(MeSqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]));
  q[0] *= n, q[1] *= n, q[2] *= n, q[3] *= n;
}

static void StepBall(const DemoWorld *world, DemoBall *b, MeReal h) {
  int i;
  b->linearVelocity[1] -= world->gravity * h;
  for (i = 0; i < 3; ++i) b->position[i] += b->linearVelocity[i] * h;
  if (b->position[1] < b->radius) {
    b->position[1] = b->radius;
    if (b->linearVelocity[1] < 0) {
      b->linearVelocity[1] = -world->restitution * b->linearVelocity[1];
      b->linearVelocity[0] *= world->friction;
      /* A bounce lower than one step of gravity is a ball at rest. */
      if (b->linearVelocity[1] < world->gravity * h) b->linearVelocity[1] = 0;
    }
  }
  IntegrateOrientation(b->quaternion, b->angularVelocity, h);
}

void DemoWorldStep(DemoWorld *world, MeReal h) {
  int i;
  for (i = 0; i < DEMO_BALL_COUNT; ++i) StepBall(world, &world->balls[i], h);
}
