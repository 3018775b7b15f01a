// guide_values_test.cpp: the guide's values that the tutorials do not use
// as printed (issue 19, item 4), measured, so that each tutorial README's
// figure is the engine's behaviour and not a guess:
//   - CarTerrain's epsilon: the guide's default 0.01 against the tutorial's
//     0.001, as the depth a standing wheel sinks into the ground;
//   - Ballman's VISCOCITY: the guide's slip 0.3 against the tutorial's 0.05,
//     as how far the doll gets from the stairs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ballman_sim.h"
#include "carterrain.h"

namespace {

// The deepest a wheel's lowest point is below the terrain after `seconds`
// standing still (no script: no throttle), with the world's epsilon set to
// `epsilon` right after the car is built.
double StandingWheelSink(MeReal epsilon, double seconds) {
  CarTerrain car;
  EXPECT_EQ(CarTerrainCreate(&car, "terrain2"), 1);
  if (!car.universe) return -1;
  MdtWorldSetEpsilon(car.universe->world, epsilon);
  for (int s = 0; s < (int)std::lround(seconds / (double)CAR_STEP); ++s) CarTerrainStep(&car);
  double sink = -1e9;
  for (int i = 0; i < CAR_WHEELS; ++i) {
    MeVector3 p;
    MdtBodyGetPosition(car.wheelBody[i], p);
    const double ground = (double)HeightFieldHeightAt(&car.terrain, p[0], p[2]);
    sink = std::fmax(sink, ground - ((double)p[1] - (double)CAR_WHEEL_RADIUS));
  }
  CarTerrainDestroy(&car);
  return sink;
}

// A rigid row of softness epsilon, its error corrected a fraction gamma per
// step h, settles where gamma * d / h = epsilon * h * F: d = epsilon h^2 F /
// gamma (constraint.h's row equation). F: one wheel's static load.
double PredictedSink(double epsilon) {
  const double h = (double)CAR_STEP, gamma = 0.2, load = (double)CAR_WHEEL_LOAD;
  return epsilon * h * h * load / gamma;
}

}  // namespace

TEST(GuideValues, CarTerrainEpsilon) {
  const double atDefault = StandingWheelSink((MeReal)0.01, 2);
  const double atTutorial = StandingWheelSink(CAR_EPSILON, 2);
  std::printf(
      "CarTerrain standing 2 s: a wheel sinks %.1f mm at epsilon 0.01 (predicted %.1f), "
      "%.1f mm at %g (predicted %.1f)\n",
      atDefault * 1e3, PredictedSink(0.01) * 1e3, atTutorial * 1e3, (double)CAR_EPSILON,
      PredictedSink((double)CAR_EPSILON) * 1e3);
  EXPECT_NEAR(atDefault, PredictedSink(0.01), 0.3 * PredictedSink(0.01));
  EXPECT_NEAR(atTutorial, PredictedSink((double)CAR_EPSILON), 0.3 * PredictedSink(0.01));
  EXPECT_GT(atDefault, 8 * atTutorial);
}

namespace {

// Where the doll's torso is after `frames` frames of the cheap materials
// with slip `slip` on every pair (the tutorial sets kBallmanViscosity).
void CheapDollAfter(MeReal slip, int frames, MeVector3 torso) {
  Ballman *b = BallmanCreate();
  ASSERT_NE(b, nullptr);
  const MstMaterialID m[3] = {b->dollMaterial, b->stairMaterial, b->boxMaterial};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      MdtContactParamsSetSlip(MstBridgeGetContactParams(b->universe->bridge, m[i], m[j]), slip);
  for (int f = 0; f < frames; ++f) BallmanStep(b);
  BallmanTorsoPosition(b, torso);
  BallmanDestroy(b);
}

}  // namespace

TEST(GuideValues, BallmanViscosity) {
  // 8 s: down the stairs and out onto the floor. The guide's 0.3 m/s per
  // newton against the tutorial's 0.05, and 0.3 scaled by one step (slip
  // read as velocity per unit impulse, 0.3 h).
  MeVector3 guide, tutorial, perImpulse;
  CheapDollAfter((MeReal)0.3, 480, guide);
  CheapDollAfter(kBallmanViscosity, 480, tutorial);
  CheapDollAfter((MeReal)0.3 * kBallmanStep, 480, perImpulse);
  std::printf(
      "Ballman cheap friction, torso after 8 s: slip 0.3 at x = %.2f m, slip %.2f at x = "
      "%.2f m, slip 0.3 h at x = %.2f m\n",
      (double)guide[0], (double)kBallmanViscosity, (double)tutorial[0], (double)perImpulse[0]);
  EXPECT_GT(guide[0], tutorial[0] + 1);
}
