// spec_scene.cpp: a scene description built by the anchor scenes' builder
// (scenes/anchor_scene.h) and stepped with the sweep's step size h.
//
// AnchorScene::advance steps by 1/60 s, so this adapter applies the drives
// itself: each driven wheel gets its torque about the hinge axis, which is
// fixed in the wheel (the car-wheel joint's hinge), and the chassis the
// reaction; then MstUniverseStep(universe, h).
#include <array>
#include <cmath>

#include "anchor_scene.h"
#include "builtin_scenes.h"

namespace karma::tradeoff {

namespace {

using scenes::AnchorScene;
using scenes::BodyState;
using scenes::Expectation;
using scenes::SceneFigures;
using scenes::SceneMonitor;
using scenes::SceneSpec;

class SpecScene final : public TradeoffScene {
 public:
  explicit SpecScene(SceneSpec spec) : scene_(std::move(spec)), monitor_(scene_.spec()) {
    for (McdModelID m : scene_.models()) bodies_.push_back(McdModelGetBody(m));
    for (const scenes::DriveSpec &d : scene_.spec().drives) hingeInWheel_.push_back(HingeInWheel(d));
    scene_.states(states_);
    monitor_.start(states_);
  }

  MdtWorldID world() const override { return scene_.world(); }
  McdFrameworkID framework() const override { return MstUniverseGetFramework(scene_.universe()); }
  const std::vector<MdtBodyID> &bodies() const override { return bodies_; }

  void advance(MeReal h) override {
    const SceneSpec &spec = scene_.spec();
    for (size_t i = 0; i < spec.drives.size(); ++i) {
      const scenes::CarWheelSpec &w = spec.carWheels[(size_t)spec.drives[i].joint];
      MeMatrix4 tm;
      MdtBodyGetTransform(bodies_[(size_t)w.wheel], tm);
      MeVector3 axis = {0, 0, 0};  // the hinge in world: its body components times the axes (rows)
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) axis[j] += hingeInWheel_[i][(size_t)k] * tm[k][j];
      const MeReal t = (MeReal)spec.drives[i].torque;
      MdtBodyAddTorque(bodies_[(size_t)w.wheel], t * axis[0], t * axis[1], t * axis[2]);
      MdtBodyAddTorque(bodies_[(size_t)w.chassis], -t * axis[0], -t * axis[1], -t * axis[2]);
    }
    MstUniverseStep(scene_.universe(), h);
  }

  void observe() override {
    scene_.states(states_);
    monitor_.observe(states_);
  }

  SceneOutcome finish(double seconds) override {
    scene_.states(states_);
    // The monitor counts steps of 1/60 s (the car's analytic check reads
    // the time from them).
    const int frames = (int)std::lround(seconds / scenes::kStepSeconds);
    const SceneFigures f = monitor_.finish(states_, frames, scenes::DeepestPenetration(scene_.models()));
    SceneOutcome o;
    o.held = f.stable();
    o.detail = f.detail;
    o.sceneError = SceneError(scene_.spec(), f, seconds);
    o.jointErrorMax = f.jointErrorMax;
    return o;
  }

 private:
  // The drive's hinge axis in the wheel's frame at the start.
  std::array<MeReal, 3> HingeInWheel(const scenes::DriveSpec &d) const {
    const scenes::CarWheelSpec &w = scene_.spec().carWheels[(size_t)d.joint];
    MeMatrix4 tm;
    MdtBodyGetTransform(bodies_[(size_t)w.wheel], tm);
    std::array<MeReal, 3> b{};
    for (int k = 0; k < 3; ++k)
      b[(size_t)k] = (MeReal)(tm[k][0] * w.hingeAxis[0] + tm[k][1] * w.hingeAxis[1] + tm[k][2] * w.hingeAxis[2]);
    return b;
  }

  AnchorScene scene_;
  SceneMonitor monitor_;
  std::vector<MdtBodyID> bodies_;
  std::vector<std::array<MeReal, 3>> hingeInWheel_;
  std::vector<BodyState> states_;
};

}  // namespace

double StackClosure(const SceneSpec &spec) {
  double closure = 0;
  for (int w : spec.watched) {
    const scenes::BodySpec &top = spec.bodies[(size_t)w];
    double rest = top.shape.b / 2;  // on the boxes below it in its column, gaps closed
    for (const scenes::BodySpec &b : spec.bodies)
      if (std::fabs(b.position[0] - top.position[0]) < 1e-9 && std::fabs(b.position[2] - top.position[2]) < 1e-9 &&
          b.position[1] < top.position[1])
        rest += b.shape.b;
    closure = std::fmax(closure, top.position[1] - rest);
  }
  return closure;
}

double SceneError(const SceneSpec &spec, const SceneFigures &f, double seconds) {
  switch (spec.expectation) {
    case Expectation::kCarRolls:
      return std::fabs(f.carPosition - spec.carAcceleration * seconds * seconds / 2);
    case Expectation::kStacksStand:
    case Expectation::kTopStill:
      return std::fmax(f.drift, std::fabs(f.drop - StackClosure(spec)));
    case Expectation::kJointsWhole:
      return f.jointErrorMax;
    case Expectation::kNothingLost:
      return f.penetration;
  }
  return 0;
}

std::unique_ptr<TradeoffScene> MakeSpecScene(SceneSpec spec) { return std::make_unique<SpecScene>(std::move(spec)); }

}  // namespace karma::tradeoff
