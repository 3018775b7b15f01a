/* StateHash.h: the 64-bit state hash of a run.
 *
 * Definition (the contract every program and golden relies on):
 *   FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3) over the
 *   bytes of the state values, each value taken as the IEEE-754 bit pattern of
 *   its precision (4 bytes for single, 8 for double) and fed least significant
 *   byte first, so the hash is the same on any host byte order. Values are fed
 *   frame by frame (sampled frames, in order), body by body, and per body
 *   position, quaternion (w,x,y,z), linear velocity, angular velocity.
 *   Nothing else (frame numbers, time, header) enters the hash.
 * So bit-identical runs give identical hashes and flipping any bit of any
 * value changes the hash (with overwhelming probability); -0 and +0 differ.
 * The hash after a frame covers every sampled frame up to and including it;
 * the hash of a run is the hash after its last sampled frame.
 *
 * Text form: "0x" followed by exactly 16 lowercase hex digits. */
#ifndef KARMA_GOLDEN_STATEHASH_H
#define KARMA_GOLDEN_STATEHASH_H

#include <karma/golden/Trajectory.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace karma::golden {

class MEPUBLIC StateHash {
 public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;

  /* Feed one value. For Single, `value` must be exactly a float (it is
   * converted to float, which is then exact). */
  void AddValue(double value, Precision precision) noexcept;
  /* Feed one body's 13 values in the order above. */
  void AddBody(const BodyState &body, Precision precision) noexcept;

  std::uint64_t Value() const noexcept { return hash_; }

 private:
  void AddBytes(std::uint64_t bits, int byteCount) noexcept;
  std::uint64_t hash_ = kOffsetBasis;
};

/* "0x0123456789abcdef". */
MEPUBLIC std::string FormatHash(std::uint64_t hash);
/* Accepts exactly the text form above; nullopt otherwise. */
MEPUBLIC std::optional<std::uint64_t> ParseHash(std::string_view text) noexcept;

/* Recompute the hash of a trajectory from its values (ignoring the recorded
 * hashes). If perFrame is given it receives the running hash after each frame. */
MEPUBLIC std::uint64_t HashTrajectory(const Trajectory &trajectory, std::vector<std::uint64_t> *perFrame = nullptr);

}  // namespace karma::golden

#endif
