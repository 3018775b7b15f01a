/* GoldenTestSupport.h: shared helpers for the golden toolkit tests: a
 * deterministic synthetic trajectory and a self-cleaning temporary directory. */
#ifndef KARMA_TESTS_GOLDEN_TESTSUPPORT_H
#define KARMA_TESTS_GOLDEN_TESTSUPPORT_H

#include <karma/MePrecision.h>
#include <karma/golden/Trajectory.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

#if defined(_WIN32)
#  include <process.h>
#  define KARMA_TEST_GETPID _getpid
#else
#  include <unistd.h>
#  define KARMA_TEST_GETPID getpid
#endif

namespace karma::golden::test_support {

inline constexpr int kSyntheticBodies = 3;
inline constexpr int kSyntheticFrames = 5;
/* Sampled frame indices: not consecutive, so the frame set matters. */
inline constexpr long kSyntheticFrameIndex[kSyntheticFrames] = {0, 10, 20, 30, 37};

/* A value exactly representable as MeReal (so the writer does not round it). */
inline double Real(double v) { return static_cast<double>(static_cast<MeReal>(v)); }

/* Body b at frame f: non-round values from a simple formula; unit quaternion. */
inline BodyState SyntheticBody(int f, int b) {
  BodyState s;
  const double t = 0.1 * f + 0.37 * b;
  s.position = {Real(1.25 + 0.731 * b + 0.0137 * f), Real(2.5 - 0.0981 * f * f + 0.21 * b),
                Real(-0.333 * b + 0.071 * f)};
  const double half = 0.5 * (0.3 + 0.17 * f + 0.41 * b);
  const double ax = 0.6, ay = 0.0, az = 0.8; /* unit axis */
  s.quaternion = {Real(std::cos(half)), Real(ax * std::sin(half)), Real(ay * std::sin(half) + 1e-3 * b),
                  Real(az * std::sin(half))};
  s.linearVelocity = {Real(0.137 * b - 0.01 * f), Real(-0.981 * t), Real(0.0421 + 0.003 * f)};
  s.angularVelocity = {Real(0.17 * std::sin(t)), Real(-0.29 * std::cos(t)), Real(0.0137 * (b + 1))};
  return s;
}

inline TrajectoryHeader SyntheticHeader() {
  TrajectoryHeader h;
  h.program = "synthetic";
  h.step = "main";
  h.backend = "reference";
  h.precision = kBuildPrecision;
  h.bodyCount = kSyntheticBodies;
  h.sampling = "frames 0 10 20 30 and the last (37)";
  h.timeStep = Real(1.0 / 60.0);
  return h;
}

/* The model (recorded hashes left 0; use HashTrajectory or a writer). */
inline Trajectory SyntheticTrajectory() {
  Trajectory t;
  t.header = SyntheticHeader();
  for (int f = 0; f < kSyntheticFrames; ++f) {
    TrajectoryFrame frame;
    frame.index = kSyntheticFrameIndex[f];
    frame.time = Real(static_cast<double>(frame.index) / 60.0);
    for (int b = 0; b < kSyntheticBodies; ++b) frame.bodies.push_back(SyntheticBody(f, b));
    t.frames.push_back(frame);
  }
  return t;
}

/* A fresh directory under the test temp dir, removed with its contents. */
class TempDir {
 public:
  explicit TempDir(const std::string &tag) {
    const std::filesystem::path base = std::filesystem::temp_directory_path();
    for (int attempt = 0;; ++attempt) {
      path_ =
          base / ("karma_golden_" + tag + "_" + std::to_string(KARMA_TEST_GETPID()) + "_" + std::to_string(attempt));
      if (std::filesystem::create_directories(path_)) break;
    }
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  const std::filesystem::path &path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace karma::golden::test_support

#endif
