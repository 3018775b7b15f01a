// catalogue.cpp: the built-in scenes by name, and finding a scene.
#include <algorithm>

#include "anchor_scene.h"
#include "builtin_scenes.h"
#include "hard_cases.h"

namespace karma::tradeoff {

namespace {

SceneEntry FromSpec(scenes::SceneSpec (*spec)(), const char *kind, const char *about) {
  const scenes::SceneSpec s = spec();
  return {s.name, kind, about, s.steps * scenes::kStepSeconds, [spec] { return MakeSpecScene(spec()); }};
}

std::vector<SceneEntry> MakeCatalogue() {
  std::vector<SceneEntry> all = {
      FromSpec(&scenes::CarSpec, "anchor", "a driven car on four car-wheel joints (SCENES.md 1)"),
      FromSpec(&scenes::ToppleSpec, "anchor", "six stacks of cubes, 25 boxes (SCENES.md 2)"),
      FromSpec(&scenes::Stack21Spec, "anchor", "21 flat boxes in one stack (SCENES.md 3)"),
      FromSpec(&scenes::RagdollSpec, "anchor", "a falling rag doll, 9 ball joints (SCENES.md 4)"),
      FromSpec(&scenes::Pile1000Spec, "anchor", "1000 cubes dropped in a lattice (SCENES.md 5)"),
      FromSpec(&Pile27Spec, "hard case", "27 cubes dropped in a 3x3x3 lattice, shifted layers"),
      FromSpec(&ChainSpec, "hard case", "20 light links and a 100x heavier ball falling"),
      FromSpec(&HeavyOnLightSpec, "hard case", "boxes of 1, 100, 1, 100 kg stacked"),
  };
#if KARMA_TRADEOFF_HAVE_TUTORIALS
  all.push_back({"ballman", "tutorial", "Ballman's rag doll on its stairs, not pushed", 4.0, &MakeBallman});
  all.push_back({"rainbowchain", "tutorial", "RainbowChain's ten balls swinging from a pivot", 6.0, &MakeRainbowChain});
  all.push_back({"quadbike", "tutorial", "QuadBike's rider on its scripted ride over the terrain", 6.0, &MakeQuadBike});
#endif
  return all;
}

}  // namespace

const std::vector<SceneEntry> &Catalogue() {
  static const std::vector<SceneEntry> all = MakeCatalogue();
  return all;
}

bool FindScene(const std::string &name, SceneEntry &out, std::string &error) {
  if (name.find('/') != std::string::npos || (name.size() > 3 && name.substr(name.size() - 3) == ".so"))
    return OpenUserScene(name, out, error);
  const auto &all = Catalogue();
  const auto found = std::find_if(all.begin(), all.end(), [&](const SceneEntry &e) { return e.name == name; });
  if (found == all.end()) {
    error = "no scene '" + name + "' (karma-tradeoff --list shows the built-in scenes)";
    return false;
  }
  out = *found;
  return true;
}

double LargestJointGap(const std::vector<MdtConstraintID> &joints) {
  double gap = 0;
  for (MdtConstraintID c : joints) {
    MeVector3 p0, p1;
    MdtConstraintBodyGetPosition(c, 0, p0);
    MdtConstraintBodyGetPosition(c, 1, p1);
    gap = std::max(gap, (double)MeVector3Distance(p0, p1));
  }
  return gap;
}

}  // namespace karma::tradeoff
