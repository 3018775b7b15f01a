// gyroscopic.cpp: when the step computes a body's gyroscopic effect, and the
// per-body switch MdtBodySetGyroscopicMode (MdtBody.h).
//
// The gyroscopic effect is the term w x Iw w of Euler's equation: without
// it a body keeps its world angular velocity w and turns about it; with it
// the body keeps its world angular momentum L = Iw w and w moves (a tumbling
// box, a precessing top). The step computes it in the torque-free turn
// (freeRotationDrift) or, for a body with a fast-spin axis, in the velocity
// stage (gyroscopicStep). Both cost far more than the plain turn about w, so
// the step leaves the term out where it cannot change the result:
//
// 1. Spherical inertia: Ib = s (Id + D) with every |D_ij| <= kSphericalTolerance
//    (three principal moments equal within a relative 1e-6, up to the factor
//    3 between the largest entry and the 2-norm of D). Then
//        |w x Iw w| = s |w x D w| <= 3e-6 s |w|^2,
//    and with D = 0 exactly the term is exactly zero: L = s w, so keeping L
//    is keeping w.
// 2. Negligible spin. Over one step the plain turn (w held in the world)
//    changes the world angular momentum by
//        dL = Iw(q1) w - Iw(q0) w = h (w x Iw w) + O(h^2)
//    (dIw/dt = [w]x Iw - Iw [w]x), and the gyroscopic turn would have kept L;
//    the two angular velocities then differ by |Iw^-1 dL| <= |Ib^-1| h |w x Iw w|.
//    With |Ib^-1| bounded by its infinity norm (for a symmetric matrix the
//    2-norm is at most the infinity norm), the term is left out when
//        h |w x Iw w| |Ib^-1|_inf <= epsilon |w|,
//    epsilon the precision's unit roundoff (ME_REAL_EPSILON): the change it
//    would make to w is below the rounding of w itself. |w x Iw w| is
//    computed in body axes (wb = R w, Lb = Ib wb), where it has the same size.
//
// Modes: Auto applies rules 1 and 2; Always applies rule 1 only with D = 0
// exactly (where the term is exactly zero); Never leaves the term out.
#include "MeMessage.h"
#include "mdt_internal.h"

namespace karma::mdt {

namespace {

constexpr MeReal kSphericalTolerance = (MeReal)1e-6;

// The infinity norm (largest absolute row sum) of a 3x3 matrix.
MeReal infinityNorm(MECONSTMATRIX MeMatrix3 m) {
  MeReal largest = 0;
  for (int i = 0; i < 3; ++i) {
    const MeReal row = MeFabs(m[i][0]) + MeFabs(m[i][1]) + MeFabs(m[i][2]);
    if (row > largest) largest = row;
  }
  return largest;
}

// |wb x Ib wb| with wb the body-frame image of the world vector w.
MeReal gyroscopicSize(const MdtBody *b, const MeVector3 w) {
  MeMatrix3 R;
  MeMatrix4TMGetRotation(R, b->tm);
  MeVector3 wb, Lb, t;
  MeMatrix3MultiplyVector(wb, R, w);
  MeMatrix3MultiplyVector(Lb, b->inertia, wb);
  MeVector3Cross(t, wb, Lb);
  return MeVector3Magnitude(t);
}

}  // namespace

void classifyInertia(MdtBody *b) {
  const MeReal s = (b->inertia[0][0] + b->inertia[1][1] + b->inertia[2][2]) / 3;
  bool near = true, exact = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const MeReal d = b->inertia[i][j] - (i == j ? s : 0);
      near = near && MeFabs(d) <= kSphericalTolerance * s;
      exact = exact && (i == j ? b->inertia[i][i] == b->inertia[0][0] : b->inertia[i][j] == 0);
    }
  b->inertiaSpherical = near ? TRUE : FALSE;
  b->inertiaExactlySpherical = exact ? TRUE : FALSE;
  b->invInertiaNorm = infinityNorm(b->invInertia);
}

bool gyroscopicActs(const MdtBody *b, const MeVector3 w, MeReal h) {
  switch (b->gyroscopicMode) {
    case MdtGyroscopicNever:
      return false;
    case MdtGyroscopicAlways:
      return !b->inertiaExactlySpherical;
    case MdtGyroscopicAuto:
      break;
  }
  if (b->inertiaSpherical) return false;
  return h * gyroscopicSize(b, w) * b->invInertiaNorm > ME_REAL_EPSILON * MeVector3Magnitude(w);
}

}  // namespace karma::mdt

extern "C" {

void MEAPI MdtBodySetGyroscopicMode(const MdtBodyID body, const MdtGyroscopicMode mode) {
  static const char *fn = "MdtBodySetGyroscopicMode";
  ME_REQUIRE_ARG(body != nullptr, fn, "body is NULL");
  ME_REQUIRE_ARG(mode == MdtGyroscopicAuto || mode == MdtGyroscopicAlways || mode == MdtGyroscopicNever, fn,
                 "unknown mode %d (MdtGyroscopicAuto, MdtGyroscopicAlways or MdtGyroscopicNever); ignored", (int)mode);
  body->gyroscopicMode = mode;
}

MdtGyroscopicMode MEAPI MdtBodyGetGyroscopicMode(const MdtBodyID body) {
  ME_REQUIRE_ARG_RET(body != nullptr, MdtGyroscopicAuto, "MdtBodyGetGyroscopicMode", "body is NULL");
  return body->gyroscopicMode;
}

}  // extern "C"
