// Pools running out: a scene that needs more contacts (constraint pool) or
// more model pairs (pair pool) than the universe was sized for. What rests
// must keep resting: nothing may fall through the ground, and the shortage
// is reported once.
#include <algorithm>

#include "scene_support.h"
#include "support/warning_capture.h"

using namespace hard;
using karma_test::WarningCapture;

namespace {

// 10 boxes on the ground, 1 m apart, with room for `constraints` contacts and
// `pairs` model pairs; returns the lowest centre height after 3 s.
double lowestAfterRest(int constraints, int pairs, size_t *warningCount) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  sizes.dynamicConstraintsMaxCount = constraints;
  sizes.collisionPairsMaxCount = pairs;
  WarningCapture warnings;
  Universe U(sizes);
  std::vector<MdtBodyID> bodies;
  for (int i = 0; i < 10; ++i) bodies.push_back(bodyOf(addBox(U, 0.5, 0.5, 0.5, 1, 2.0 * i, 0.25, 0)));
  double lowest = 1e9;
  for (int s = 0; s < 180; ++s) {
    U.step(1.0 / 60);
    for (MdtBodyID b : bodies) {
      double p[3];
      position(b, p);
      lowest = std::min(lowest, p[1]);
    }
  }
  *warningCount = warnings.count();
  return lowest;
}

}  // namespace

// Reference: pools large enough, every box stays at 0.25 m.
TEST(HardCases, PoolsLargeEnoughKeepBoxesUp) {
  size_t warnings = 0;
  const double lowest = lowestAfterRest(500, 500, &warnings);
  EXPECT_GT(lowest, 0.2);
  EXPECT_EQ(warnings, 0u);
}

// A constraint pool of 12 for 10 boxes with 4 contacts each: the world
// grows its constraint slots (constraint_slots.cpp) and says so once.
TEST(HardCases, ConstraintPoolRunningOutKeepsRestingBoxes) {
  size_t warnings = 0;
  const double lowest = lowestAfterRest(12, 500, &warnings);
  std::printf("[ figures  ] constraint pool 12 for 40 contacts: lowest box %.3f m, %zu warnings\n", lowest, warnings);
  EXPECT_GT(lowest, 0.2);
  EXPECT_LT(lowest, 0.26);
  EXPECT_EQ(warnings, 1u);
}

// A pair pool of 4 for 10 box-ground pairs: the space grows its pair
// records (farfield/pair_table.h) and says so once.
TEST(HardCases, PairPoolRunningOutKeepsRestingBoxes) {
  size_t warnings = 0;
  const double lowest = lowestAfterRest(500, 4, &warnings);
  std::printf("[ figures  ] pair pool 4 for 10 pairs: lowest box %.3f m, %zu warnings\n", lowest, warnings);
  EXPECT_GT(lowest, 0.2);
  EXPECT_LT(lowest, 0.26);
  EXPECT_EQ(warnings, 1u);
}
