/* Trajectory.h: the in-memory model of a trajectory file.
 *
 * A trajectory is a header plus the states of every body at a set of sampled
 * frames. Per body the state is 13 numbers, always in this order (the order of
 * the file and of the hash):
 *   position[3], quaternion[4] (w, x, y, z), linear velocity[3], angular velocity[3].
 *
 * Invariants of a well-formed Trajectory (the writer and reader enforce them):
 *   - every frame has exactly header.bodyCount bodies;
 *   - frame indices are >= 0 and strictly increasing;
 *   - when header.precision is Single every value is exactly a float (values are
 *     stored as double, which holds any float exactly).
 * The recorded hashes are what the file said; HashTrajectory() (StateHash.h)
 * recomputes them from the values. */
#ifndef KARMA_GOLDEN_TRAJECTORY_H
#define KARMA_GOLDEN_TRAJECTORY_H

#include <karma/golden/Precision.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace karma::golden {

/* The four classes of state values; each has its own tolerance. */
enum class Quantity { Position = 0, Quaternion = 1, LinearVelocity = 2, AngularVelocity = 3 };
inline constexpr int kQuantityCount = 4;
inline constexpr std::array<Quantity, kQuantityCount> kAllQuantities = {
    Quantity::Position, Quantity::Quaternion, Quantity::LinearVelocity, Quantity::AngularVelocity};

/* The keyword of a quantity in trajectory files and reports: pos, quat, linvel, angvel. */
constexpr std::string_view QuantityName(Quantity q) noexcept {
  switch (q) {
    case Quantity::Position:
      return "pos";
    case Quantity::Quaternion:
      return "quat";
    case Quantity::LinearVelocity:
      return "linvel";
    case Quantity::AngularVelocity:
      return "angvel";
  }
  return "?";
}

constexpr int QuantitySize(Quantity q) noexcept { return q == Quantity::Quaternion ? 4 : 3; }

struct BodyState {
  std::array<double, 3> position{};
  std::array<double, 4> quaternion{1.0, 0.0, 0.0, 0.0}; /* (w, x, y, z) */
  std::array<double, 3> linearVelocity{};
  std::array<double, 3> angularVelocity{};

  /* The components of one quantity (QuantitySize(q) of them). */
  const double *Values(Quantity q) const noexcept;
  double *Values(Quantity q) noexcept;

  bool operator==(const BodyState &) const = default;
};

struct TrajectoryHeader {
  std::string program;               /* e.g. "demo", "quadbike" */
  std::string step = "main";         /* tutorial step, "main" for programs without steps */
  std::string backend = "reference"; /* platform backend that produced it */
  Precision precision = kBuildPrecision;
  int bodyCount = 0;
  std::string sampling;  /* human description of which frames are sampled */
  double timeStep = 0.0; /* seconds per frame, a value of `precision` */

  bool operator==(const TrajectoryHeader &) const = default;
};

struct TrajectoryFrame {
  long index = 0;    /* frame number in the run (0 = initial state) */
  double time = 0.0; /* simulated time of this frame; not part of the hash */
  std::vector<BodyState> bodies;
  std::uint64_t hash = 0; /* as recorded: running state hash after this frame */
};

struct Trajectory {
  TrajectoryHeader header;
  std::vector<TrajectoryFrame> frames;
  std::uint64_t finalHash = 0; /* as recorded: running hash after the last frame */
};

inline const double *BodyState::Values(Quantity q) const noexcept {
  switch (q) {
    case Quantity::Position:
      return position.data();
    case Quantity::Quaternion:
      return quaternion.data();
    case Quantity::LinearVelocity:
      return linearVelocity.data();
    case Quantity::AngularVelocity:
      return angularVelocity.data();
  }
  return position.data();
}

inline double *BodyState::Values(Quantity q) noexcept {
  return const_cast<double *>(static_cast<const BodyState *>(this)->Values(q));
}

}  // namespace karma::golden

#endif
