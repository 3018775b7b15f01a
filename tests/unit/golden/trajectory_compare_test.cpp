/* CompareTrajectories: match, within tolerance, beyond tolerance, quaternion
 * sign, header mismatches, and the text report. */
#include "GoldenTestSupport.h"

#include <karma/golden/StateHash.h>
#include <karma/golden/Tolerances.h>
#include <karma/golden/TrajectoryCompare.h>
#include <karma/golden/TrajectoryReader.h>
#include <karma/golden/TrajectoryWriter.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace kg = karma::golden;
namespace ts = karma::golden::test_support;

namespace {

const kg::TrajectoryTolerances kTol = kg::DefaultTrajectoryTolerances(kg::kBuildPrecision);

bool StartsWith(const std::string &s, const std::string &prefix) { return s.rfind(prefix, 0) == 0; }

/* A trajectory as it would come back from a file: written and read again. */
kg::Trajectory ThroughFile(const kg::Trajectory &t) {
  std::ostringstream out;
  kg::WriteTrajectory(out, t);
  std::istringstream in(out.str());
  return kg::ReadTrajectory(in, "memory");
}

}  // namespace

TEST(TrajectoryCompare, IdenticalRunsMatch) {
  const kg::Trajectory a = ThroughFile(ts::SyntheticTrajectory());
  const kg::Trajectory b = ThroughFile(ts::SyntheticTrajectory());
  EXPECT_EQ(kg::HashTrajectory(a), kg::HashTrajectory(b));
  EXPECT_EQ(a.finalHash, b.finalHash);
  const kg::TrajectoryComparison c = kg::CompareTrajectories(a, b, kTol);
  EXPECT_TRUE(c.passed);
  EXPECT_TRUE(c.hashesMatch);
  EXPECT_EQ(c.expectedHash, c.actualHash);
  EXPECT_TRUE(c.headerMismatches.empty());
  EXPECT_TRUE(c.notes.empty());
  EXPECT_FALSE(c.firstFailure.has_value());
  EXPECT_EQ(c.failingValues, 0);
  EXPECT_EQ(c.comparedValues, ts::kSyntheticFrames * ts::kSyntheticBodies * 13);
  EXPECT_TRUE(StartsWith(c.verdict, "MATCH")) << c.verdict;
  EXPECT_NE(c.verdict.find(kg::FormatHash(c.actualHash)), std::string::npos) << c.verdict;
}

TEST(TrajectoryCompare, PerturbationBeyondToleranceFails) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory actual = expected;
  double &y = actual.frames[3].bodies[1].position[1];
  const double original = y;
  y = ts::Real(y + 0.01);

  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, actual, kTol);
  EXPECT_FALSE(c.passed);
  EXPECT_FALSE(c.hashesMatch);
  EXPECT_TRUE(c.headerMismatches.empty());
  EXPECT_EQ(c.failingValues, 1);
  ASSERT_TRUE(c.firstFailure.has_value());
  const kg::ValueDifference &f = *c.firstFailure;
  EXPECT_EQ(f.frame, ts::kSyntheticFrameIndex[3]);
  EXPECT_EQ(f.body, 1);
  EXPECT_EQ(f.quantity, kg::Quantity::Position);
  EXPECT_EQ(f.component, 1);
  EXPECT_EQ(f.expected, original);
  EXPECT_EQ(f.actual, y);
  EXPECT_NEAR(f.difference, 0.01, 1e-5);
  EXPECT_DOUBLE_EQ(f.allowed, kTol[kg::Quantity::Position].Allowed(original));
  EXPECT_TRUE(StartsWith(c.verdict, "FAIL")) << c.verdict;

  ASSERT_EQ(c.deviations.size(), static_cast<std::size_t>(ts::kSyntheticBodies));
  const int pos = static_cast<int>(kg::Quantity::Position);
  EXPECT_NEAR(c.deviations[1].maxDifference[pos], 0.01, 1e-5);
  EXPECT_EQ(c.deviations[1].atFrame[pos], ts::kSyntheticFrameIndex[3]);
  EXPECT_FALSE(c.deviations[1].withinTolerance[pos]);
  EXPECT_TRUE(c.deviations[1].withinTolerance[static_cast<int>(kg::Quantity::Quaternion)]);
  EXPECT_EQ(c.deviations[0].maxDifference[pos], 0.0);
  EXPECT_TRUE(c.deviations[0].withinTolerance[pos]);

  const std::string report = kg::ReportText(c, "golden.txt", "run.txt");
  const std::string frame = "frame " + std::to_string(ts::kSyntheticFrameIndex[3]);
  EXPECT_NE(report.find(frame), std::string::npos) << report;
  EXPECT_NE(report.find("body 1"), std::string::npos) << report;
  EXPECT_NE(report.find("pos.y"), std::string::npos) << report;
  EXPECT_NE(report.find("golden.txt"), std::string::npos) << report;
  EXPECT_NE(report.find("run.txt"), std::string::npos) << report;
  EXPECT_NE(report.find("verdict: FAIL"), std::string::npos) << report;
}

