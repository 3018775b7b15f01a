// scene_spec.cpp: what every scene description shares: the list of the
// five, and the shape formulas (volume, inertia at uniform density, lowest
// point) that the engines without their own use.
#include "scene_spec.h"

#include <cmath>
#include <numbers>

namespace karma::scenes {

std::vector<SceneSpec> AnchorSpecs() { return {CarSpec(), ToppleSpec(), Stack21Spec(), RagdollSpec(), Pile1000Spec()}; }

double ShapeVolume(const ShapeSpec &s) {
  constexpr double pi = std::numbers::pi;
  switch (s.kind) {
    case ShapeKind::kBox:
      return s.a * s.b * s.c;
    case ShapeKind::kSphere:
      return 4.0 / 3 * pi * s.a * s.a * s.a;
    case ShapeKind::kCapsule:
      return pi * s.a * s.a * s.b + 4.0 / 3 * pi * s.a * s.a * s.a;
  }
  return 0;
}

Vec3 UniformInertia(const ShapeSpec &s, double mass) {
  switch (s.kind) {
    case ShapeKind::kBox: {
      const double k = mass / 12;
      return {k * (s.b * s.b + s.c * s.c), k * (s.a * s.a + s.c * s.c), k * (s.a * s.a + s.b * s.b)};
    }
    case ShapeKind::kSphere: {
      const double i = 0.4 * mass * s.a * s.a;
      return {i, i, i};
    }
    case ShapeKind::kCapsule: {
      const double r = s.a, h = s.b;
      const double cylinder = r * r * h, caps = 4.0 / 3 * r * r * r;  // volumes over pi
      const double mc = mass * cylinder / (cylinder + caps), ms = mass - mc;
      const double side = mc * (h * h / 12 + r * r / 4) + ms * (0.4 * r * r + h * h / 4 + 3 * h * r / 8);
      return {side, side, mc * r * r / 2 + ms * 0.4 * r * r};
    }
  }
  return {0, 0, 0};
}

double LowestPoint(const ShapeSpec &s, const Vec3 &position, const Axes &axes) {
  // A body-frame vector b reaches sum_k b_k axes[k][1] in world y.
  switch (s.kind) {
    case ShapeKind::kBox:
      return position[1] -
             (s.a / 2 * std::fabs(axes[0][1]) + s.b / 2 * std::fabs(axes[1][1]) + s.c / 2 * std::fabs(axes[2][1]));
    case ShapeKind::kSphere:
      return position[1] - s.a;
    case ShapeKind::kCapsule:
      return position[1] - s.b / 2 * std::fabs(axes[2][1]) - s.a;
  }
  return position[1];
}

}  // namespace karma::scenes
