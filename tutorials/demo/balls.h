/* balls.h: the demo's tiny simulation, which needs no engine.
 *
 * Three balls are launched under gravity and bounce on the ground plane y = 0
 * (y is up). Each step of length h is semi-implicit Euler in MeReal:
 *   v += g h;  x += v h;
 *   if the ball's bottom is below the ground: put it on the ground, reverse and
 *   scale the normal velocity by the restitution, scale the horizontal velocity
 *   by the ground friction factor, and stop small bounces;
 *   q += (h/2) (0, w) q, then renormalise (w is a constant world-frame spin).
 * Every operation is a plain IEEE operation in a fixed order, so a run is
 * bit-identical on every build of the same precision. */
#ifndef KARMA_DEMO_BALLS_H
#define KARMA_DEMO_BALLS_H

#include "MePrecision.h"

#define DEMO_BALL_COUNT 3

typedef struct DemoBall {
  MeVector3 position;        /* centre, metres */
  MeVector4 quaternion;      /* (w, x, y, z), body to world */
  MeVector3 linearVelocity;  /* m/s */
  MeVector3 angularVelocity; /* rad/s, world frame, constant */
  MeReal radius;
  unsigned char colour[3];
} DemoBall;

typedef struct DemoWorld {
  DemoBall balls[DEMO_BALL_COUNT];
  MeReal gravity;     /* m/s^2 along -y */
  MeReal restitution; /* normal speed kept by a bounce */
  MeReal friction;    /* horizontal speed kept by a bounce */
} DemoWorld;

void DemoWorldInit(DemoWorld *world);
void DemoWorldStep(DemoWorld *world, MeReal h);

#endif
