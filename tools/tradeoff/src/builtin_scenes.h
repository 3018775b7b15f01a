// builtin_scenes.h: the makers of the built-in scenes, gathered by
// Catalogue() (catalogue.cpp).
#pragma once

#include <memory>

#include "scene.h"
#include "scene_figures.h"
#include "scene_spec.h"

namespace karma::tradeoff {

// A scene description (an anchor scene or a hard case) built through the
// anchor scenes' builder, stepped with any h.
std::unique_ptr<TradeoffScene> MakeSpecScene(scenes::SceneSpec spec);
// The scene's own error figure of a run from its figures, the same figure
// the peers' table gives (peers.h):
//   car rolls       |x - a t^2/2|, the chassis against the analytic distance
//   stacks, top box the worst top box's larger of sideways drift and
//                   |drop - closure|, closure = StackClosure (the gaps the
//                   boxes start with, which a stack rightly closes)
//   joints whole    the largest joint gap over the run
//   nothing lost    the deepest penetration after the last step
double SceneError(const scenes::SceneSpec &spec, const scenes::SceneFigures &f, double seconds);
// How far the watched top boxes fall when the gaps below them close (the
// boxes of a column resting on each other), the largest over them, m.
double StackClosure(const scenes::SceneSpec &spec);

#if KARMA_TRADEOFF_HAVE_TUTORIALS
std::unique_ptr<TradeoffScene> MakeBallman();
std::unique_ptr<TradeoffScene> MakeRainbowChain();
std::unique_ptr<TradeoffScene> MakeQuadBike();
#endif

}  // namespace karma::tradeoff

namespace karma::tradeoff {
// A user's scene (user_scene.cpp).
bool OpenUserScene(const std::string &path, SceneEntry &out, std::string &error);
}  // namespace karma::tradeoff
