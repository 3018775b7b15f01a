#include <karma/golden/StateHash.h>

#include <cstring>

namespace karma::golden {

void StateHash::AddBytes(std::uint64_t bits, int byteCount) noexcept {
  /* Least significant byte first: the little-endian memory image of the value,
   * independent of the host's byte order. */
  for (int i = 0; i < byteCount; ++i) {
    hash_ ^= (bits >> (8 * i)) & 0xffu;
    hash_ *= kPrime;
  }
}

void StateHash::AddValue(double value, Precision precision) noexcept {
  if (precision == Precision::Single) {
    const float f = static_cast<float>(value);
    std::uint32_t bits = 0;
    static_assert(sizeof f == sizeof bits);
    std::memcpy(&bits, &f, sizeof bits);
    AddBytes(bits, 4);
  } else {
    std::uint64_t bits = 0;
    static_assert(sizeof value == sizeof bits);
    std::memcpy(&bits, &value, sizeof bits);
    AddBytes(bits, 8);
  }
}

void StateHash::AddBody(const BodyState &body, Precision precision) noexcept {
  for (Quantity q : kAllQuantities) {
    const double *v = body.Values(q);
    for (int i = 0; i < QuantitySize(q); ++i) AddValue(v[i], precision);
  }
}

std::string FormatHash(std::uint64_t hash) {
  static const char digits[] = "0123456789abcdef";
  std::string text = "0x";
  for (int shift = 60; shift >= 0; shift -= 4) text += digits[(hash >> shift) & 0xfu];
  return text;
}

std::optional<std::uint64_t> ParseHash(std::string_view text) noexcept {
  if (text.size() != 18 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X')) return std::nullopt;
  std::uint64_t hash = 0;
  for (char c : text.substr(2)) {
    int digit;
    if (c >= '0' && c <= '9')
      digit = c - '0';
    else if (c >= 'a' && c <= 'f')
      digit = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F')
      digit = c - 'A' + 10;
    else
      return std::nullopt;
    hash = (hash << 4) | static_cast<std::uint64_t>(digit);
  }
  return hash;
}

std::uint64_t HashTrajectory(const Trajectory &trajectory, std::vector<std::uint64_t> *perFrame) {
  StateHash hash;
  if (perFrame) perFrame->clear();
  for (const TrajectoryFrame &frame : trajectory.frames) {
    for (const BodyState &body : frame.bodies) hash.AddBody(body, trajectory.header.precision);
    if (perFrame) perFrame->push_back(hash.Value());
  }
  return hash.Value();
}

}  // namespace karma::golden
