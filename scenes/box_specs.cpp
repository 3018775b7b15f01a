// box_specs.cpp: SCENES.md's box scenes: "topple" (six stacks of 0.5 m
// cubes), "stack21" (21 flat boxes) and "pile1000" (1000 cubes dropped in
// a 10 x 10 x 10 lattice with small deterministic tilts), and "pile10k"
// (10,000 cubes in 100 columns of 100, issue 14's large scene).
#include <cmath>
#include <cstdint>

#include "scene_spec.h"

namespace karma::scenes {

namespace {

// A fixed pseudo-random sequence in [-1, 1) (64-bit LCG, top bits).
class Sequence {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(state_ >> 11) / (double)(1ull << 52) - 1;
  }

 private:
  std::uint64_t state_ = 0x4b61726d61ull;  // "Karma"
};

constexpr ShapeSpec kCube = {ShapeKind::kBox, 0.5, 0.5, 0.5};

// A heap of 5 kg cubes of 0.5 m (mu 0.4 on each other and on the ground),
// 600 steps, judged by nothing being lost; the caller places the cubes.
SceneSpec CubePile(const char *name) {
  SceneSpec s;
  s.name = name;
  s.steps = 600;
  s.friction = {0.4, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  s.expectation = Expectation::kNothingLost;
  return s;
}

}  // namespace

Axes TiltAxes(double yaw, double a, double b) {
  const double cy = std::cos(yaw), sy = std::sin(yaw), ca = std::cos(a), sa = std::sin(a), cb = std::cos(b),
               sb = std::sin(b);
  // Column-vector matrix M = Ry Rx Rz; the body axes are M's columns.
  const double Ry[3][3] = {{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}};
  const double Rx[3][3] = {{1, 0, 0}, {0, ca, -sa}, {0, sa, ca}};
  const double Rz[3][3] = {{cb, -sb, 0}, {sb, cb, 0}, {0, 0, 1}};
  double t[3][3] = {}, m[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) t[i][j] += Ry[i][k] * Rx[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += t[i][k] * Rz[k][j];
  Axes R;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 3; ++i) R[axis][i] = m[i][axis];
  return R;
}

SceneSpec ToppleSpec() {
  SceneSpec s;
  s.name = "topple";
  s.steps = 600;
  s.friction = {0.4, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  const int heights[6] = {3, 4, 5, 6, 3, 4};
  for (int k = 0; k < 6; ++k) {
    for (int i = 0; i < heights[k]; ++i)
      s.bodies.push_back({kCube, 5, {-5.0 + 2 * k, (i + 0.5) * 0.5 + 0.001 * i, 0}, kIdentityAxes, 0});
    s.watched.push_back((int)s.bodies.size() - 1);  // the stack's top box
  }
  s.expectation = Expectation::kStacksStand;
  s.capacity = {32, 32, 256, 512};
  return s;
}

SceneSpec Stack21Spec() {
  SceneSpec s;
  s.name = "stack21";
  s.steps = 1200;
  s.friction = {0.1, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  for (int i = 0; i < 21; ++i)
    s.bodies.push_back({{ShapeKind::kBox, 1, 0.3, 1}, 5, {0, (i + 0.5) * 0.3 + 0.001 * i, 0}, kIdentityAxes, 0});
  s.expectation = Expectation::kTopStill;
  s.watched = {20};
  s.capacity = {24, 24, 128, 256};
  return s;
}

SceneSpec Pile1000Spec() {
  SceneSpec s = CubePile("pile1000");
  Sequence random;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) {
        const double yaw = 0.3 * random.next(), a = 0.1 * random.next(), b = 0.1 * random.next();
        s.bodies.push_back({kCube, 5, {(i - 4.5) * 0.7, 0.6 + 0.7 * j, (k - 4.5) * 0.7}, TiltAxes(yaw, a, b), 0});
      }
  s.capacity = {1000, 1001, 20000, 30000};
  return s;
}

// A 10 x 10 grid of columns 1 m apart, each of 100 cubes of 0.5 m and 5 kg
// 0.502 m apart (gaps of 2 mm, the lowest 2 mm above the ground), each cube
// turned by a pseudo-random yaw of up to 0.3 rad and tilts of up to 0.01
// rad: the columns land, the gaps close from the bottom up (the top cube,
// having fallen the 0.2 m of all the gaps below it, meets the one below at
// about sqrt(2 g 0.2 m) = 2 m/s) and each column rests as one stack of about
// 1,200 contact rows, its own partition.
SceneSpec Pile10kSpec() {
  SceneSpec s = CubePile("pile10k");
  Sequence random;
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < 10; ++k)
      for (int j = 0; j < 100; ++j) {
        const double yaw = 0.3 * random.next(), a = 0.01 * random.next(), b = 0.01 * random.next();
        s.bodies.push_back({kCube, 5, {(i - 4.5) * 1.0, 0.252 + 0.502 * j, (k - 4.5) * 1.0}, TiltAxes(yaw, a, b), 0});
      }
  // pile1000's per-cube margins (20 pairs, 30 constraints): a standing
  // column needs about 2 pairs a cube, but fallen columns heap up.
  s.capacity = {10000, 10001, 200000, 300000};
  return s;
}

}  // namespace karma::scenes
