// karma_engine.cpp: this project's engine in the comparison: the anchor
// scene as scenes/anchor_scene.h builds it (Mst, defaults: the exact Kea
// solver, unless SetKarmaIterativeRows sends large partitions to the
// iterative one; SetKarmaMaxIterations caps the solver's iterations, the
// sweeps of the iterative one; SetKarmaEpsilon and SetKarmaJointProjection
// set the world's softness and joint projection; SetPeersSleep turns on
// the auto-disable the anchor scenes turn off, at the guide's default
// thresholds), stepped without the scene's own bookkeeping.
#include "anchor_scene.h"
#include "peer_engine.h"

namespace karma::peers {

namespace {

int iterativeRows = -1;    // < 0: the engine's default
int maxIterations = 0;     // MdtWorldSetKeaMaxIterations; 0: the engine's default
double epsilon = -1;       // MdtWorldSetEpsilon; < 0: the engine's default
int jointProjection = -1;  // MdtWorldSetJointProjection; < 0: the engine's default
bool peersSleep = false;   // SetPeersSleep, for every engine

class KarmaEngine final : public PeerEngine {
 public:
  explicit KarmaEngine(const SceneSpec &spec) : scene_(spec) {
    if (iterativeRows >= 0) MdtWorldSetKeaIterativeRows(scene_.world(), iterativeRows);
    if (maxIterations > 0) MdtWorldSetKeaMaxIterations(scene_.world(), maxIterations);
    if (epsilon >= 0) MdtWorldSetEpsilon(scene_.world(), (MeReal)epsilon);
    if (jointProjection >= 0) MdtWorldSetJointProjection(scene_.world(), jointProjection);
    if (PeersSleep()) MdtWorldSetAutoDisable(scene_.world(), 1);
  }
  void step() override { scene_.advance(); }
  void states(std::vector<BodyState> &out) const override { scene_.states(out); }
  double penetration() override { return scenes::DeepestPenetration(scene_.models()); }

 private:
  scenes::AnchorScene scene_;
};

}  // namespace

void SetKarmaIterativeRows(int rows) { iterativeRows = rows; }
void SetKarmaMaxIterations(int count) { maxIterations = count; }
void SetKarmaEpsilon(double e) { epsilon = e; }
void SetKarmaJointProjection(int sweeps) { jointProjection = sweeps; }
void SetPeersSleep(bool on) { peersSleep = on; }
bool PeersSleep() { return peersSleep; }

std::unique_ptr<PeerEngine> MakeKarma(const SceneSpec &spec) { return std::make_unique<KarmaEngine>(spec); }

}  // namespace karma::peers
