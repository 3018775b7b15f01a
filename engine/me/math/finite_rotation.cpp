// finite_rotation.cpp: the integrator's orientation update.
//
// A body spinning at constant world angular velocity omega for time h turns
// by the angle a = |omega| h about n = omega / |omega|, i.e. by the
// quaternion d = (cos(a/2), sin(a/2) n) = (cos(a/2), (h/2) sinc(a/2) omega),
// applied after the current orientation q: q' = "q, then d" (Hamilton d q).
// Writing sin(a/2)/|omega| as (h/2) sinc(a/2) avoids dividing by a tiny
// |omega|; for small arguments sinc uses its Taylor series.
#include "math_detail.h"

using karma::me::detail::kHalf;
using karma::me::detail::kOne;

namespace {

// sinc(x) = sin(x)/x, with sinc(0) = 1.
MeReal sinc(MeReal x) {
  // Below this the series 1 - x^2/6 + x^4/120 is exact to rounding in
  // both precisions (the next term, x^6/5040, is far below epsilon).
  const MeReal small = MeReal(1e-3);
  if (MeFabs(x) < small) {
    const MeReal x2 = x * x;
    return kOne - x2 / MeReal(6) + x2 * x2 / MeReal(120);
  }
  return MeSin(x) / x;
}

}  // namespace

extern "C" {

void MEAPI MeQuaternionFiniteRotation(MeVector4 q, const MeVector3 omega, MeReal h) {
  const MeReal half = kHalf * h;
  const MeReal halfAngle = MeVector3Magnitude(omega) * half;  // a/2
  const MeReal k = half * sinc(halfAngle);
  const MeVector4 d = {MeCos(halfAngle), k * omega[0], k * omega[1], k * omega[2]};
  MeQuaternionMultiply(q, q, d);
  MeQuaternionNormalize(q);
}

}  // extern "C"
