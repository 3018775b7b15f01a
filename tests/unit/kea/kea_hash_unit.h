// kea_hash_unit.h: a deterministic value in [-1, 1) from a seed and an
// index (a multiplicative hash with MurmurHash2's mixing steps), for test
// matrices that every platform and build make alike.
#pragma once

#include <cstdint>

namespace kea_test {

inline double Unit(std::uint32_t seed, std::uint32_t i) {
  std::uint32_t x = seed * 2654435761u ^ (i + 1) * 40503u;
  x ^= x >> 13;
  x *= 0x5bd1e995u;
  x ^= x >> 15;
  return (x & 0xffffff) / double(1 << 23) - 1;
}

}  // namespace kea_test
