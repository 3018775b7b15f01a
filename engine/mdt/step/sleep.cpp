// sleep.cpp: stage 8 of the step (step.h), auto-disable. A body is idle
// while its speed, angular speed, acceleration and angular acceleration are
// all below the world's thresholds; a partition whose bodies have all been
// idle for the alive window goes to sleep, at rest.
#include "step.h"

namespace karma::mdt {

namespace {

bool idle(const MdtBody *b, const MdtWorldParams &w) {
  return MeVector3Magnitude(b->velocity) < w.velocityThreshold &&
         MeVector3Magnitude(b->angularVelocity) < w.angularVelocityThreshold &&
         MeVector3Magnitude(b->acceleration) < w.accelerationThreshold &&
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
