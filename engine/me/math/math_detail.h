// math_detail.h: helpers shared by the MeMath sources (not installed).
//
// Every MeMath function computes into locals first and writes its outputs
// last, so an output may alias any input. Sums are written in one fixed
// order (index 0 first) so that results are reproducible bit for bit.
#ifndef KARMA_ME_MATH_DETAIL_H
#define KARMA_ME_MATH_DETAIL_H

#include "MeMath.h"

#include <cmath>

namespace karma::me::detail {

inline constexpr MeReal kZero = MeReal(0);
inline constexpr MeReal kOne = MeReal(1);
inline constexpr MeReal kTwo = MeReal(2);
inline constexpr MeReal kHalf = MeReal(0.5);

// a . b for three components.
inline MeReal dot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A 3x3 matrix held by value, so results can be built before being stored.
struct Mat3 {
  MeReal m[3][3];
};

inline Mat3 load3(MECONSTMATRIX MeMatrix3 in) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = in[i][j];
  return r;
}

inline void store3(MeMatrix3 out, const Mat3 &r) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = r.m[i][j];
}

// The rotation block (rows 0..2, columns 0..2) of a TM.
inline Mat3 rotationOf(MECONSTMATRIX MeMatrix4 tm) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = tm[i][j];
  return r;
}

}  // namespace karma::me::detail

#endif  // KARMA_ME_MATH_DETAIL_H
