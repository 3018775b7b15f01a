// vector4.cpp: MeVector4 helpers (see MeMath.h for the formulas).
#include "math_detail.h"

using karma::me::detail::kOne;
using karma::me::detail::kZero;

extern "C" {

void MEAPI MeVector4Set(MeVector4 v, MeReal a, MeReal b, MeReal c, MeReal d) {
  v[0] = a;
  v[1] = b;
  v[2] = c;
  v[3] = d;
}

void MEAPI MeVector4Copy(MeVector4 out, const MeVector4 in) {
  const MeReal a = in[0], b = in[1], c = in[2], d = in[3];
  MeVector4Set(out, a, b, c, d);
}

MeReal MEAPI MeVector4Dot(const MeVector4 a, const MeVector4 b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

MeReal MEAPI MeVector4Magnitude(const MeVector4 v) { return MeSqrt(MeVector4Dot(v, v)); }

MeReal MEAPI MeVector4Normalize(MeVector4 v) {
  const MeReal len = MeVector4Magnitude(v);
  if (len > kZero) {
    const MeReal r = kOne / len;
    MeVector4Set(v, v[0] * r, v[1] * r, v[2] * r, v[3] * r);
  }
  return len;
}

}  // extern "C"
