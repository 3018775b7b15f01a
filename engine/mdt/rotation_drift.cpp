// rotation_drift.cpp: the torque-free turn of a body over one step, which
// keeps its angular momentum and kinetic energy.
//
// After the velocity stage the body's world angular momentum about its
// centre of mass is L = Iw(q0) w1 (every torque and constraint impulse of
// the step is in w1). Over the step the body then turns freely: L is
// constant in the world while its body-frame image Lb obeys Euler's equation
//   dLb/dt = Lb x Ib^-1 Lb.
// The step turns the body about one body-frame axis wm by the angle
// phi = turnAngle(|wm|, h) (h |wm| up to one radian per step, see below), so
// Lb1 = Rot(wm, -phi) Lb0 (L stays fixed in the world, |Lb| is kept
// exactly), with wm chosen as the midpoint velocity
//   wm = Ib^-1 m,   m = (Lb0 + Lb1) / 2.
// Then E1 - E0 = (1/2) (Lb1 - Lb0) . Ib^-1 (Lb1 + Lb0) = (Lb1 - Lb0) . wm = 0,
// since a rotation about wm moves Lb0 at right angles to wm: the kinetic
// energy is kept exactly too (to the solve's tolerance). This is the
// Lie-Poisson midpoint idea (cf. Hairer, Lubich, Wanner, "Geometric
// Numerical Integration", VII.5, where the Cayley rotation is used); the
// exact angle h |wm| keeps a spin about a principal axis exact (Lb0 is
// then along wm and m = Lb0). No damping is added. Above one radian per
// step the angle is compressed (below 1 + pi/2 at any speed): a fast
// spinner whose axis also moves (a top, a wheel) then moves its off-axis
// points by chords its constraints, linear in h w, can follow; turned by
// the full angle near or beyond pi per step, a top at 200 rad/s on a ball
// joint flies apart at 1/60 s (tests/hard_cases, docs/STABILITY.md).
//
// m solves F(m) = 2 m - Lb0 - Rot(Ib^-1 m, -h |Ib^-1 m|) Lb0 = 0 from
// m = Lb0, first by the fixed point m <- m - F(m) / 2 (one evaluation of F a
// step): its map has the derivative (1/2) d(Rot Lb0)/dw Ib^-1, of size about
// (h/2) |Lb0| |Ib^-1|, so a slow body (a rag doll at rest) converges in two
// or three steps. Once a step shrinks by less than half (a fast or very
// uneven body), or the steps allowed are used up, Newton's method takes
// over from the current iterate (from Lb0 when the first step made F
// larger), the Jacobian by forward differences (step sqrt(epsilon) |Lb0|;
// four evaluations a step). Both stop when a step is within
// 4 epsilon |Lb0|. Lb1 is then the turned Lb0 for the last iterate, so |L|
// and the world L hold whatever the iterate, E to the solve's accuracy.
#include "mdt_internal.h"

