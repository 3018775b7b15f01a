// user_scene.cpp: a user's scene from a shared library exporting
// KarmaTradeoffBuildScene (KarmaTradeoffScene.h), opened with dlopen.
// The library stays open for the tool's lifetime (its code runs in every
// run); each run calls the build function again.
#include <dlfcn.h>

#include <cmath>
#include <cstring>

#include "KarmaTradeoffScene.h"
#include "builtin_scenes.h"

namespace karma::tradeoff {

namespace {

class UserScene final : public TradeoffScene {
 public:
  explicit UserScene(const KarmaTradeoffScene &s) : s_(s) {
    bodies_.assign(s.bodies, s.bodies + s.bodyCount);
    joints_.assign(s.joints, s.joints + s.jointCount);
  }
  ~UserScene() override {
    if (s_.destroy) s_.destroy(s_.user);
  }
  MdtWorldID world() const override { return s_.world; }
  McdFrameworkID framework() const override { return s_.universe ? MstUniverseGetFramework(s_.universe) : nullptr; }
  const std::vector<MdtBodyID> &bodies() const override { return bodies_; }
  double jointGap() const override { return LargestJointGap(joints_); }
  void observe() override { worstGap_ = std::fmax(worstGap_, jointGap()); }
  void advance(MeReal h) override {
    if (s_.beforeStep) s_.beforeStep(s_.user, h);
    if (s_.universe)
      MstUniverseStep(s_.universe, h);
    else
      MdtWorldStep(s_.world, h);
  }
  SceneOutcome finish(double) override {
    SceneOutcome o;
    o.held = s_.check ? s_.check(s_.user) != 0 : true;
    o.detail = s_.check ? (o.held ? "the scene's check held" : "the scene's check failed") : "no check";
    o.sceneError = joints_.empty() ? std::nan("") : worstGap_;
    o.jointErrorMax = worstGap_;
    return o;
  }

 private:
  KarmaTradeoffScene s_;
  std::vector<MdtBodyID> bodies_;
  std::vector<MdtConstraintID> joints_;
  double worstGap_ = 0;
};

// Calls the build function; an invalid scene is destroyed and reported.
bool Build(KarmaTradeoffBuildSceneFn build, KarmaTradeoffScene &s, std::string &error) {
  std::memset(&s, 0, sizeof s);
  if (!build(&s)) {
    error = "the scene's build function returned 0";
    return false;
  }
  if (s.version != KARMA_TRADEOFF_SCENE_VERSION)
    error = "the scene's version is not KARMA_TRADEOFF_SCENE_VERSION";
  else if (s.realSize != (int)sizeof(MeReal))
    error = "the scene was built for another precision (realSize != sizeof(MeReal))";
  else if (!s.world)
    error = "the scene has no world";
  else if (s.bodyCount < 0 || (s.bodyCount > 0 && !s.bodies))
    error = "the scene's bodies are missing";
  else if (s.jointCount < 0 || (s.jointCount > 0 && !s.joints))
    error = "the scene's joints are missing";
  else if (!(s.seconds > 0))
    error = "the scene's seconds must be positive";
  else
    return true;
  if (s.destroy) s.destroy(s.user);
  return false;
}

}  // namespace

bool OpenUserScene(const std::string &path, SceneEntry &out, std::string &error) {
  void *library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    error = std::string("cannot open the scene library: ") + dlerror();
    return false;
  }
  auto build = reinterpret_cast<KarmaTradeoffBuildSceneFn>(dlsym(library, KARMA_TRADEOFF_BUILD_SCENE_SYMBOL));
  if (!build) {
    error = path + " does not export " KARMA_TRADEOFF_BUILD_SCENE_SYMBOL;
    return false;
  }
  KarmaTradeoffScene probe;
  if (!Build(build, probe, error)) return false;
  out.name = probe.name && *probe.name ? probe.name : path;
  out.kind = "user";
  out.about = "a user's scene from " + path;
  out.seconds = probe.seconds;
  if (probe.destroy) probe.destroy(probe.user);
  out.make = [build]() -> std::unique_ptr<TradeoffScene> {
    KarmaTradeoffScene s;
    std::string ignored;
    if (!Build(build, s, ignored)) return nullptr;
    return std::make_unique<UserScene>(s);
  };
  return true;
}

}  // namespace karma::tradeoff
