// sleep.cpp: stage 8 of the step (step.h), auto-disable. A body is idle
// while its speed, angular speed, acceleration and angular acceleration are
// all below the world's thresholds; a partition whose bodies have all been
// idle for the alive window goes to sleep, at rest.
//
// A body in free fall accelerates at |g| whatever the world's scale, while
// one held up by contacts or joints accelerates at ~0. The acceleration
// threshold scales with the world's length scale (0.5 l: 50 m/s^2 at
// l = 100), so on its own it can exceed |g| and put a falling body to
// sleep in mid-air. A body therefore counts as idle only while its
// acceleration is also below |g| / 2: whatever the thresholds, a body
// still accelerating under gravity stays awake.
#include "step.h"

namespace karma::mdt {

namespace {

bool idle(const MdtBody *b, const MdtWorldParams &w) {
  const MeReal g = MeVector3Magnitude(w.gravity);
  const MeReal a = MeVector3Magnitude(b->acceleration);
  if (g > 0 && !(a < g / 2)) return false;
  return MeVector3Magnitude(b->velocity) < w.velocityThreshold &&
         MeVector3Magnitude(b->angularVelocity) < w.angularVelocityThreshold &&
         a < w.accelerationThreshold &&
         MeVector3Magnitude(b->angularAcceleration) < w.angularAccelerationThreshold;
}

}  // namespace

bool autoDisablePartition(MdtWorldID world, StepScratch &s, const Partition &part, MeReal h) {
  const MdtWorldParams &w = world->params;
  bool sleepy = true;
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    if (idle(b, w))
      b->idleTime += h;
    else
      b->idleTime = 0;
    if (b->idleTime < w.aliveWindow) sleepy = false;
  }
  if (!w.autoDisable || !sleepy) return false;
  // Asleep: at rest exactly, so waking up starts from rest. Constraint
  // forces keep their last values.
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    MdtBodyDisable(b);
    MeVector3Set(b->velocity, 0, 0, 0);
    MeVector3Set(b->angularVelocity, 0, 0, 0);
    MeVector3Set(b->acceleration, 0, 0, 0);
    MeVector3Set(b->angularAcceleration, 0, 0, 0);
  }
  return true;
}

}  // namespace karma::mdt
