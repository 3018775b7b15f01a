/* Tolerances.h: how close is close enough, and every default in one place.
 *
 * docs/GOLDEN.md documents these numbers and the reasons for them; change
 * both together (the golden.docs-defaults test checks that the text of
 * `karma-golden defaults` appears in docs/GOLDEN.md). */
#ifndef KARMA_GOLDEN_TOLERANCES_H
#define KARMA_GOLDEN_TOLERANCES_H

#include <karma/golden/Precision.h>
#include <karma/golden/Trajectory.h>

#include <array>
#include <cmath>
#include <optional>

namespace karma::golden {

/* A value `actual` matches `expected` when
 *   |actual - expected| <= absolute + relative * |expected|.
 * Equal values (including equal infinities) always match; a NaN matches only
 * a NaN. */
struct Tolerance {
  double absolute = 0.0;
  double relative = 0.0;

  double Allowed(double expected) const noexcept { return absolute + relative * std::fabs(expected); }
  bool Accepts(double actual, double expected) const noexcept {
    if (actual == expected) return true;
    if (std::isnan(actual) || std::isnan(expected)) return std::isnan(actual) && std::isnan(expected);
    return std::fabs(actual - expected) <= Allowed(expected);
  }
};

/* One tolerance per quantity class. Quaternions are compared up to sign. */
struct TrajectoryTolerances {
  std::array<Tolerance, kQuantityCount> byQuantity{};

  Tolerance &operator[](Quantity q) noexcept { return byQuantity[static_cast<int>(q)]; }
  const Tolerance &operator[](Quantity q) const noexcept { return byQuantity[static_cast<int>(q)]; }
};

/* Per-field overrides (from command-line flags) applied on top of defaults. */
struct TrajectoryToleranceOverrides {
  std::array<std::optional<double>, kQuantityCount> absolute{};
  std::array<std::optional<double>, kQuantityCount> relative{};

  TrajectoryTolerances ApplyTo(TrajectoryTolerances tolerances) const noexcept {
    for (int i = 0; i < kQuantityCount; ++i) {
      if (absolute[i]) tolerances.byQuantity[i].absolute = *absolute[i];
      if (relative[i]) tolerances.byQuantity[i].relative = *relative[i];
    }
    return tolerances;
  }
};

/* Image comparison: a pixel differs when any channel (R, G, B, A) differs by
 * more than channelTolerance (0..255); the images match when the fraction of
 * differing pixels is at most maxDifferingFraction. */
struct ImageTolerances {
  int channelTolerance = 0;
  double maxDifferingFraction = 0.0;
};

/* ---- The defaults. ---------------------------------------------------- */

/* Trajectories, by the precision of the expected (golden) file. Units: metres,
 * unit quaternion components, m/s, rad/s. */
constexpr TrajectoryTolerances DefaultTrajectoryTolerances(Precision precision) noexcept {
  TrajectoryTolerances t;
  if (precision == Precision::Single) {
    t.byQuantity[0] = {1e-4, 1e-4}; /* position */
    t.byQuantity[1] = {1e-4, 0.0};  /* quaternion */
    t.byQuantity[2] = {1e-3, 1e-4}; /* linear velocity */
    t.byQuantity[3] = {1e-3, 1e-4}; /* angular velocity */
  } else {
    t.byQuantity[0] = {1e-9, 1e-9};
    t.byQuantity[1] = {1e-9, 0.0};
    t.byQuantity[2] = {1e-8, 1e-9};
    t.byQuantity[3] = {1e-8, 1e-9};
  }
  return t;
}

inline constexpr ImageTolerances kDefaultImageTolerances{8, 0.005};

}  // namespace karma::golden

#endif
