// tutorial_scenes.cpp: the tutorials' simulations that build without a
// viewer, run as the tutorial runs them but with the sweep's step size:
// each step is the tutorial's collision half (BallmanCollide,
// RainbowChainCollide), then MdtWorldStep(world, h). Nobody drives: the
// rag doll is not pushed and the chain's end force stays zero, so the rag
// doll falls where it stands and the chain swings down from its pivot.
// (The tutorials themselves take one 1/60 s step per frame with the joint
// projection on; the sweep keeps their worlds' settings.) Their check: every
// joint's gap under 20 mm after the run; their scene error: the largest
// gap over the run.
#include <cstdio>

#include "builtin_scenes.h"

extern "C" {
#include "ballman_sim.h"
#include "chain.h"
}

namespace karma::tradeoff {

namespace {

constexpr double kWholeGap = 0.02;  // m: a joint this far apart has come apart

// What the two tutorial scenes share: the bodies, the joints, the outcome.
class TutorialScene : public TradeoffScene {
 public:
  const std::vector<MdtBodyID> &bodies() const override { return bodies_; }
  double jointGap() const override { return LargestJointGap(joints_); }
  void observe() override { worstGap_ = std::max(worstGap_, jointGap()); }
  SceneOutcome finish(double) override {
    SceneOutcome o;
    const double end = jointGap();
    o.held = end < kWholeGap;
    char text[96];
    std::snprintf(text, sizeof text, "joint error: max %.2f mm, end %.2f mm", worstGap_ * 1e3, end * 1e3);
    o.detail = text;
    o.sceneError = worstGap_;
    o.jointErrorMax = worstGap_;
    return o;
  }

 protected:
  std::vector<MdtBodyID> bodies_;
  std::vector<MdtConstraintID> joints_;
  double worstGap_ = 0;
};

class BallmanScene final : public TutorialScene {
 public:
  BallmanScene() : b_(BallmanCreate()) {
    if (!b_) return;
    for (McdModelID m : b_->part) bodies_.push_back(McdModelGetBody(m));
    for (McdModelID m : b_->box) bodies_.push_back(McdModelGetBody(m));
    for (MdtSkeletalID j : b_->joint) joints_.push_back(MdtSkeletalQuaConstraint(j));
  }
  ~BallmanScene() override { BallmanDestroy(b_); }
  MdtWorldID world() const override { return b_ ? b_->universe->world : nullptr; }
  McdFrameworkID framework() const override { return b_ ? b_->universe->frame : nullptr; }
  void advance(MeReal h) override {
    BallmanCollide(b_);
    MdtWorldStep(b_->universe->world, h);
  }

 private:
  Ballman *b_;
};

class ChainScene final : public TutorialScene {
 public:
  ChainScene() : c_(RainbowChainCreate()) {
    if (!c_) return;
    for (McdModelID m : c_->ball) bodies_.push_back(McdModelGetBody(m));
    for (MdtBSJointID j : c_->joint) joints_.push_back(MdtBSJointQuaConstraint(j));
  }
  ~ChainScene() override { RainbowChainDestroy(c_); }
  MdtWorldID world() const override { return c_ ? c_->universe->world : nullptr; }
  McdFrameworkID framework() const override { return c_ ? c_->universe->frame : nullptr; }
  void advance(MeReal h) override {
    RainbowChainCollide(c_);
    MdtWorldStep(c_->universe->world, h);
  }

 private:
  RainbowChain *c_;
};

}  // namespace

std::unique_ptr<TradeoffScene> MakeBallman() { return std::make_unique<BallmanScene>(); }
std::unique_ptr<TradeoffScene> MakeRainbowChain() { return std::make_unique<ChainScene>(); }

}  // namespace karma::tradeoff
