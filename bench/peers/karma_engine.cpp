// karma_engine.cpp: this project's engine in the comparison: the anchor
// scene as scenes/anchor_scene.h builds it (Mst, defaults: the exact Kea
// solver, unless SetKarmaIterativeRows sends large partitions to the
// iterative one), stepped without the scene's own bookkeeping.
#include "anchor_scene.h"
#include "peer_engine.h"

namespace karma::peers {

namespace {

int iterativeRows = -1;  // < 0: the engine's default

class KarmaEngine final : public PeerEngine {
 public:
  explicit KarmaEngine(const SceneSpec &spec) : scene_(spec) {
    if (iterativeRows >= 0) MdtWorldSetKeaIterativeRows(scene_.world(), iterativeRows);
  }
  void step() override { scene_.advance(); }
  void states(std::vector<BodyState> &out) const override { scene_.states(out); }
  double penetration() override { return scenes::DeepestPenetration(scene_.models()); }

 private:
  scenes::AnchorScene scene_;
};

}  // namespace

void SetKarmaIterativeRows(int rows) { iterativeRows = rows; }

std::unique_ptr<PeerEngine> MakeKarma(const SceneSpec &spec) { return std::make_unique<KarmaEngine>(spec); }

}  // namespace karma::peers
