// CarTerrain's behaviour, through the simulation library (no viewer):
// over the scripted 20 s drive across terrain2 the car stays on top of the
// terrain and finite, and it actually gets somewhere; the per-contact
// callback gives every wheel contact a friction direction along the tyre.
// One drive, one TEST (each TEST runs in its own process under ctest).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "carterrain.h"

namespace {

// How far a wheel's lowest point (centre minus radius) or a chassis corner
// may be below the terrain height under it. Contacts are soft (epsilon
// 0.001) and corrected a fraction gamma per step: standing, a loaded wheel
// sits about 3 mm into the ground; driving over the hills at 6 m/s the
// impacts push a wheel up to about 16 mm in before the correction lifts it
// out. (On a slope the test errs the safe way: a sphere resting on it has
// its lowest point above the terrain under its centre.)
constexpr double kSinkTolerance = 0.025;  // m
constexpr int kSteps = 20 * 60;           // 20 s at CAR_STEP = 1/60 s

bool Finite(const MeReal *v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite((double)v[i])) return false;
  return true;
}

struct Drive {
  double worstWheelSink = -1e9;    // max over steps and wheels of terrain - lowest point
  double worstChassisSink = -1e9;  // max over steps and corners of terrain - corner
  bool finite = true;
  double restSink = -1e9;  // the same, standing still before the throttle (t = 0.85 s)
  double distance = 0, farthest = 0, topSpeed = 0, lowestUp = 1;
  long contacts = 0;
  double worstDirectionDot = 0;
  int stepsRun = 0;
};

Drive RunDrive(int steps) {
  Drive d;
  CarTerrain car;
  EXPECT_EQ(CarTerrainCreate(&car, "terrain2"), 1);
  if (!car.universe) return d;
  MeVector3 start;
  MdtBodyGetPosition(car.chassisBody, start);
  for (int s = 0; s < steps; ++s) {
    CarTerrainScript(&car);
    CarTerrainStep(&car);
    d.stepsRun = s + 1;
    for (int i = 0; i < CAR_WHEELS; ++i) {
      MeVector3 p, v, w;
      MdtBodyGetPosition(car.wheelBody[i], p);
      MdtBodyGetLinearVelocity(car.wheelBody[i], v);
      MdtBodyGetAngularVelocity(car.wheelBody[i], w);
      d.finite = d.finite && Finite(p, 3) && Finite(v, 3) && Finite(w, 3);
      const double ground = (double)HeightFieldHeightAt(&car.terrain, p[0], p[2]);
      const double sink = ground - ((double)p[1] - (double)CAR_WHEEL_RADIUS);
      if (s == 50) d.restSink = std::max(d.restSink, sink);
      d.worstWheelSink = std::max(d.worstWheelSink, sink);
    }
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(car.chassisBody);
    d.finite = d.finite && Finite(&tm[0][0], 16);
    for (int c = 0; c < 8; ++c) {
      const double l[3] = {(c & 1 ? 0.5 : -0.5) * (double)CAR_CHASSIS_LENGTH,
                           (c & 2 ? 0.5 : -0.5) * (double)CAR_CHASSIS_HEIGHT,
                           (c & 4 ? 0.5 : -0.5) * (double)CAR_CHASSIS_WIDTH};
      double w[3];
      for (int j = 0; j < 3; ++j) w[j] = l[0] * tm[0][j] + l[1] * tm[1][j] + l[2] * tm[2][j] + tm[3][j];
      const double ground = (double)HeightFieldHeightAt(&car.terrain, (MeReal)w[0], (MeReal)w[2]);
      d.worstChassisSink = std::max(d.worstChassisSink, ground - w[1]);
    }
    d.lowestUp = std::min(d.lowestUp, (double)tm[1][1]);
    d.farthest = std::max(d.farthest, std::hypot((double)(tm[3][0] - start[0]), (double)(tm[3][2] - start[2])));
    d.topSpeed = std::max(d.topSpeed, (double)CarTerrainForwardSpeed(&car));
    if (!d.finite) break;
  }
  d.distance = car.distance;
  d.contacts = car.wheelContacts;
  d.worstDirectionDot = car.worstDirectionDot;
  CarTerrainDestroy(&car);
  return d;
}

}  // namespace

TEST(CarTerrain, TwentySecondsOnTheTerrainWithoutSinkingOrNaNAndGetsSomewhere) {
  const Drive d = RunDrive(kSteps);
  std::printf(
      "[ figures  ] carterrain 20 s: path %.1f m, farthest %.1f m from the start, top speed %.2f "
      "m/s; wheel sink at rest %.2f mm, worst %.2f mm; worst chassis corner %.2f m above the "
      "terrain; lowest chassis up-axis y %.3f; %ld wheel contacts, worst |dir.n| or "
      "|dir.hinge| %.2g\n",
      d.distance, d.farthest, d.topSpeed, d.restSink * 1000, d.worstWheelSink * 1000, -d.worstChassisSink, d.lowestUp,
      d.contacts, d.worstDirectionDot);
  EXPECT_EQ(d.stepsRun, kSteps);
  EXPECT_TRUE(d.finite) << "NaN or infinity after step " << d.stepsRun;
  EXPECT_LT(d.worstWheelSink, kSinkTolerance) << "a wheel sank into the terrain";
  EXPECT_LT(d.worstChassisSink, kSinkTolerance) << "the chassis went into the terrain";
  EXPECT_GT(d.lowestUp, 0.7) << "the car tipped over";
  // 17 s of throttle 0.5 (a 6 m/s target) minus the run-up: well over 60 m
  // of path; the left turn (radius about 14 m) takes it round a loop, about
  // 30 m across, and back near the start.
  EXPECT_GT(d.distance, 60.0);
  EXPECT_GT(d.farthest, 15.0);
  EXPECT_GT(d.topSpeed, 4.5);
  EXPECT_LT(d.topSpeed, 8.0) << "far faster than the throttle asks for (downhill it may run a little ahead)";
  // The per-contact callback: four wheels touching nearly all the time, so
  // about 4 contacts a step, each given the direction normal x hinge,
  // perpendicular to both.
  EXPECT_GT(d.contacts, 3 * kSteps);
  EXPECT_LT(d.worstDirectionDot, 1e-3);
}
