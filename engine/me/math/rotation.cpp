// rotation.cpp: rotation matrices from an axis and an angle.
// Rows are the rotated body axes in world coordinates (MeMath.h), so each
// matrix here is the transpose of the usual column-vector rotation matrix.
#include "math_detail.h"

using karma::me::detail::kOne;
using karma::me::detail::kZero;

namespace {

void setRows(MeMatrix3 R, MeReal a, MeReal b, MeReal c, MeReal d, MeReal e, MeReal f, MeReal g, MeReal h, MeReal i) {
  MeVector3Set(R[0], a, b, c);
  MeVector3Set(R[1], d, e, f);
  MeVector3Set(R[2], g, h, i);
}

}  // namespace

extern "C" {

void MEAPI MeMatrix3MakeRotationX(MeMatrix3 R, MeReal angle) {
  const MeReal c = MeCos(angle), s = MeSin(angle);
  setRows(R, kOne, kZero, kZero, kZero, c, s, kZero, -s, c);
}

void MEAPI MeMatrix3MakeRotationY(MeMatrix3 R, MeReal angle) {
  const MeReal c = MeCos(angle), s = MeSin(angle);
  setRows(R, c, kZero, -s, kZero, kOne, kZero, s, kZero, c);
}

void MEAPI MeMatrix3MakeRotationZ(MeMatrix3 R, MeReal angle) {
  const MeReal c = MeCos(angle), s = MeSin(angle);
  setRows(R, c, s, kZero, -s, c, kZero, kZero, kZero, kOne);
}

// R[i][j] = c d_ij + (1 - c) n_i n_j + s e_ijk n_k  (e the Levi-Civita symbol):
// the transpose of Rodrigues' c I + (1 - c) n n^T + s [n]x.
void MEAPI MeMatrix3FromAxisAngle(MeMatrix3 R, const MeVector3 axis, MeReal angle) {
  MeVector3 n = {axis[0], axis[1], axis[2]};
  if (MeVector3Normalize(n) == kZero || !MeVector3AllFinite(n)) {
    MeMatrix3MakeIdentity(R);
    return;
  }
  const MeReal c = MeCos(angle), s = MeSin(angle), k = kOne - c;
  const MeReal x = n[0], y = n[1], z = n[2];
  setRows(R, c + k * x * x, k * x * y + s * z, k * x * z - s * y,  //
          k * x * y - s * z, c + k * y * y, k * y * z + s * x,     //
          k * x * z + s * y, k * y * z - s * x, c + k * z * z);
}

}  // extern "C"
