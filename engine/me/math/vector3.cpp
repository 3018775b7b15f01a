// vector3.cpp: MeVector3 arithmetic (see MeMath.h for the formulas).
#include "math_detail.h"

using karma::me::detail::dot3;
using karma::me::detail::kOne;
using karma::me::detail::kZero;

extern "C" {

void MEAPI MeVector3Set(MeVector3 v, MeReal x, MeReal y, MeReal z) {
  v[0] = x;
  v[1] = y;
  v[2] = z;
}

void MEAPI MeVector3Copy(MeVector3 out, const MeVector3 in) {
  const MeReal x = in[0], y = in[1], z = in[2];
  MeVector3Set(out, x, y, z);
}

void MEAPI MeVector3Add(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[0] + b[0], a[1] + b[1], a[2] + b[2]);
}

void MEAPI MeVector3Subtract(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

void MEAPI MeVector3Scale(MeVector3 v, MeReal s) {
  v[0] *= s;
  v[1] *= s;
  v[2] *= s;
}

void MEAPI MeVector3MultiplyScalar(MeVector3 out, const MeVector3 v, MeReal s) {
  MeVector3Set(out, v[0] * s, v[1] * s, v[2] * s);
}

void MEAPI MeVector3MultiplyAdd(MeVector3 v, MeReal s, const MeVector3 a) {
  MeVector3Set(v, v[0] + s * a[0], v[1] + s * a[1], v[2] + s * a[2]);
}

void MEAPI MeVector3Negate(MeVector3 v) { MeVector3Set(v, -v[0], -v[1], -v[2]); }

MeReal MEAPI MeVector3Dot(const MeVector3 a, const MeVector3 b) { return dot3(a, b); }

// (a x b)_i = a_j b_k - a_k b_j for (i, j, k) cyclic.
void MEAPI MeVector3Cross(MeVector3 out, const MeVector3 a, const MeVector3 b) {
  MeVector3Set(out, a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

MeReal MEAPI MeVector3MagnitudeSqr(const MeVector3 v) { return dot3(v, v); }

MeReal MEAPI MeVector3Magnitude(const MeVector3 v) { return MeSqrt(dot3(v, v)); }

MeReal MEAPI MeVector3DistanceSqr(const MeVector3 a, const MeVector3 b) {
  const MeVector3 d = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return dot3(d, d);
}

MeReal MEAPI MeVector3Distance(const MeVector3 a, const MeVector3 b) { return MeSqrt(MeVector3DistanceSqr(a, b)); }

MeReal MEAPI MeVector3Normalize(MeVector3 v) {
  const MeReal len = MeSqrt(dot3(v, v));
  if (len > kZero) MeVector3Scale(v, kOne / len);
  return len;
}

MeBool MEAPI MeVector3IsZero(const MeVector3 v) {
  return (v[0] == kZero && v[1] == kZero && v[2] == kZero) ? TRUE : FALSE;
}

MeBool MEAPI MeVector3AllFinite(const MeVector3 v) {
  return (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) ? TRUE : FALSE;
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
