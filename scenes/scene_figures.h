// scene_figures.h: the figures of a run of an anchor scene (SCENES.md
// "Figures to report") and the scene's expectation, computed the same way
// for every engine from the bodies' states.
#pragma once

#include <string>
#include <vector>

#include "scene_spec.h"

namespace karma::scenes {

// One body's state, in double precision, in the order of SceneSpec::bodies.
struct BodyState {
  Vec3 position{};
  Axes axes = kIdentityAxes;  // rows: the body axes in world
  Vec3 velocity{};
  Vec3 angularVelocity{};
};

struct SceneFigures {
  int steps = 0;
  bool finite = true;        // no NaN or infinity in any body's state
  double maxSpeed = 0;       // fastest body speed seen at any step, m/s
  bool expectation = false;  // the scene's own check, after the run
  std::string detail;        // the figures behind `expectation`
  double penetration = 0;    // deepest overlap of two bodies after the last step, m
  // car: chassis velocity, position and height after the run.
  double carVelocity = 0, carPosition = 0, carRideHeight = 0;
  // ragdoll: joint error (anchor gap), largest over the run and at the end.
  double jointErrorMax = 0, jointErrorEnd = 0;
  // topple, stack21: worst sideways drift and drop of a watched top box, m;
  // how many of the watched stacks stand (both under 50 mm).
  double drift = 0, drop = 0;
  int standing = 0, stacks = 0;
  // pile1000: the lowest centre's height and the farthest centre's
  // horizontal distance from the middle, m.
  double lowest = 0, farthest = 0;
  bool stable() const { return finite && maxSpeed < 50 && expectation; }
};

// Follows a run: finite states, the largest speed, the ball joints' gap.
// The joint anchors are fixed in the two bodies' frames at start().
class SceneMonitor {
 public:
  explicit SceneMonitor(const SceneSpec &spec) : spec_(&spec) {}
  // The initial states: where the anchors and the watched bodies start.
  void start(const std::vector<BodyState> &bodies);
  // After every step.
  void observe(const std::vector<BodyState> &bodies);
  // The figures and the expectation after `steps` steps, with the deepest
  // penetration the engine measured.
  SceneFigures finish(const std::vector<BodyState> &bodies, int steps, double penetration) const;

 private:
  // Largest distance between a ball joint's anchor as carried by each body.
  double jointError(const std::vector<BodyState> &bodies) const;
  void check(const std::vector<BodyState> &bodies, SceneFigures &f) const;

  const SceneSpec *spec_;
  std::vector<Vec3> anchors_;  // per ball joint: in body0's frame, then in body1's
  std::vector<Vec3> watchedStart_;
  SceneFigures running_;
};

}  // namespace karma::scenes
