// matrix3.cpp: MeMatrix3 algebra (see MeMath.h for the formulas); the
// matrix-vector products are inline in MeMathInline.h.
// Outputs are written only after the result is complete, so they may alias
// inputs.
#include "math_detail.h"

using karma::me::detail::dot3;
using karma::me::detail::kOne;
using karma::me::detail::kZero;
using karma::me::detail::load3;
using karma::me::detail::Mat3;
using karma::me::detail::store3;

extern "C" {

void MEAPI MeMatrix3MakeIdentity(MeMatrix3 m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = (i == j) ? kOne : kZero;
}

void MEAPI MeMatrix3Copy(MeMatrix3 out, MECONSTMATRIX MeMatrix3 in) { store3(out, load3(in)); }

void MEAPI MeMatrix3Multiply(MeMatrix3 out, MECONSTMATRIX MeMatrix3 a, MECONSTMATRIX MeMatrix3 b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  store3(out, r);
}

void MEAPI MeMatrix3Transpose(MeMatrix3 out, MECONSTMATRIX MeMatrix3 m) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
  store3(out, r);
}

MeReal MEAPI MeMatrix3Determinant(MECONSTMATRIX MeMatrix3 m) {
  MeVector3 c;
  MeVector3Cross(c, m[1], m[2]);
  return dot3(m[0], c);
}

// Column j of the inverse is (row (j+1) x row (j+2)) / det, because
// row_i . (row_{j+1} x row_{j+2}) = det when i == j and 0 otherwise.
MeBool MEAPI MeMatrix3Inverse(MeMatrix3 out, MECONSTMATRIX MeMatrix3 m) {
  MeVector3 c[3];
  MeVector3Cross(c[0], m[1], m[2]);
  MeVector3Cross(c[1], m[2], m[0]);
  MeVector3Cross(c[2], m[0], m[1]);
  const MeReal det = dot3(m[0], c[0]);
  // Hadamard: |det| <= |r0| |r1| |r2|, so this threshold is scale-free.
  const MeReal bound = MeVector3Magnitude(m[0]) * MeVector3Magnitude(m[1]) * MeVector3Magnitude(m[2]);
  if (!std::isfinite(det) || MeFabs(det) <= ME_REAL_EPSILON * bound || det == kZero) return FALSE;
  const MeReal r = kOne / det;
  Mat3 inv{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inv.m[i][j] = c[j][i] * r;
  store3(out, inv);
  return TRUE;
}

MeBool MEAPI MeMatrix3IsOrthonormal(MECONSTMATRIX MeMatrix3 R, MeReal tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const MeReal e = dot3(R[i], R[j]) - ((i == j) ? kOne : kZero);
      if (!(MeFabs(e) <= tol)) return FALSE;  // also rejects NaN
    }
  return TRUE;
}

MeBool MEAPI MeMatrix3IsRotation(MECONSTMATRIX MeMatrix3 R, MeReal tol) {
  return (MeMatrix3IsOrthonormal(R, tol) && MeMatrix3Determinant(R) > kZero) ? TRUE : FALSE;
}

}  // extern "C"
