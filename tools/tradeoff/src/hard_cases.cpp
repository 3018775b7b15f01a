// hard_cases.cpp: the hard cases' descriptions (hard_cases.h).
#include "hard_cases.h"

namespace karma::tradeoff {

using scenes::BallJointSpec;
using scenes::Expectation;
using scenes::kIdentityAxes;
using scenes::SceneSpec;
using scenes::ShapeKind;
using scenes::ShapeSpec;

SceneSpec Pile27Spec() {
  SceneSpec s;
  s.name = "pile27";
  s.steps = 180;
  s.friction = {0.4, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  const ShapeSpec cube = {ShapeKind::kBox, 0.5, 0.5, 0.5};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        s.bodies.push_back({cube, 5, {(i - 1) * 0.7 + 0.2 * (j % 2), 0.6 + 0.7 * j, (k - 1) * 0.7}, kIdentityAxes, 0});
  s.expectation = Expectation::kNothingLost;
  s.capacity = {27, 28, 512, 1024};
  return s;
}

SceneSpec ChainSpec() {
  SceneSpec s;
  s.name = "chain";
  s.steps = 180;
  s.friction = {0.4, 0.4};  // chain, ground
  s.groundMaterial = 1;
  constexpr int kLinks = 20;
  constexpr double kRadius = 0.05, kLength = 0.3, kPitch = kLength + 2 * kRadius, kHeight = 2;
  // Capsules lie along z in their frame: turn z onto x (rows: body axes).
  const scenes::Axes alongX = {{{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
  for (int i = 0; i < kLinks; ++i)
    s.bodies.push_back({{ShapeKind::kCapsule, kRadius, kLength, 0}, 0.2, {i * kPitch, kHeight, 0}, alongX, 0});
  constexpr double kBall = 0.3;
  s.bodies.push_back(
      {{ShapeKind::kSphere, kBall, 0, 0}, 20, {(kLinks - 0.5) * kPitch + kBall, kHeight, 0}, kIdentityAxes, 0});
  for (int i = 0; i < kLinks; ++i) s.ballJoints.push_back(BallJointSpec{i, i + 1, {(i + 0.5) * kPitch, kHeight, 0}});
  for (int i = 0; i + 1 < (int)s.bodies.size(); ++i)
    for (int j = i + 1; j < (int)s.bodies.size(); ++j) s.disabledPairs.push_back({i, j});
  s.expectation = Expectation::kJointsWhole;
  s.capacity = {24, 24, 512, 256};
  return s;
}

SceneSpec HeavyOnLightSpec() {
  SceneSpec s;
  s.name = "heavy_on_light";
  s.steps = 300;
  s.friction = {0.4, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  const double masses[4] = {1, 100, 1, 100};
  for (int i = 0; i < 4; ++i)
    s.bodies.push_back(
        {{ShapeKind::kBox, 1, 0.2, 1}, masses[i], {0, (i + 0.5) * 0.2 + 0.001 * i, 0}, kIdentityAxes, 0});
  s.expectation = Expectation::kTopStill;
  s.watched = {3};
  s.capacity = {4, 5, 64, 128};
  return s;
}

}  // namespace karma::tradeoff
