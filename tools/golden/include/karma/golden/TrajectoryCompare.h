/* TrajectoryCompare.h: comparing an actual trajectory with an expected one.
 *
 * Rules:
 *   - The hashes (recomputed from the values) are compared first; equal hashes
 *     mean a bit-identical run and the comparison passes.
 *   - Header: body count, frame set (the list of sampled frame indices),
 *     program, step, precision and time step must agree, else the comparison
 *     fails. A different backend is only noted (comparing a SIMD backend with
 *     the reference golden is a legitimate use).
 *   - Values: each value must satisfy the tolerance of its quantity class with
 *     the expected file as reference (Tolerances.h). A quaternion is compared
 *     as whichever of q and -q is closer to the expected one (they are the same
 *     rotation).
 * The result carries everything the text report shows; ReportText() renders
 * it. */
#ifndef KARMA_GOLDEN_TRAJECTORYCOMPARE_H
#define KARMA_GOLDEN_TRAJECTORYCOMPARE_H

#include <karma/golden/Tolerances.h>
#include <karma/golden/Trajectory.h>

#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace karma::golden {

/* One value that is out of tolerance. */
struct ValueDifference {
  long frame = 0; /* frame index (as in the file) */
  double time = 0.0;
  int body = 0;
  Quantity quantity = Quantity::Position;
  int component = 0; /* 0..2, or 0..3 = w,x,y,z for quaternions */
  double expected = 0.0;
  double actual = 0.0; /* sign-aligned for quaternions */
  double difference = 0.0;
  double allowed = 0.0;
};

/* The largest |actual - expected| over the run, per quantity, for one body. */
struct BodyDeviation {
  std::array<double, kQuantityCount> maxDifference{};
  std::array<long, kQuantityCount> atFrame{}; /* frame index of the maximum */
  std::array<bool, kQuantityCount> withinTolerance{true, true, true, true};
};

struct TrajectoryComparison {
  bool passed = false;
  bool hashesMatch = false;
  std::uint64_t expectedHash = 0;            /* recomputed */
  std::uint64_t actualHash = 0;              /* recomputed */
  std::vector<std::string> headerMismatches; /* each fails the comparison */
  std::vector<std::string> notes;            /* informative only */
  std::optional<ValueDifference> firstFailure;
  long failingValues = 0;
  long comparedValues = 0;
  std::vector<BodyDeviation> deviations; /* one per body when the counts agree */
  TrajectoryTolerances tolerances;
  std::string verdict; /* one line, starts with MATCH, PASS or FAIL */
};

MEPUBLIC TrajectoryComparison CompareTrajectories(const Trajectory &expected, const Trajectory &actual,
                                                  const TrajectoryTolerances &tolerances);

/* Human-readable report (several lines, ending with the verdict line). */
MEPUBLIC std::string ReportText(const TrajectoryComparison &comparison, const std::string &expectedName,
                                const std::string &actualName);

}  // namespace karma::golden

#endif
