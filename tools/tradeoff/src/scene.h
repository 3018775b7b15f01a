// scene.h: a scene the trade-off tool can run: something that builds a
// world, steps it with any step size and judges its own run.
//
// Built-in scenes (Catalogue()): the five anchor scenes of
// ../shared/bench/SCENES.md (scenes/), three hard cases (hard_cases.cpp),
// the tutorials' simulations that build without a viewer (Ballman,
// RainbowChain, QuadBike); and a user's scene from a shared library
// (KarmaTradeoffScene.h, user_scene.cpp).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Mst.h"

namespace karma::tradeoff {

// The scene's own judgement of a run.
struct SceneOutcome {
  bool held = true;    // the scene's check (stack standing, nothing lost, ...)
  std::string detail;  // the figures behind it
  // The scene's own error figure (see SceneError in anchor_scenes.cpp),
  // comparable with the peers' figures; NaN when the scene has none.
  double sceneError = 0;
  double jointErrorMax = 0;  // joint gap the scene tracked itself, m (0: none)
};

class TradeoffScene {
 public:
  virtual ~TradeoffScene() = default;
  virtual MdtWorldID world() const = 0;
  // The collision framework, or NULL for a scene without collision.
  virtual McdFrameworkID framework() const { return nullptr; }
  // The scene's drives, then one step of h seconds (collision and dynamics).
  virtual void advance(MeReal h) = 0;
  // After every step, untimed: the scene's own bookkeeping.
  virtual void observe() {}
  // The bodies the errors are measured on, in a fixed order.
  virtual const std::vector<MdtBodyID> &bodies() const = 0;
  // The largest gap of the scene's joints now, m (0 without joints).
  virtual double jointGap() const { return 0; }
  // After the last step, `seconds` of simulated time since the start.
  virtual SceneOutcome finish(double seconds) = 0;
};

struct SceneEntry {
  std::string name;
  std::string kind;    // "anchor", "hard case", "tutorial", "user"
  std::string about;   // one line
  double seconds = 0;  // the default run length
  std::function<std::unique_ptr<TradeoffScene>()> make;
};

// Every built-in scene, anchors first.
const std::vector<SceneEntry> &Catalogue();
// A built-in scene by name, or a user's scene from a shared library when
// `name` contains a '/' or ends in ".so". False with a message when
// neither works.
bool FindScene(const std::string &name, SceneEntry &out, std::string &error);

// The largest distance between a joint's point as carried by its two
// bodies (MdtConstraintBodyGetPosition), over `joints`.
double LargestJointGap(const std::vector<MdtConstraintID> &joints);

}  // namespace karma::tradeoff
