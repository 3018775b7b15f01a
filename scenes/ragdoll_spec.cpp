// ragdoll_spec.cpp: SCENES.md's "ragdoll": ten bodies (boxes and capsules,
// 67 kg) joined by nine ball-and-socket joints, built standing (feet at
// y = 0, facing +z, arms along +-x), turned 0.4 rad about (1, 0, 0.5)
// through the origin and lifted so that its lowest point is at y = 2; its
// parts collide only with the ground.
#include <algorithm>
#include <cmath>

#include "scene_spec.h"

namespace karma::scenes {

namespace {

enum Lie { kUpright, kAlongX, kAlongY };  // a capsule's axis, standing

struct Part {
  ShapeSpec shape;
  Lie lie;
  double mass;
  Vec3 centre;  // standing
};

struct Joint {
  int parent, child;
  Vec3 anchor;  // standing
};

constexpr ShapeKind kBox = ShapeKind::kBox, kCapsule = ShapeKind::kCapsule;

const Part kParts[10] = {
    {{kBox, 0.36, 0.55, 0.20}, kUpright, 30, {0, 1.225, 0}},      // 0 torso
    {{kBox, 0.20, 0.24, 0.20}, kUpright, 5, {0, 1.62, 0}},        // 1 head
    {{kCapsule, 0.05, 0.30, 0}, kAlongX, 2.5, {0.33, 1.42, 0}},   // 2 upper arm L
    {{kCapsule, 0.05, 0.30, 0}, kAlongX, 2.5, {-0.33, 1.42, 0}},  // 3 upper arm R
    {{kCapsule, 0.04, 0.28, 0}, kAlongX, 1.5, {0.62, 1.42, 0}},   // 4 forearm L
    {{kCapsule, 0.04, 0.28, 0}, kAlongX, 1.5, {-0.62, 1.42, 0}},  // 5 forearm R
    {{kCapsule, 0.07, 0.45, 0}, kAlongY, 8, {0.1, 0.725, 0}},     // 6 thigh L
    {{kCapsule, 0.07, 0.45, 0}, kAlongY, 8, {-0.1, 0.725, 0}},    // 7 thigh R
    {{kCapsule, 0.06, 0.44, 0}, kAlongY, 4, {0.1, 0.28, 0}},      // 8 calf L
    {{kCapsule, 0.06, 0.44, 0}, kAlongY, 4, {-0.1, 0.28, 0}},     // 9 calf R
};

const Joint kJoints[9] = {
    {0, 1, {0, 1.50, 0}},    {0, 2, {0.18, 1.42, 0}},  {0, 3, {-0.18, 1.42, 0}},
    {2, 4, {0.48, 1.42, 0}}, {3, 5, {-0.48, 1.42, 0}}, {0, 6, {0.1, 0.95, 0}},
    {0, 7, {-0.1, 0.95, 0}}, {6, 8, {0.1, 0.50, 0}},   {7, 9, {-0.1, 0.50, 0}},
};

// Rotation by `angle` about the unit axis k (column-vector matrix).
void AxisAngle(double M[3][3], const double k[3], double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  M[0][0] = t * k[0] * k[0] + c;
  M[0][1] = t * k[0] * k[1] - s * k[2];
  M[0][2] = t * k[0] * k[2] + s * k[1];
  M[1][0] = t * k[0] * k[1] + s * k[2];
  M[1][1] = t * k[1] * k[1] + c;
  M[1][2] = t * k[1] * k[2] - s * k[0];
  M[2][0] = t * k[0] * k[2] - s * k[1];
  M[2][1] = t * k[1] * k[2] + s * k[0];
  M[2][2] = t * k[2] * k[2] + c;
}

Vec3 Apply(const double M[3][3], const Vec3 &in) {
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = M[i][0] * in[0] + M[i][1] * in[1] + M[i][2] * in[2];
  return out;
}

// Body axes (rows) standing: a capsule lies along its local z.
Axes StandingAxes(Lie lie) {
  switch (lie) {
    case kAlongX:
      return {{{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
    case kAlongY:
      return {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}};
    case kUpright:
      break;
  }
  return kIdentityAxes;
}

}  // namespace

SceneSpec RagdollSpec() {
  SceneSpec s;
  s.name = "ragdoll";
  s.steps = 600;
  s.friction = {0.4, 0.4};  // ground, parts
  s.groundMaterial = 0;
  const double len = std::sqrt(1.25), axis[3] = {1 / len, 0, 0.5 / len};
  double M[3][3];
  AxisAngle(M, axis, 0.4);
  double lowest = 1e9;
  for (const Part &p : kParts) {
    const Axes standing = StandingAxes(p.lie);
    Axes turned;
    for (int r = 0; r < 3; ++r) turned[r] = Apply(M, standing[r]);
    s.bodies.push_back({p.shape, p.mass, Apply(M, p.centre), turned, 1});
    lowest = std::min(lowest, LowestPoint(p.shape, s.bodies.back().position, turned));
  }
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < i; ++j) s.disabledPairs.push_back({i, j});
  for (const Joint &j : kJoints) s.ballJoints.push_back({j.parent, j.child, Apply(M, j.anchor)});
  s.offset = {0, 2.0 - lowest, 0};
  s.expectation = Expectation::kJointsWhole;
  s.capacity = {16, 16, 64, 128};
  return s;
}

}  // namespace karma::scenes
