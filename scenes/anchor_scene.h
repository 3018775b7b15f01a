// anchor_scene.h: an anchor scene of ../shared/bench/SCENES.md built in
// Karma through Mst from its engine-neutral description (scene_spec.h),
// for the benchmarks (time per step), the peer comparison
// (bench/peers/) and the tests (each scene's expectation).
//
// The description maps onto Mst as: one material per friction entry,
// whose pairs use Coulomb friction (the normal-force model, 2D) with the
// larger of the two coefficients and restitution 0; a static McdPlane
// ground; per body an Mcd box, sphere or sphyl with density mass / volume
// (so Mcd's uniform-density inertia); car-wheel joints (MdtCarWheel,
// steering locked, suspension k, c and travel limits about the initial
// pose) and ball-and-socket joints (MdtBSJoint); auto-disable off.
#pragma once

#include <memory>
#include <vector>

#include "Mst.h"
#include "scene_figures.h"
#include "scene_spec.h"

namespace karma::scenes {

class AnchorScene {
 public:
  explicit AnchorScene(SceneSpec spec);
  ~AnchorScene();
  AnchorScene(const AnchorScene &) = delete;
  AnchorScene &operator=(const AnchorScene &) = delete;

  const char *name() const { return spec_.name.c_str(); }
  int steps() const { return spec_.steps; }  // the scene's run length
  const SceneSpec &spec() const { return spec_; }
  MstUniverseID universe() const { return universe_; }
  MdtWorldID world() const;
  // Every dynamic model, in the order of the description's bodies.
  const std::vector<McdModelID> &models() const { return bodies_; }

  // The scene's drives, then MstUniverseStep(1/60): the engine's step.
  void advance();
  // One step: advance(), then the bookkeeping of the figures (finite, max
  // speed, joint error).
  void step();
  // Every body's state, in description order.
  void states(std::vector<BodyState> &out) const;
  // Kinetic energy of every dynamic body, (1/2) m v.v + (1/2) w.Iw w, in J.
  double kineticEnergy() const;
  // Runs the remaining steps and evaluates the expectation.
  SceneFigures run();
  // Evaluates the expectation and the final figures now.
  SceneFigures finish();

  static constexpr MeReal kStep = (MeReal)1 / 60;

 private:
  void createMaterials();
  void createGround();
  void createBody(const BodySpec &b);
  void createCarWheel(const CarWheelSpec &w);
  void createBallJoint(const BallJointSpec &j);
  void disablePair(McdModelID a, McdModelID b);
  McdFrameworkID framework() const;
  MdtBodyID body(int index) const { return McdModelGetBody(bodies_[(size_t)index]); }

  SceneSpec spec_;
  SceneMonitor monitor_;
  int done_ = 0;
  MstUniverseID universe_ = nullptr;
  std::vector<MstMaterialID> materials_;  // per friction entry
  std::vector<MeReal> mu_;                // per Mst material id
  MeMatrix4 groundTM_;
  std::vector<McdModelID> bodies_;
  std::vector<MdtCarWheelID> carWheels_;
  mutable std::vector<BodyState> states_;
};

std::unique_ptr<AnchorScene> MakeCar();
std::unique_ptr<AnchorScene> MakeTopple();
std::unique_ptr<AnchorScene> MakeStack21();
std::unique_ptr<AnchorScene> MakeRagdoll();
std::unique_ptr<AnchorScene> MakePile1000();
std::unique_ptr<AnchorScene> MakePile10k();  // not an anchor scene: issue 14's large pile (scene_spec.h)

// Deepest penetration over the enabled contacts of the models' bodies.
double DeepestPenetration(const std::vector<McdModelID> &models);

}  // namespace karma::scenes
