// car_spec.cpp: SCENES.md's "car": a 150 kg chassis on four 10 kg sphere
// wheels joined by car-wheel joints, rear wheels driven by 100 N m each.
//
// Rolling without slip, the car accelerates at
//   a = (2T/r) / (M + 4 I_w / r^2),  I_w = 2/5 m_w r^2,
// = (200/0.3) / (190 + 16) = 3.236 m/s^2: v(5 s) = 16.18 m/s, x(5 s) = 40.45 m.
// The static sag is the load per wheel over k: (150 g / 4) / 20000 = 18.4 mm.
#include "scene_spec.h"

namespace karma::scenes {

SceneSpec CarSpec() {
  SceneSpec s;
  s.name = "car";
  s.steps = 300;
  // Ground 0.4; the wheels' 1.0 is the larger, so it applies at the tyres.
  s.friction = {0.4, 0.4, 1.0};
  s.groundMaterial = 0;
  const int chassisMaterial = 1, wheelMaterial = 2;
  s.bodies.push_back({{ShapeKind::kBox, 1.6, 0.4, 0.8}, 150, {0, 0.6, 0}, kIdentityAxes, chassisMaterial});
  for (int i = 0; i < 4; ++i) {
    const double x = (i & 1) ? 0.6 : -0.6, z = (i & 2) ? 0.5 : -0.5;
    const int wheel = 1 + i;
    s.bodies.push_back({{ShapeKind::kSphere, 0.3, 0, 0}, 10, {x, 0.3, z}, kIdentityAxes, wheelMaterial});
    s.disabledPairs.push_back({0, wheel});
    for (int j = 0; j < i; ++j) s.disabledPairs.push_back({wheel, 1 + j});
    s.carWheels.push_back({0, wheel, {x, 0.3, z}, {0, 1, 0}, {0, 0, 1}, 20000, 500, -0.2, 0.2});
    if (x < 0) s.drives.push_back({i, -100});  // rear wheels, toward +x
  }
  s.expectation = Expectation::kCarRolls;
  s.watched = {0};
  s.carAcceleration = (2 * 100 / 0.3) / (190 + 4 * (0.4 * 10 * 0.09) / 0.09);
  s.capacity = {8, 8, 32, 64};
  return s;
}

}  // namespace karma::scenes
