// karma_engine.cpp: this project's engine in the comparison: the anchor
// scene as scenes/anchor_scene.h builds it (Mst, defaults: the exact Kea
// solver), stepped without the scene's own bookkeeping.
#include "anchor_scene.h"
#include "peer_engine.h"

namespace karma::peers {

namespace {

class KarmaEngine final : public PeerEngine {
 public:
  explicit KarmaEngine(const SceneSpec &spec) : scene_(spec) {}
  void step() override { scene_.advance(); }
  void states(std::vector<BodyState> &out) const override { scene_.states(out); }
  double penetration() override { return scenes::DeepestPenetration(scene_.models()); }

 private:
  scenes::AnchorScene scene_;
};

}  // namespace

std::unique_ptr<PeerEngine> MakeKarma(const SceneSpec &spec) { return std::make_unique<KarmaEngine>(spec); }

}  // namespace karma::peers
