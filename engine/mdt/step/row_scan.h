// row_scan.h: the one pass over a constraint's rows that collectRows makes
// before it keeps them (collect_rows.cpp): whether J, speed and softness
// are all finite, the largest |J| value and |softness|, and how many rows
// ask for a bounce. Not installed.
//
// The pass works on magnitude bits: a MeReal's bits as a signed integer of
// its width with the sign bit cleared, the bits of |x|. IEEE 754 orders
// non-negative values as their bit patterns, so for values that are not
// NaN the larger |x| has the larger bits, and equal |x| equal bits (-0 and
// +0 both give 0); an infinity or a NaN has bits of at least
// kExponentBits. One integer maximum over the values thus gives both the
// largest |x|, bit for bit what a maximum of fabs gives, and whether every
// value is finite, without a branch per value.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "constraint.h"

namespace karma::mdt {

struct RowScan {
  bool finite = true;  // every J value, speed and softness finite
  MeReal largestJ = 0, largestSoftness = 0;  // largest |J| value, |softness|; meaningful when finite
  int asking = 0;                            // rows with bounceAfter > 0
};

namespace row_scan_detail {

using MagnitudeBits = std::conditional_t<sizeof(MeReal) == 4, std::int32_t, std::int64_t>;
static_assert(sizeof(MagnitudeBits) == sizeof(MeReal));
inline constexpr MagnitudeBits kExponentBits =
    sizeof(MeReal) == 4 ? MagnitudeBits(0x7f800000) : MagnitudeBits(0x7ff0000000000000ll);
inline constexpr MagnitudeBits kMagnitudeMask = std::numeric_limits<MagnitudeBits>::max();

// Magnitude bits in lanes 16 bytes wide (GCC's vector extension).
using MagnitudeLanes = MagnitudeBits __attribute__((vector_size(16)));
inline constexpr int kPerLanes = 16 / (int)sizeof(MeReal);
static_assert(sizeof(Row::J) % 16 == 0, "J fills whole lanes");
inline constexpr int kJLanes = (int)(sizeof(Row::J) / 16);

inline MagnitudeBits magnitudeBits(MeReal x) { return std::bit_cast<MagnitudeBits>(x) & kMagnitudeMask; }

}  // namespace row_scan_detail

inline RowScan scanRowValues(const Row *rows, int n) {
  using namespace row_scan_detail;
  MagnitudeLanes largestJ = {};
  MagnitudeBits largestSpeed = 0, largestSoftness = 0;
  RowScan scan;
  for (int r = 0; r < n; ++r) {
    const Row &row = rows[r];
    const auto *bytes = reinterpret_cast<const unsigned char *>(&row.J);  // J's object representation
    for (int k = 0; k < kJLanes; ++k) {
      MagnitudeLanes lanes;
      std::memcpy(&lanes, bytes + k * sizeof lanes, sizeof lanes);
      lanes &= kMagnitudeMask;
      largestJ = lanes > largestJ ? lanes : largestJ;
    }
    largestSpeed = std::max(largestSpeed, magnitudeBits(row.speed));
    largestSoftness = std::max(largestSoftness, magnitudeBits(row.softness));
    scan.asking += row.bounceAfter > 0 ? 1 : 0;
  }
  MagnitudeBits j = 0;
  for (int k = 0; k < kPerLanes; ++k) j = std::max(j, largestJ[k]);
  scan.finite = std::max(std::max(j, largestSpeed), largestSoftness) < kExponentBits;
  scan.largestJ = std::bit_cast<MeReal>(j);
  scan.largestSoftness = std::bit_cast<MeReal>(largestSoftness);
  return scan;
}

}  // namespace karma::mdt
