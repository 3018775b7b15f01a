// peer_engine.h: one engine running one anchor scene, built from the
// scene's engine-neutral description (scenes/scene_spec.h). The runner
// (peer_bench.cpp) times step() only; everything else is bookkeeping.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene_figures.h"
#include "scene_spec.h"

namespace karma::peers {

using scenes::BodyState;
using scenes::SceneSpec;

class PeerEngine {
 public:
  virtual ~PeerEngine() = default;
  // The scene's drives, then one step of 1/60 s: collision, solve and
  // integration.
  virtual void step() = 0;
  // Every body's state, in the order of SceneSpec::bodies.
  virtual void states(std::vector<BodyState> &out) const = 0;
  // The deepest overlap of two shapes (or a shape and the ground) in the
  // current state, m; may run the engine's collision detection again.
  virtual double penetration() = 0;
};

// An engine of the comparison: its name in the table and how to build it.
struct EngineKind {
  std::string name;
  std::unique_ptr<PeerEngine> (*make)(const SceneSpec &spec);
};

// Whether the engines built after the call let resting bodies sleep, each
// by its own rule at its own default thresholds (Karma's auto-disable,
// ODE's auto-disable, Bullet's deactivation). Off by default: the
// comparison is of the solvers, and ODE's own default is off.
void SetPeersSleep(bool on);
bool PeersSleep();

std::unique_ptr<PeerEngine> MakeKarma(const SceneSpec &spec);
// MdtWorldSetKeaIterativeRows for the Karma engines built after the call
// (0: every partition solved exactly); negative, the default: the engine's
// own default is left in place.
void SetKarmaIterativeRows(int rows);
void SetKarmaMaxIterations(int count);
// MdtWorldSetEpsilon (>= 0) and MdtWorldSetJointProjection (>= 0) for the
// Karma engines built after the call; negative, the default: the engine's
// own defaults (the guide's epsilon 0.01, no projection).
void SetKarmaEpsilon(double epsilon);
void SetKarmaJointProjection(int sweeps);
#if KARMA_PEERS_HAVE_ODE
std::unique_ptr<PeerEngine> MakeOdeStep(const SceneSpec &spec);
std::unique_ptr<PeerEngine> MakeOdeQuickStep(const SceneSpec &spec);
// Contacts per colliding pair for the ODE engines built after the call
// (1 to 8; 8 by default).
void SetOdeMaxContacts(int n);
#endif
#if KARMA_PEERS_HAVE_BULLET
std::unique_ptr<PeerEngine> MakeBullet(const SceneSpec &spec);
#endif

}  // namespace karma::peers
