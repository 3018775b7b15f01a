// anchor_scene.h: the five anchor scenes of ../shared/bench/SCENES.md (car,
// topple, stack21, ragdoll, pile1000) built through Mst, for the
// benchmarks (time per step) and the tests (each scene's expectation).
//
// Common to all: SI units, y up, gravity (0, -9.81, 0), steps of 1/60 s, a
// static ground plane y = 0, restitution 0, no damping, auto-disable off
// (a scene's caller may turn it on), zero initial velocities. Each body's
// frame is its centre of mass and its shape's centre; masses are given and
// the inertia follows from uniform density. Contact friction is Coulomb
// (the normal-force model, 2D) with the larger of the two materials'
// coefficients.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "Mst.h"

namespace karma::scenes {

// What a run reports (SCENES.md "Figures to report").
struct SceneFigures {
  int steps = 0;
  bool finite = true;         // no NaN or infinity in any body's state
  double maxSpeed = 0;        // fastest body speed seen at any step, m/s
  bool expectation = false;   // the scene's own check, after the run
  std::string detail;         // the figures behind `expectation`
  double penetration = 0;     // deepest contact penetration after the last step, m
  // car: chassis velocity and position along x after the run.
  double carVelocity = 0, carPosition = 0, carRideHeight = 0;
  // ragdoll: joint error (anchor gap), largest over the run and at the end.
  double jointErrorMax = 0, jointErrorEnd = 0;
  bool stable() const { return finite && maxSpeed < 50 && expectation; }
};

class AnchorScene {
 public:
  virtual ~AnchorScene();
  AnchorScene(const AnchorScene &) = delete;
  AnchorScene &operator=(const AnchorScene &) = delete;

  const char *name() const { return name_; }
  int steps() const { return steps_; }  // the scene's run length
  MstUniverseID universe() const { return universe_; }
  MdtWorldID world() const;

  // One step: the scene's own forces, then MstUniverseStep(1/60), then the
  // bookkeeping of the figures (finite, max speed, joint error).
  void step();
  // Kinetic energy of every dynamic body, (1/2) m v.v + (1/2) w.Iw w, in J.
  double kineticEnergy() const;
  // Runs the remaining steps and evaluates the expectation.
  SceneFigures run();
  // Evaluates the expectation and the final figures now.
  SceneFigures finish();

  static constexpr MeReal kStep = (MeReal)1 / 60;

 protected:
  AnchorScene(const char *name, int steps, int bodies, int models, int pairs, int constraints);

  // Scene hooks.
  virtual void applyForces() {}
  virtual void check(SceneFigures &f) = 0;
  virtual void afterStep() {}

  // Building blocks. Materials get their own friction coefficient; the
  // pair's parameters use the larger one.
  MstMaterialID material(MeReal mu);
  McdModelID ground(MstMaterialID m);
  // A body of `mass` with geometry g (inertia from uniform density) at
  // position p and orientation R (rows: the body axes in world; identity
  // when null).
  McdModelID body(McdGeometryID g, MeReal mass, const MeVector3 p, MstMaterialID m,
                  const MeMatrix3 *R = nullptr);
  void disablePair(McdModelID a, McdModelID b);

  McdFrameworkID framework() const;
  std::vector<McdModelID> bodies_;  // every dynamic model, in creation order
  SceneFigures figures_;

 private:
  const char *name_;
  int steps_;
  int done_ = 0;
  MstUniverseID universe_ = nullptr;
  std::vector<MeReal> mu_;  // per material
  MeMatrix4 groundTM_;
};

std::unique_ptr<AnchorScene> MakeCar();
std::unique_ptr<AnchorScene> MakeTopple();
std::unique_ptr<AnchorScene> MakeStack21();
std::unique_ptr<AnchorScene> MakeRagdoll();
std::unique_ptr<AnchorScene> MakePile1000();

// Deepest penetration over the enabled contacts of the models' bodies.
double DeepestPenetration(const std::vector<McdModelID> &models);

}  // namespace karma::scenes