TEST(TrajectoryCompare, PerturbationWithinTolerancePassesWithDifferentHashes) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory actual = expected;
  double &v = actual.frames[2].bodies[2].position[0];
  /* Half the allowed deviation for the build precision's defaults. */
  const double delta = 0.5 * kTol[kg::Quantity::Position].Allowed(v);
  const double original = v;
  v = ts::Real(v + delta);
  ASSERT_NE(v, original) << "the perturbation vanished in rounding";

  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, actual, kTol);
  EXPECT_TRUE(c.passed) << c.verdict;
  EXPECT_FALSE(c.hashesMatch);
  EXPECT_NE(c.expectedHash, c.actualHash);
  EXPECT_EQ(c.failingValues, 0);
  EXPECT_TRUE(StartsWith(c.verdict, "PASS")) << c.verdict;
  ASSERT_EQ(c.deviations.size(), static_cast<std::size_t>(ts::kSyntheticBodies));
  EXPECT_GT(c.deviations[2].maxDifference[0], 0.0);
  EXPECT_LE(c.deviations[2].maxDifference[0], kTol[kg::Quantity::Position].Allowed(original));

  /* Tightening the tolerance below the deviation makes it fail. */
  kg::TrajectoryToleranceOverrides tighter;
  tighter.absolute[0] = 0.0;
  tighter.relative[0] = 0.0;
  const kg::TrajectoryComparison strict = kg::CompareTrajectories(expected, actual, tighter.ApplyTo(kTol));
  EXPECT_FALSE(strict.passed);
}

TEST(TrajectoryCompare, QuaternionSignFlipPasses) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory actual = expected;
  for (kg::TrajectoryFrame &f : actual.frames)
    for (double &q : f.bodies[1].quaternion) q = -q;
  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, actual, kTol);
  EXPECT_TRUE(c.passed) << c.verdict;
  EXPECT_FALSE(c.hashesMatch);
  EXPECT_EQ(c.failingValues, 0);
  EXPECT_EQ(c.deviations[1].maxDifference[static_cast<int>(kg::Quantity::Quaternion)], 0.0);

  /* Negating only one component is a different rotation and fails. */
  kg::Trajectory bad = expected;
  bad.frames[0].bodies[1].quaternion[0] = -bad.frames[0].bodies[1].quaternion[0];
  EXPECT_FALSE(kg::CompareTrajectories(expected, bad, kTol).passed);
}

TEST(TrajectoryCompare, BodyCountMismatchFails) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory actual = expected;
  actual.header.bodyCount = 2;
  for (kg::TrajectoryFrame &f : actual.frames) f.bodies.pop_back();
  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, actual, kTol);
  EXPECT_FALSE(c.passed);
  ASSERT_FALSE(c.headerMismatches.empty());
  EXPECT_NE(c.headerMismatches.front().find("body count"), std::string::npos) << c.headerMismatches.front();
  EXPECT_TRUE(StartsWith(c.verdict, "FAIL")) << c.verdict;
  EXPECT_NE(c.verdict.find("body"), std::string::npos) << c.verdict;
  const std::string report = kg::ReportText(c, "e", "a");
  EXPECT_NE(report.find("header mismatch: body count"), std::string::npos) << report;
}

TEST(TrajectoryCompare, DifferentFrameSetFails) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory dropped = expected;
  dropped.frames.erase(dropped.frames.begin() + 2);
  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, dropped, kTol);
  EXPECT_FALSE(c.passed);
  ASSERT_EQ(c.headerMismatches.size(), 1u);
  EXPECT_NE(c.headerMismatches[0].find("frame set"), std::string::npos) << c.headerMismatches[0];
  EXPECT_TRUE(StartsWith(c.verdict, "FAIL")) << c.verdict;

  /* Same number of frames, one index different. */
  kg::Trajectory shifted = expected;
  shifted.frames.back().index += 1;
  const kg::TrajectoryComparison s = kg::CompareTrajectories(expected, shifted, kTol);
  EXPECT_FALSE(s.passed);
  ASSERT_EQ(s.headerMismatches.size(), 1u);
  EXPECT_NE(s.headerMismatches[0].find("frame set"), std::string::npos);
}

TEST(TrajectoryCompare, OtherHeaderFieldsAndBackendNote) {
  const kg::Trajectory expected = ts::SyntheticTrajectory();
  kg::Trajectory program = expected;
  program.header.program = "other";
  EXPECT_FALSE(kg::CompareTrajectories(expected, program, kTol).passed);

  kg::Trajectory step = expected;
  step.header.timeStep = ts::Real(1.0 / 30.0);
  EXPECT_FALSE(kg::CompareTrajectories(expected, step, kTol).passed);

  /* A different backend is only a note. */
  /* (Through a file, so the recorded hashes are consistent and add no note.) */
  kg::Trajectory backend = expected;
  backend.header.backend = "simd";
  const kg::TrajectoryComparison c = kg::CompareTrajectories(ThroughFile(expected), ThroughFile(backend), kTol);
  EXPECT_TRUE(c.passed);
  EXPECT_TRUE(c.hashesMatch);
  EXPECT_TRUE(c.headerMismatches.empty());
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_NE(c.notes[0].find("backend"), std::string::npos) << c.notes[0];
}

TEST(TrajectoryCompare, InconsistentRecordedHashesAreNoted) {
  kg::Trajectory edited = ThroughFile(ts::SyntheticTrajectory());
  edited.frames[1].bodies[0].linearVelocity[0] = ts::Real(edited.frames[1].bodies[0].linearVelocity[0] + 0.5);
  const kg::TrajectoryComparison c = kg::CompareTrajectories(ThroughFile(ts::SyntheticTrajectory()), edited, kTol);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.actualHash, kg::HashTrajectory(edited));
  EXPECT_NE(c.actualHash, edited.finalHash);
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_NE(c.notes[0].find("actual file's recorded hashes"), std::string::npos) << c.notes[0];
}