namespace karma::mdt {

namespace {

constexpr int kNewtonIterations = 12;
// Fixed-point steps allowed before Newton's method takes over. A slow body
// contracts by a thousandth or less a step and needs two or three; in double
// precision a body contracting by a tenth uses all eight and then Newton's
// steps (handing over earlier, when the steps left could not reach the
// tolerance, cost the single-precision rag doll 0.6 % more instructions).
constexpr int kFixedPointIterations = 8;

// The angle turned in one step at the speed s: h s up to one radian, then
// phi = 1 + atan(h s - 1), smooth at 1 and below 1 + pi/2 at any speed.
// Energy and |L| are kept whatever the angle.
MeReal turnAngle(MeReal s, MeReal h) {
  const MeReal x = h * s;
  return x <= 1 ? x : 1 + MeAtan2(x - 1, 1);
}

// v turned about the axis w by the angle -turnAngle(|w|, h) (Rodrigues).
void turnBack(const MeVector3 w, MeReal h, const MeVector3 v, MeVector3 out) {
  const MeReal s = MeVector3Magnitude(w);
  if (!(s > 0)) {
    MeVector3Copy(out, v);
    return;
  }
  MeVector3 k, kxv;
  MeVector3MultiplyScalar(k, w, 1 / s);
  MeVector3Cross(kxv, k, v);
  const MeReal phi = -turnAngle(s, h), c = MeCos(phi), sn = MeSin(phi), kv = MeVector3Dot(k, v);
  for (int r = 0; r < 3; ++r) out[r] = v[r] * c + kxv[r] * sn + k[r] * kv * (1 - c);
}

// F(m) = 2 m - Lb0 - (Lb0 turned back about Ib^-1 m).
void residual(MECONSTMATRIX MeMatrix3 invIb, const MeVector3 Lb0, MeReal h, const MeVector3 m, MeVector3 F) {
  MeVector3 wm, L1;
  MeMatrix3MultiplyVector(wm, invIb, m);
  turnBack(wm, h, Lb0, L1);
  for (int r = 0; r < 3; ++r) F[r] = 2 * m[r] - Lb0[r] - L1[r];
}

// Newton's method on F from m, whose residual F(m) is given; at most
// kNewtonIterations steps, until a step is within tol.
void newtonMidpointMomentum(MECONSTMATRIX MeMatrix3 invIb, const MeVector3 Lb0, MeReal h, MeReal size, MeReal tol,
                            MeVector3 F, MeVector3 m) {
  const MeReal delta = MeSqrt(ME_REAL_EPSILON) * size;  // forward-difference step
  for (int it = 0; it < kNewtonIterations; ++it) {
    if (it > 0) residual(invIb, Lb0, h, m, F);
    MeMatrix3 J, Jinv;
    for (int k = 0; k < 3; ++k) {
      MeVector3 mk, Fk;
      MeVector3Copy(mk, m);
      mk[k] += delta;
      residual(invIb, Lb0, h, mk, Fk);
      for (int r = 0; r < 3; ++r) J[r][k] = (Fk[r] - F[r]) / delta;
    }
    if (!MeMatrix3Inverse(Jinv, J)) return;
    MeVector3 dm;
    MeMatrix3MultiplyVector(dm, Jinv, F);
    MeVector3Subtract(m, m, dm);
    if (!(MeVector3Magnitude(dm) > tol)) return;
  }
}

void solveMidpointMomentum(MECONSTMATRIX MeMatrix3 invIb, const MeVector3 Lb0, MeReal h, MeVector3 m) {
  MeVector3Copy(m, Lb0);
  const MeReal size = MeVector3Magnitude(Lb0);
  if (!(size > 0)) return;  // at rest: m = Lb0 = 0
  const MeReal tol = 4 * ME_REAL_EPSILON * size;
  MeVector3 F0, F;  // F(Lb0); F(m) throughout
  residual(invIb, Lb0, h, m, F0);
  if (!MeVector3AllFinite(F0)) return;
  MeVector3Copy(F, F0);
  MeReal lastStep = 0;
  for (int it = 0; it < kFixedPointIterations; ++it) {
    const MeReal step = MeVector3Magnitude(F) / 2;
    if (it > 0 && !(step <= lastStep / 2)) {  // shrank by less than half, or not finite
      // A first step that grew F (the map does not contract there) is
      // undone: Newton starts from Lb0, as it would without it.
      if (it == 1 && !(step < lastStep)) {
        MeVector3Copy(m, Lb0);
        MeVector3Copy(F, F0);
      }
      break;
    }
    MeVector3MultiplyAdd(m, -(MeReal)0.5, F);
    if (!(step > tol)) return;
    lastStep = step;
    residual(invIb, Lb0, h, m, F);
  }
  if (!MeVector3AllFinite(F)) return;
  newtonMidpointMomentum(invIb, Lb0, h, size, tol, F, m);
}

}  // namespace

void plainRotationTurn(const MeVector3 w1, MeReal h, MeVector3 turn) {
  MeVector3Copy(turn, w1);
  const MeReal s = MeVector3Magnitude(w1);
  if (h * s > 1) MeVector3Scale(turn, turnAngle(s, h) / (h * s));
}

void freeRotationDrift(const MdtBody *b, const MeVector3 w1, MeReal h, MeVector3 turn, MeVector3 wEndBody) {
  MeMatrix3 R;
  MeMatrix4TMGetRotation(R, b->tm);
  MeVector3 wb, Lb0;
  MeMatrix3MultiplyVector(wb, R, w1);  // world -> body
  MeMatrix3MultiplyVector(Lb0, b->inertia, wb);
  MeVector3 m, wm, Lb1;
  solveMidpointMomentum(b->invInertia, Lb0, h, m);
  MeMatrix3MultiplyVector(wm, b->invInertia, m);
  if (!MeVector3AllFinite(wm)) MeVector3Copy(wm, wb);
  turnBack(wm, h, Lb0, Lb1);
  MeMatrix3MultiplyVector(wEndBody, b->invInertia, Lb1);
  // The turn as a world angular velocity held over h: along wm, whose
  // direction is the same in both frames of the step.
  MeMatrix3TransposeMultiplyVector(turn, R, wm);  // body -> world
  const MeReal s = MeVector3Magnitude(wm);
  if (s > 0) MeVector3Scale(turn, turnAngle(s, h) / (h * s));
}

}  // namespace karma::mdt
