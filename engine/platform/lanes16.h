/* lanes16.h: MeReal values in vectors of 16 bytes, GCC's vector extension
 * at the width every x86-64 processor has (not installed). Operations on
 * them go element by element, so each element rounds as the scalar
 * expression does: code written with them gives the scalar code's bits in
 * every build and on every backend. Loads and stores go through memcpy
 * (no alignment asked). */
#ifndef KARMA_PLATFORM_LANES16_H
#define KARMA_PLATFORM_LANES16_H

#include "MePrecision.h"

#include <cstddef>
#include <cstring>

namespace karma::platform {

using Lanes16 = MeReal __attribute__((vector_size(16)));
/* MeReal values in one Lanes16. */
inline constexpr std::size_t kPerLanes16 = 16 / sizeof(MeReal);

inline Lanes16 LoadLanes16(const MeReal *from) {
  Lanes16 v;
  std::memcpy(&v, from, sizeof v);
  return v;
}

inline void StoreLanes16(MeReal *to, Lanes16 v) { std::memcpy(to, &v, sizeof v); }

}  // namespace karma::platform

#endif
