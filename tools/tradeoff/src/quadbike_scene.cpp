// quadbike_scene.cpp: the QuadBike tutorial (its step 19: bike, rider,
// height-field terrain) on its scripted ride, stepped with the sweep's h:
// each step is the tutorial's tick with h for its fixed step (the ride's
// inputs at the run's own time, the bike's and the rider's controls,
// collision, MdtWorldStep(world, h)). The tutorial keeps its world in
// globals: one QuadBike exists at a time, which the sweep's one run at a
// time respects. Its check: the rider's joints within 20 mm of whole at
// the end and the chassis above the terrain; its scene error: the rider's
// largest joint gap over the run.
#include <cmath>
#include <cstdio>

#include "builtin_scenes.h"

extern "C" {
#include "quadbike.h"
}
#undef max  // quadbike.h's C macros would shadow std::max and std::min
#undef min

namespace karma::tradeoff {

namespace {

constexpr double kWholeGap = 0.02;  // m

class QuadBikeScene final : public TradeoffScene {
 public:
  QuadBikeScene() {
    const QuadBikeOptions options = {1, 1};  // the height field, the scripted ride
    built_ = QuadBikeCreate(&options) != 0 && ::world != nullptr;
    if (!built_) return;
    MdtBodyID all[14];
    const int n = QuadBikeBodies(all);
    bodies_.assign(all, all + n);
  }
  ~QuadBikeScene() override { QuadBikeDestroy(); }
  MdtWorldID world() const override { return built_ ? ::world : nullptr; }
  McdFrameworkID framework() const override { return built_ ? ::framework : nullptr; }
  const std::vector<MdtBodyID> &bodies() const override { return bodies_; }
  double jointGap() const override { return QuadBikeRiderJointError(); }
  void observe() override { worstGap_ = std::fmax(worstGap_, jointGap()); }

  void advance(MeReal h) override {
    QuadBikeRideInputs((MeReal)time_, &quadBike.throttleInput, &quadBike.brakeInput, &quadBike.steeringInput);
    UpdateVehicleControls(&quadBike);
    UpdateRiderControls(&rider);
    McdSpaceUpdateAll(space);
    MstBridgeUpdateContacts(bridge, space, ::world);
    MdtWorldStep(::world, h);
    time_ += h;
  }

  SceneOutcome finish(double) override {
    SceneOutcome o;
    MeVector3 x;
    MdtBodyGetPosition(quadBike.chassisBody, x);
    const double end = jointGap(), above = x[1] - TerrainHeightAt(x[0], x[2]);
    o.held = end < kWholeGap && above > 0;
    char text[128];
    std::snprintf(text, sizeof text, "rider joint error: max %.2f mm, end %.2f mm; chassis %.2f m above the terrain",
                  worstGap_ * 1e3, end * 1e3, above);
    o.detail = text;
    o.sceneError = worstGap_;
    o.jointErrorMax = worstGap_;
    return o;
  }

 private:
  bool built_ = false;
  std::vector<MdtBodyID> bodies_;
  double time_ = 0;
  double worstGap_ = 0;
};

}  // namespace

std::unique_ptr<TradeoffScene> MakeQuadBike() { return std::make_unique<QuadBikeScene>(); }

}  // namespace karma::tradeoff
