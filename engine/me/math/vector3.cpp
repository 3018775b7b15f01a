// vector3.cpp: MeVector3 arithmetic (see MeMath.h for the formulas). The
// operations MeMathInline.h defines inline (the small vector operations and
// the matrix-vector and TM point/direction products) are exported from
// here, compiled from that same text.
#define ME_MATH_EXPORT_INLINES
#include "math_detail.h"

using karma::me::detail::dot3;
using karma::me::detail::kOne;
using karma::me::detail::kZero;

extern "C" {

MeReal MEAPI MeVector3DistanceSqr(const MeVector3 a, const MeVector3 b) {
  const MeVector3 d = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return dot3(d, d);
}

MeReal MEAPI MeVector3Distance(const MeVector3 a, const MeVector3 b) { return MeSqrt(MeVector3DistanceSqr(a, b)); }

MeBool MEAPI MeVector3IsZero(const MeVector3 v) {
  return (v[0] == kZero && v[1] == kZero && v[2] == kZero) ? TRUE : FALSE;
}

// p is made normal to n by crossing n with the coordinate axis least aligned
// with it (so |n x e| >= |n| sqrt(2/3)); then q = n x p completes the basis,
// which makes p x q = n.
void MEAPI MeVector3PlaneSpace(const MeVector3 n, MeVector3 p, MeVector3 q) {
  MeVector3 u = {n[0], n[1], n[2]};
  if (MeVector3Normalize(u) == kZero || !MeVector3AllFinite(u)) MeVector3Set(u, kZero, kZero, kOne);
  const MeReal ax = MeFabs(u[0]), ay = MeFabs(u[1]), az = MeFabs(u[2]);
  MeVector3 e = {kZero, kZero, kZero};
  if (ax <= ay && ax <= az)
    e[0] = kOne;
  else if (ay <= az)
    e[1] = kOne;
  else
    e[2] = kOne;
  MeVector3 pp, qq;
  MeVector3Cross(pp, u, e);
  MeVector3Normalize(pp);
  MeVector3Cross(qq, u, pp);
  MeVector3Copy(p, pp);
  MeVector3Copy(q, qq);
}

}  // extern "C"
