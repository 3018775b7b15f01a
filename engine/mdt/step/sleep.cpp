// sleep.cpp: auto-disable, both ways (MdtWorld.h, "Waking by force" and
// "The alive window").
//
// Stage 8 of the step (step.h): a body is idle while its speed, angular
// speed, acceleration and angular acceleration are all below the world's
// thresholds. When a partition goes to sleep depends on the alive-window
// mode:
//   IdleSeconds   every body idle now and for the last aliveWindow seconds
//                 (idleTime >= aliveWindow; enabling restarts idleTime; a
//                 window of 0 needs the body idle now all the same);
//   AwakeSeconds  every body idle now and enabled for >= aliveWindow s;
//   AwakeSteps    every body idle now and enabled for >= aliveWindow steps.
//
// A body in free fall accelerates at |g| whatever the world's scale, while
// one held up by contacts or joints accelerates at ~0. The acceleration
// threshold scales with the world's length scale (0.5 l: 50 m/s^2 at
// l = 100), so on its own it can exceed |g| and put a falling body to
// sleep in mid-air. A body therefore counts as idle only while its
// acceleration is also below |g| / 2: whatever the thresholds, a body
// still accelerating under gravity stays awake.
//
// Before stage 1 (unless MdtWorldSetWakeByForce(world, 0)), wakeDrivenBodies
// enables each disabled body whose applied force, torque or impulse would
// take it past a threshold in one step:
// |F|/m > a_max, |I^-1 tau| > alpha_max, |J|/m > v_max, |I^-1 Ja| > w_max
// (I^-1 the world-frame inverse inertia about the centre of mass).
#include <climits>

#include "active_sets.h"
#include "step.h"

namespace karma::mdt {

namespace {

bool idle(const MdtBody *b, const MdtWorldParams &w) {
  const MeReal g = MeVector3Magnitude(w.gravity);
  const MeReal a = MeVector3Magnitude(b->acceleration);
  if (g > 0 && !(a < g / 2)) return false;
  return MeVector3Magnitude(b->velocity) < w.velocityThreshold &&
         MeVector3Magnitude(b->angularVelocity) < w.angularVelocityThreshold && a < w.accelerationThreshold &&
         MeVector3Magnitude(b->angularAcceleration) < w.angularAccelerationThreshold;
}

// Counts one step of body b and says whether the alive window lets it sleep.
bool windowAllowsSleep(MdtBody *b, const MdtWorldParams &w, MdtAliveWindowMode mode, MeReal h) {
  const bool still = idle(b, w);
  b->idleTime = still ? b->idleTime + h : 0;
  b->awakeTime += h;
  if (b->awakeSteps < INT_MAX) ++b->awakeSteps;
  switch (mode) {
    case MdtAliveWindowAwakeSeconds:
      return still && b->awakeTime >= w.aliveWindow;
    case MdtAliveWindowAwakeSteps:
      return still && (MeReal)b->awakeSteps >= w.aliveWindow;
    case MdtAliveWindowIdleSeconds:
    default:
      return still && b->idleTime >= w.aliveWindow;
  }
}

// Magnitude of the body's world-frame inverse inertia applied to v.
MeReal angularResponse(const MdtBody *b, const MeVector3 v) {
  MeVector3 out;
  applyBodyTensor(out, b, b->invInertia, v);
  return MeVector3Magnitude(out);
}

bool drivenPastThresholds(const MdtBody *b, const MdtWorldParams &w) {
  return MeVector3Magnitude(b->force) * b->invMass > w.accelerationThreshold ||
         angularResponse(b, b->torque) > w.angularAccelerationThreshold ||
         MeVector3Magnitude(b->impulse) * b->invMass > w.velocityThreshold ||
         angularResponse(b, b->angularImpulse) > w.angularVelocityThreshold;
}

void clearAccumulators(MdtBody *b) {
  MeVector3Set(b->force, 0, 0, 0);
  MeVector3Set(b->torque, 0, 0, 0);
  MeVector3Set(b->impulse, 0, 0, 0);
  MeVector3Set(b->angularImpulse, 0, 0, 0);
}

}  // namespace

void wakeDrivenBodies(MdtWorldID world) {
  MdtWorldPrivate *p = world->priv;
  if (p->forcesDoNotWake) return;  // the FAQ's reading: forces wait for an enable
  // Only the driven list can hold a disabled body with a non-zero
  // accumulator (active_sets.h). Each body is decided on its own
  // accumulators, so the list's order does not matter; an enable callback
  // may add to the list, hence the index.
  std::vector<MdtBody *> &driven = p->active->driven;
  for (size_t i = 0; i < driven.size(); ++i) {
    MdtBody *b = driven[i];
    if (!b->drivenListed) continue;  // destroyed (its slot may serve another body)
    b->drivenListed = FALSE;
    if (b->enabled) continue;
    if (drivenPastThresholds(b, world->params))
      MdtBodyEnable(b);
    else
      clearAccumulators(b);
  }
  driven.clear();
}

bool autoDisablePartition(MdtWorldID world, StepScratch &s, const Partition &part, MeReal h) {
  const MdtWorldParams &w = world->params;
  const MdtAliveWindowMode mode = world->priv->aliveWindowMode;
  bool sleepy = true;
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    if (!windowAllowsSleep(b, w, mode, h)) sleepy = false;
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
