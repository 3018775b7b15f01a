// hard_cases.h: the hard cases of ../shared/DESIGN.md ("tall stacks, big
// mass ratios, long chains") as scene descriptions (scenes/scene_spec.h),
// built in Karma by the anchor scenes' builder. stack21 (an anchor scene)
// is the tall stack; these add:
//   pile27          27 cubes dropped in a 3 x 3 x 3 lattice, alternate
//                   layers shifted 0.2 m along x so they land overhanging;
//                   check: nothing lost or below the ground
//   chain           20 capsule links of 0.2 kg and a 20 kg ball (mass ratio
//                   100:1) on ball-and-socket joints, falling level from
//                   2 m onto the ground; check: joints whole at the end
//   heavy_on_light  four flat boxes, 1, 100, 1 and 100 kg from the ground
//                   up; check: the top box drifts < 50 mm
#pragma once

#include "scene_spec.h"

namespace karma::tradeoff {

scenes::SceneSpec Pile27Spec();
scenes::SceneSpec ChainSpec();
scenes::SceneSpec HeavyOnLightSpec();

}  // namespace karma::tradeoff
