// matrix4.cpp: general 4x4 MeMatrix4 algebra (see MeMath.h).
// Results are assembled in a local copy, so outputs may alias inputs.
#include "math_detail.h"

#include <cstring>

using karma::me::detail::kOne;
using karma::me::detail::kZero;

namespace {

struct Mat4 {
  MeReal m[4][4];
};

void store4(MeMatrix4 out, const Mat4 &r) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out[i][j] = r.m[i][j];
}

}  // namespace

extern "C" {

void MEAPI MeMatrix4MakeIdentity(MeMatrix4 m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[i][j] = (i == j) ? kOne : kZero;
}

void MEAPI MeMatrix4Copy(MeMatrix4 out, MECONSTMATRIX MeMatrix4 in) {
  if (out != in) std::memmove(out, in, sizeof(MeMatrix4));
}

void MEAPI MeMatrix4Multiply(MeMatrix4 out, MECONSTMATRIX MeMatrix4 a, MECONSTMATRIX MeMatrix4 b) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      r.m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j];
  store4(out, r);
}

void MEAPI MeMatrix4Transpose(MeMatrix4 out, MECONSTMATRIX MeMatrix4 m) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  store4(out, r);
}

}  // extern "C"
