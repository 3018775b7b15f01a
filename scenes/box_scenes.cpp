// box_scenes.cpp: SCENES.md's box scenes: "topple" (six stacks of 0.5 m
// cubes), "stack21" (21 flat boxes) and "pile1000" (1000 cubes dropped in
// a 10 x 10 x 10 lattice with small deterministic tilts).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "anchor_scene.h"

namespace karma::scenes {

namespace {

// Rotation rows of Ry(yaw) Rx(a) Rz(b) (rows: body axes in world).
void Tilt(MeMatrix3 R, double yaw, double a, double b) {
  const double cy = std::cos(yaw), sy = std::sin(yaw), ca = std::cos(a), sa = std::sin(a),
               cb = std::cos(b), sb = std::sin(b);
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
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 3; ++i) R[axis][i] = (MeReal)m[i][axis];
}

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

// Tracks the top box of each stack: sideways drift and drop.
struct StackTop {
  McdModelID model;
  MeVector3 start;
};

class ToppleScene final : public AnchorScene {
 public:
  ToppleScene() : AnchorScene("topple", 600, 32, 32, 256, 512) {
    const MstMaterialID m = material((MeReal)0.4);
    ground(material((MeReal)0.4));
    McdGeometryID cube = McdBoxCreate(framework(), (MeReal)0.5, (MeReal)0.5, (MeReal)0.5);
    const int heights[6] = {3, 4, 5, 6, 3, 4};
    for (int k = 0; k < 6; ++k) {
      McdModelID top = nullptr;
      for (int i = 0; i < heights[k]; ++i) {
        const MeVector3 p = {(MeReal)(-5 + 2 * k), (MeReal)((i + 0.5) * 0.5 + 0.001 * i), 0};
        top = body(cube, 5, p, m);
      }
      StackTop s{top, {0, 0, 0}};
      MdtBodyGetPosition(McdModelGetBody(top), s.start);
      tops_.push_back(s);
    }
  }

 private:
  void check(SceneFigures &f) override {
    double drift = 0, drop = 0;
    for (const StackTop &s : tops_) {
      MeVector3 x;
      MdtBodyGetPosition(McdModelGetBody(s.model), x);
      drift = std::max(drift, std::hypot((double)(x[0] - s.start[0]), (double)(x[2] - s.start[2])));
      drop = std::max(drop, (double)(s.start[1] - x[1]));
    }
    f.expectation = drift < 0.05 && drop < 0.05;
    char text[120];
    std::snprintf(text, sizeof text, "worst top box: drift %.1f mm, drop %.1f mm", drift * 1e3,
                  drop * 1e3);
    f.detail = text;
  }
  std::vector<StackTop> tops_;
};

class Stack21Scene final : public AnchorScene {
 public:
  Stack21Scene() : AnchorScene("stack21", 1200, 24, 24, 128, 256) {
    const MstMaterialID m = material((MeReal)0.1);
    ground(material((MeReal)0.4));
    McdGeometryID slab = McdBoxCreate(framework(), 1, (MeReal)0.3, 1);
    for (int i = 0; i < 21; ++i) {
      const MeVector3 p = {0, (MeReal)((i + 0.5) * 0.3 + 0.001 * i), 0};
      top_.model = body(slab, 5, p, m);
    }
    MdtBodyGetPosition(McdModelGetBody(top_.model), top_.start);
  }

 private:
  void check(SceneFigures &f) override {
    MeVector3 x;
    MdtBodyGetPosition(McdModelGetBody(top_.model), x);
    const double drift = std::hypot((double)(x[0] - top_.start[0]), (double)(x[2] - top_.start[2]));
    f.expectation = drift < 0.05;
    char text[120];
    std::snprintf(text, sizeof text, "top box drift %.2f mm, height %.4f m", drift * 1e3,
                  (double)x[1]);
    f.detail = text;
  }
  StackTop top_{};
};

class PileScene final : public AnchorScene {
 public:
  PileScene() : AnchorScene("pile1000", 600, 1000, 1001, 20000, 30000) {
    const MstMaterialID m = material((MeReal)0.4);
    ground(material((MeReal)0.4));
    McdGeometryID cube = McdBoxCreate(framework(), (MeReal)0.5, (MeReal)0.5, (MeReal)0.5);
    Sequence random;
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j)
        for (int k = 0; k < 10; ++k) {
          const MeVector3 p = {(MeReal)((i - 4.5) * 0.7), (MeReal)(0.6 + 0.7 * j),
                               (MeReal)((k - 4.5) * 0.7)};
          MeMatrix3 R;
          const double yaw = 0.3 * random.next(), a = 0.1 * random.next(),
                       b = 0.1 * random.next();
          Tilt(R, yaw, a, b);
          body(cube, 5, p, m, &R);
        }
  }

 private:
  void check(SceneFigures &f) override {
    // No box below the ground (its centre at least 0.25 m up less a
    // tolerance of 50 mm) and none lost (within the 10 m lattice area).
    double lowest = 1e9, farthest = 0;
    for (McdModelID model : bodies_) {
      MeVector3 x;
      MdtBodyGetPosition(McdModelGetBody(model), x);
      lowest = std::min(lowest, (double)x[1]);
      farthest = std::max(farthest, std::hypot((double)x[0], (double)x[2]));
    }
    f.expectation = lowest > 0.2 && farthest < 20;
    char text[120];
    std::snprintf(text, sizeof text, "lowest centre %.3f m, farthest %.2f m from the middle",
                  lowest, farthest);
    f.detail = text;
  }
};

}  // namespace

std::unique_ptr<AnchorScene> MakeTopple() { return std::make_unique<ToppleScene>(); }
std::unique_ptr<AnchorScene> MakeStack21() { return std::make_unique<Stack21Scene>(); }
std::unique_ptr<AnchorScene> MakePile1000() { return std::make_unique<PileScene>(); }

}  // namespace karma::scenes
