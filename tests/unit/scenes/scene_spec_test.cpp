// The engine-neutral scene descriptions (scene_spec.h): the shape formulas
// the peers use agree with Karma's own geometry, and the descriptions say
// what SCENES.md says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "anchor_scene.h"
#include "scene_spec.h"

namespace {

using namespace karma::scenes;

// UniformInertia gives ODE and Bullet the moments Karma computes from its
// geometry at density mass / volume: for every body of every scene, the
// diagonal of Karma's body-frame inertia tensor, to single precision.
TEST(SceneSpec, UniformInertiaMatchesKarmaGeometry) {
  for (const SceneSpec &spec : AnchorSpecs()) {
    if (spec.name == "pile1000") continue;  // the same cube as topple, 1000 times
    AnchorScene scene(spec);
    for (size_t i = 0; i < spec.bodies.size(); ++i) {
      const BodySpec &b = spec.bodies[i];
      MdtBodyID body = McdModelGetBody(scene.models()[i]);
      MeMatrix3 I;
      MdtBodyGetInertiaTensor(body, I);
      const Vec3 expected = UniformInertia(b.shape, b.mass);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(I[k][k], expected[k], 2e-6 * expected[k]) << spec.name << " body " << i << " axis " << k;
      EXPECT_NEAR(MdtBodyGetMass(body), b.mass, 2e-6 * b.mass);
      EXPECT_NEAR(McdGeometryGetVolume(McdModelGetGeometry(scene.models()[i])), ShapeVolume(b.shape),
                  2e-6 * ShapeVolume(b.shape));
    }
  }
}

// Closed forms: a solid sphere 2/5 m r^2; a capsule of vanishing cylinder
// is a sphere; a box (a, b, c) has m (b^2 + c^2)/12 about x.
TEST(SceneSpec, UniformInertiaClosedForms) {
  const Vec3 sphere = UniformInertia({ShapeKind::kSphere, 0.3, 0, 0}, 10);
  EXPECT_DOUBLE_EQ(sphere[0], 0.4 * 10 * 0.09);
  const Vec3 round = UniformInertia({ShapeKind::kCapsule, 0.3, 0, 0}, 10);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(round[k], sphere[k], 1e-15);
  const Vec3 box = UniformInertia({ShapeKind::kBox, 1.6, 0.4, 0.8}, 150);
  EXPECT_DOUBLE_EQ(box[0], 150 * (0.16 + 0.64) / 12);
  EXPECT_NEAR(ShapeVolume({ShapeKind::kCapsule, 0.05, 0.3, 0}),
              std::numbers::pi * 0.0025 * 0.3 + 4.0 / 3 * std::numbers::pi * 0.05 * 0.05 * 0.05, 1e-18);
}

// SCENES.md: the rag doll weighs 67 kg and, once lifted, its lowest point
// is at y = 2.
TEST(SceneSpec, RagdollWeighs67KgAndHangsFrom2m) {
  const SceneSpec spec = RagdollSpec();
  double mass = 0, lowest = 1e9;
  for (const BodySpec &b : spec.bodies) {
    mass += b.mass;
    Vec3 p = b.position;
    for (int i = 0; i < 3; ++i) p[i] += spec.offset[i];
    lowest = std::min(lowest, LowestPoint(b.shape, p, b.axes));
  }
  EXPECT_DOUBLE_EQ(mass, 67);
  EXPECT_NEAR(lowest, 2.0, 1e-12);
  EXPECT_EQ(spec.ballJoints.size(), 9u);
  EXPECT_EQ(spec.disabledPairs.size(), 45u);  // every pair of the ten parts
}

// The car's analytic acceleration from SCENES.md: 3.236 m/s^2, so 16.18 m/s
// at 5 s; two driven rear wheels.
TEST(SceneSpec, CarAnalyticAcceleration) {
  const SceneSpec spec = CarSpec();
  EXPECT_NEAR(spec.carAcceleration * 5, 16.18, 0.005);
  ASSERT_EQ(spec.drives.size(), 2u);
  for (const DriveSpec &d : spec.drives) EXPECT_LT(spec.carWheels[(size_t)d.joint].anchor[0], 0);
}

// Box counts and run lengths of SCENES.md.
TEST(SceneSpec, CountsAndLengths) {
  const std::vector<SceneSpec> specs = AnchorSpecs();
  ASSERT_EQ(specs.size(), 5u);
  const size_t bodies[5] = {5, 25, 21, 10, 1000};
  const int steps[5] = {300, 600, 1200, 600, 600};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(specs[i].bodies.size(), bodies[i]) << specs[i].name;
    EXPECT_EQ(specs[i].steps, steps[i]) << specs[i].name;
  }
}

}  // namespace
