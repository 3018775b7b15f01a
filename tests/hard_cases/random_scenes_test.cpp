// Random scenes: boxes, spheres, capsules and convex hulls of random sizes
// (0.1 to 1 m) and masses (0.1 to 100 kg, three orders of magnitude),
// dropped on the ground, some joined by ball or hinge joints (between bodies
// within 100:1 of each other's mass). For every
// seed, over 3 s at 1/60 s:
//   - every state stays finite;
//   - no body is lost below the ground (centre of mass above -0.05 m);
//   - the total energy (kinetic + potential, from the ground) never exceeds
//     its start by more than 10% (contacts and joints may only take energy
//     away; 10% leaves room for the position correction of joints and
//     penetrations).
// KARMA_RANDOM_SEEDS sets the seed count (default 200, about 20 s in CI);
// a longer run is one command:
//   KARMA_RANDOM_SEEDS=5000 build/release/tests/hard_cases/hard_cases_random_test
// and KARMA_RANDOM_SEED_FIRST (default 1) where the seeds start, so that
// one failing seed reruns alone:
//   KARMA_RANDOM_SEED_FIRST=586 KARMA_RANDOM_SEEDS=1 build/release/tests/hard_cases/hard_cases_random_test
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene_support.h"

using namespace hard;

namespace {

// A small deterministic generator (splitmix64), the same on every platform.
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * (double)(next() >> 11) * 0x1.0p-53; }
  double logUniform(double lo, double hi) { return lo * std::pow(hi / lo, uniform(0, 1)); }
  int below(int n) { return (int)(next() % (uint64_t)n); }
};

// Joints join bodies within this mass ratio of each other: beyond it the
// joint error at the default epsilon is a known limit, measured on its own
// by HangingChain1000To1Holds (docs/STABILITY.md).
constexpr double kJointMassRatio = 100;

const char *const kShapeNames[] = {"box", "sphere", "capsule", "hull"};

McdGeometryID randomGeometry(McdFrameworkID fw, Rng &r, double size, double *halfHeight, int *shape) {
  *shape = r.below(4);
  switch (*shape) {
    case 0: {
      const double sx = size, sy = size * r.uniform(0.3, 1), sz = size * r.uniform(0.3, 1);
      *halfHeight = std::max(sx, std::max(sy, sz));
      return McdBoxCreate(fw, (MeReal)sx, (MeReal)sy, (MeReal)sz);
    }
    case 1:
      *halfHeight = size / 2;
      return McdSphereCreate(fw, (MeReal)(size / 2));
    case 2:
      *halfHeight = size;
      return McdSphylCreate(fw, (MeReal)(size / 4), (MeReal)(size));
    default: {
      MeVector3 v[12];
      for (auto &p : v)
        for (int k = 0; k < 3; ++k) p[k] = (MeReal)(size * r.uniform(-0.5, 0.5));
      // Guarantee volume: the corners of a tetrahedron.
      const double a = size / 3;
      MeVector3Set(v[0], (MeReal)a, 0, 0);
      MeVector3Set(v[1], 0, (MeReal)a, 0);
      MeVector3Set(v[2], 0, 0, (MeReal)a);
      MeVector3Set(v[3], (MeReal)-a, (MeReal)-a, (MeReal)-a);
      *halfHeight = size;
      return McdConvexMeshCreateHull(fw, v, 12, 0);
    }
  }
}

struct SeedResult {
  std::string scene;  // one line per body and joint, for a failure message
  bool finite = true;
  double lowest = 1e9;
  double energyGrowth = 0;  // (max E - E0) / E0
};

