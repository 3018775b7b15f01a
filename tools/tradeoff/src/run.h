// run.h: one run of a scene with one setting: the time of its steps and
// what it did, sampled every 1/60 s of simulated time so that runs of
// different step sizes compare at the same instants.
#pragma once

#include <array>
#include <vector>

#include "scene.h"
#include "settings.h"

namespace karma::tradeoff {

using Vec3d = std::array<double, 3>;

// The state of a run at the sample instants k/60 s, k = 1 .. frames.
struct Trajectory {
  std::vector<std::vector<Vec3d>> positions;  // per sample, per body
  std::vector<double> energy;                 // kinetic + gravitational potential, J
  std::vector<Vec3d> momentum;                // linear momentum, N s
};

struct RunRecord {
  int steps = 0;
  double stepSeconds = 0;  // wall time of the steps alone, summed
  bool finite = true;      // no NaN or infinity in any body's state
  double maxSpeed = 0;     // fastest body seen, m/s
  double jointError = 0;   // largest joint gap over the run, m
  double penetration = 0;  // deepest contact penetration over the run, m
  double residual = 0;     // largest Kea residual of any step (MdtWorldStepStats)
  int unsolvedSteps = 0;   // steps with a partition Kea left unsolved
  SceneOutcome outcome;
  Trajectory trajectory;
  double microsPerStep() const { return steps > 0 ? stepSeconds * 1e6 / steps : 0; }
  // Stable (finite, under 50 m/s) and the scene's check held.
  bool held() const { return finite && maxSpeed < 50 && outcome.held; }
};

// Builds the scene, applies the setting and runs `seconds` of simulated
// time in steps of setting.h. Only the steps are timed. Returns false if
// the scene could not be built.
bool RunScene(const SceneEntry &scene, const Setting &setting, double seconds, RunRecord &out);

// Errors of a run against the reference run, over the common samples:
struct Errors {
  double drift = 0;     // largest RMS over bodies of |x - x_ref|, m
  double energy = 0;    // largest |E - E_ref|, J
  double momentum = 0;  // largest |p - p_ref|, N s
};
// NaN errors when the run is not finite.
Errors CompareWithReference(const RunRecord &run, const RunRecord &reference);

// Kinetic plus gravitational potential energy of the bodies, J (potential
// -m g.x, zero at the origin).
double MechanicalEnergy(MdtWorldID world, const std::vector<MdtBodyID> &bodies);
// The deepest penetration over the bodies' contacts now, m.
double DeepestContact(const std::vector<MdtBodyID> &bodies);

}  // namespace karma::tradeoff
