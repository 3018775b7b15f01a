// shape_util.h: small helpers shared by the geometry files.
#pragma once

#include "mcd_internal.h"

#include <cmath>
#include <cstring>

namespace karma::mcd {

inline void Diagonal(MeMatrix3 I, MeReal xx, MeReal yy, MeReal zz) {
  std::memset(I, 0, sizeof(MeMatrix3));
  I[0][0] = xx;
  I[1][1] = yy;
  I[2][2] = zz;
}

// AABB of a shape whose extent along world axis j is
// sum_i |R[i][j]| * half[i] + round (R = rows 0-2 of tm), centred on tm[3].
inline void OrientedBoxAABB(MECONSTMATRIX MeMatrix4 tm, const MeVector3 half, MeReal round, MeVector3 mn,
                            MeVector3 mx) {
  for (int j = 0; j < 3; ++j) {
    MeReal e = round;
    for (int i = 0; i < 3; ++i) e += std::fabs(tm[i][j]) * half[i];
    mn[j] = tm[3][j] - e;
    mx[j] = tm[3][j] + e;
  }
}

}  // namespace karma::mcd