SeedResult runSeed(uint64_t seed) {
  SeedResult res;
  Rng r(seed);
  Universe U;
  MdtWorldSetAutoDisable(U.world(), TRUE);
  std::vector<MdtBodyID> bodies;
  const int n = 4 + r.below(9);
  double y = 0;
  for (int i = 0; i < n; ++i) {
    const double size = r.logUniform(0.1, 1);
    double hh = 0;
    int shape = 0;
    McdGeometryID g = randomGeometry(U.u->frame, r, size, &hh, &shape);
    if (!g) continue;
    y += hh + 0.05;
    McdModelID m = MstModelAndBodyCreate(U.u, g, 1);
    MdtBodyID b = bodyOf(m);
    MdtBodySetMass(b, (MeReal)r.logUniform(0.1, 100));
    MstAutoSetMassProperties(b, g, MdtBodyGetMass(b) / (MeReal)(size * size * size));
    MdtBodySetMass(b, MdtBodyGetMass(b));
    MdtBodySetPosition(b, (MeReal)r.uniform(-0.3, 0.3), (MeReal)y, (MeReal)r.uniform(-0.3, 0.3));
    MdtBodySetQuaternion(b, (MeReal)r.uniform(-1, 1), (MeReal)r.uniform(-1, 1), (MeReal)r.uniform(-1, 1),
                         (MeReal)r.uniform(-1, 1));
    y += hh;
    char line[160];
    std::snprintf(line, sizeof line, "\n  body %zu: %s size %.3f m, mass %.3g kg, at y %.2f", bodies.size(),
                  kShapeNames[shape], size, (double)MdtBodyGetMass(b), y - hh);
    res.scene += line;
    if (!bodies.empty() && r.below(3) == 0) {
      const int otherIndex = r.below((int)bodies.size());
      MdtBodyID other = bodies[(size_t)otherIndex];
      MeVector3 p0, p1;
      MdtBodyGetPosition(b, p0);
      MdtBodyGetPosition(other, p1);
      const bool ball = r.below(2) == 0;
      const double ratio = (double)MdtBodyGetMass(b) / (double)MdtBodyGetMass(other);
      const bool join = ratio <= kJointMassRatio && ratio >= 1 / kJointMassRatio;
      std::snprintf(line, sizeof line, ", %s joint to body %d%s", ball ? "ball" : "hinge", otherIndex,
                    join ? "" : " (skipped: mass ratio)");
      res.scene += line;
      if (join && ball) {
        MdtBSJointID j = MdtBSJointCreate(U.world());
        MdtBSJointSetBodies(j, b, other);
        MdtBSJointSetPosition(j, (p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2, (p0[2] + p1[2]) / 2);
        MdtBSJointEnable(j);
      } else if (join) {
        MdtHingeID j = MdtHingeCreate(U.world());
        MdtHingeSetBodies(j, b, other);
        MdtHingeSetPosition(j, (p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2, (p0[2] + p1[2]) / 2);
        MdtHingeSetAxis(j, 1, 0, 0);
        MdtHingeEnable(j);
      }
    }
    bodies.push_back(b);
  }
  auto energy = [&] {
    double e = 0;
    for (MdtBodyID b : bodies) {
      const double m = MdtBodyGetMass(b);
      MeVector3 v, w, x;
      MdtBodyGetLinearVelocity(b, v);
      MdtBodyGetAngularVelocity(b, w);
      MdtBodyGetCenterOfMassPosition(b, x);
      MeMatrix3 I;
      MdtBodyGetInertiaTensor(b, I);
      const double ww[3] = {w[0], w[1], w[2]};
      double wb[3];
      toBody(b, ww, wb);
      double rot = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rot += wb[i] * I[i][j] * wb[j];
      e += 0.5 * m * MeVector3Dot(v, v) + 0.5 * rot + m * kG * x[1];
    }
    return e;
  };
  const double E0 = energy();
  for (int s = 0; s < 180; ++s) {
    U.step(1.0 / 60);
    for (MdtBodyID b : bodies) {
      if (!bodyFinite(b)) res.finite = false;
      MeVector3 x;
      MdtBodyGetCenterOfMassPosition(b, x);
      res.lowest = std::min(res.lowest, (double)x[1]);
    }
    res.energyGrowth = std::max(res.energyGrowth, (energy() - E0) / E0);
  }
  return res;
}

bool Bounded(const SeedResult &r) { return r.finite && r.lowest > -0.05 && r.energyGrowth < 0.1; }

}  // namespace

// Seeds beyond the default 200 whose scenes ran away (energy growth from
// 0.11 to 7e24, bodies thrown kilometres) while the geometric stiffness was
// unbounded. Joints take part in each (277, 586 and 1138 stay bounded with
// their joints left out); in 586 a ball joint ties a light hull to a capsule
// with two bodies stacked between them. The bound in integrate.cpp (kMaxGeometricStiffness)
// holds them; 1138 and 4606 run away again under a bound of 100.
TEST(HardCases, RandomScenesThatRanAwayStayBounded) {
  for (uint64_t seed : {277, 586, 1138, 1535, 2454, 2553, 3196, 4606}) {
    const SeedResult r = runSeed(seed);
    EXPECT_TRUE(Bounded(r)) << "seed " << seed << ": finite " << r.finite << ", lowest centre " << r.lowest
                            << " m, energy growth " << r.energyGrowth << r.scene;
  }
}

TEST(HardCases, RandomScenesStayBounded) {
  int seeds = 200, first = 1;
  if (const char *s = std::getenv("KARMA_RANDOM_SEEDS")) seeds = std::max(1, std::atoi(s));
  if (const char *s = std::getenv("KARMA_RANDOM_SEED_FIRST")) first = std::max(1, std::atoi(s));
  int failures = 0;
  double worstLow = 1e9, worstGrowth = 0;
  for (int seed = first; seed < first + seeds; ++seed) {
    const SeedResult r = runSeed((uint64_t)seed);
    worstLow = std::min(worstLow, r.lowest);
    worstGrowth = std::max(worstGrowth, r.energyGrowth);
    if (!Bounded(r) && ++failures <= 10)
      ADD_FAILURE() << "seed " << seed << ": finite " << r.finite << ", lowest centre " << r.lowest
                    << " m, energy growth " << r.energyGrowth << r.scene;
  }
  std::printf(
      "[ figures  ] %d random scenes: %d failed; lowest centre %.4f m, largest energy "
      "growth %.4f\n",
      seeds, failures, worstLow, worstGrowth);
}
