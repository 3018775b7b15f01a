// integrate.cpp: advancing one unconstrained body by one step.
//
// Semi-implicit (symplectic) Euler: velocities first, from the forces at the
// start of the step, then positions and orientation from the NEW velocities.
//
//   F   = accumulated force - cL v                 (linear damping as drag)
//   v'  = v + h (g + F/m) + J/m                    (J: accumulated impulse)
//   tau = accumulated torque - cA w                (Iw = R^T Ib R, world frame)
//   w'  = w + Iw^-1 (h tau + Ja)                   (Ja: angular impulse)
//   x'  = x + h v'
//   q'  = q turned freely over h with the angular momentum Iw w' held fixed
//         in the world (freeRotationDrift, rotation_drift.cpp); the stored
//         angular velocity is the one the turn ends with.
//
// The gyroscopic effect w x Iw w lives in that turn: it keeps the world
// angular momentum and the kinetic energy of a free body exactly, with no
// damping, at any step and spin, and it precesses a heavy top at the
// gyroscopic rate without a fast-spin axis (tests/hard_cases).
//
// A body with a fast-spin axis a keeps the older scheme (see advanceBody):
// the gyroscopic term linearly implicit in w' (gyroscopicStep; it damps
// the wobble of a spinner by 1 / sqrt(1 + (h Omega)^2) per step), then
// the spin about a and the remaining turn applied one after the other.
//
// Constraint impulses are added between the velocity prediction and the
// position update (step.cpp): w' = wPred + Iw^-1 J^T lambda.
//
// Effects by need: the gyroscopic term is computed only where
// gyroscopicActs says it can change the result (gyroscopic.cpp: not for a
// spherical inertia, nor at a spin where it is below rounding, and as the
// body's MdtBodySetGyroscopicMode says); without it the body turns about w1
// and keeps w1 (plainRotationTurn). Damping is applied only where its
// coefficient is not zero (a zero coefficient adds -0 v: nothing).
#include "MeMessage.h"
#include "mdt_internal.h"

namespace karma::mdt {

namespace {
// The geometric stiffness may make a body at most this many times harder to
// turn (by trace) than its own inertia does. K is built from last step's
// constraint forces, so a body between constraints that fight (a ball joint
// tying a light hull to a body with two others stacked between them) can
// feed back: a stiffer response, larger forces, a stiffer response. The
// response is then far from the body's own, the step adds energy, and it
// ran away in 8 of 5,000 random scenes (hard_cases_random_test). The bound
// lies between what the designed case needs and where the runaway starts:
// a 1000:1 chain of 0.1 kg links (Stability.HangingChainMassRatio1000StaysFinite)
// peaks at a ratio of 141 and still holds under a bound of 30 (gap 14.7 mm,
// 14.6 without bound), not under 10 (1.19 m); the random scenes run away
// under a bound of 100 (RandomScenesThatRanAwayStayBounded).
constexpr MeReal kMaxGeometricStiffness = 30;

// The factor applied to K in Iw + factor K: h^2, or less where the bound
// above holds it. Iw and K are symmetric positive semi-definite.
MeReal geometricStiffnessScale(MECONSTMATRIX MeMatrix3 Iw, MECONSTMATRIX MeMatrix3 K, MeReal h) {
  const MeReal scale = h * h;
  const MeReal inertia = Iw[0][0] + Iw[1][1] + Iw[2][2];
  const MeReal stiffness = scale * (K[0][0] + K[1][1] + K[2][2]);
  if (!(stiffness > kMaxGeometricStiffness * inertia)) return scale;
  return scale * (kMaxGeometricStiffness * inertia / stiffness);
}

bool MeMatrix3IsZero3(MECONSTMATRIX MeMatrix3 m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (m[i][j] != 0) return false;
  return true;
}
}  // namespace

void applyBodyTensor(MeVector3 out, const MdtBody *b, MECONSTMATRIX MeMatrix3 tensor, const MeVector3 v) {
  MeMatrix3 R;
  MeMatrix4TMGetRotation(R, b->tm);
  MeVector3 vb, lb;
  MeMatrix3MultiplyVector(vb, R, v);             // world -> body
  MeMatrix3MultiplyVector(lb, tensor, vb);       // tensor in the body frame
  MeMatrix3TransposeMultiplyVector(out, R, lb);  // body -> world
}

void bodyTensorInWorld(MeMatrix3 out, const MdtBody *b, MECONSTMATRIX MeMatrix3 tensor) {
  for (int k = 0; k < 3; ++k) {
    MeVector3 e = {0, 0, 0}, col;
    e[k] = 1;
    applyBodyTensor(col, b, tensor, e);
    for (int r = 0; r < 3; ++r) out[r][k] = col[r];
  }
}

namespace {

// The gyroscopic velocity change, linearly implicit (bodies with a
// fast-spin axis; every other body turns by freeRotationDrift).
//
// Explicitly, dw = -h Iw^-1 (w x Iw w). For a wheel spinning at S about a
// (inertia Is about a, Ia across), the part of w across a then turns at
// Omega = S (Is - Ia) / Ia each step, and explicit Euler multiplies its size
// by sqrt(1 + (h Omega)^2) per step: with S h ~ 1 a forced turn of the
// wheel (a car cornering) blows up. Instead solve g(w') = Iw (w' - w) +
// h w' x Iw w' = 0 by one Newton step from w:
//   (Iw + h (W Iw - [Iw w]x)) dw = -h w x Iw w,    W = [w]x,
// whose cross-axis factor is 1 / sqrt(1 + (h Omega)^2) <= 1: stable at any
// spin, exact as h -> 0, and the spin about a principal axis is untouched
// (w x Iw w = 0 there). The matrix is not always invertible: W Iw has a
// symmetric part (W Iw - Iw W) / 2, and a body tumbling about its middle
// axis at h|w| of order one makes det J negative or zero; where
// MeMatrix3Inverse finds it singular the term is left out of the step. The
// price: the free wobble of a spinner is damped by that factor
// (it should precess at constant size), negligible while h Omega << 1.
// Explicitly, a rag doll's capsule limb rolling on the ground spins itself
// up and tears the doll apart (tests/unit/scenes, RagdollStaysConnected).
void gyroscopicStep(const MdtBody *b, MECONSTMATRIX MeMatrix3 Iw, MeReal h, MeVector3 dw) {
  const MeReal *w = b->angularVelocity;
  MeVector3 L, f;
  MeMatrix3MultiplyVector(L, Iw, w);
  MeVector3Cross(f, w, L);
  MeVector3Scale(f, -h);
  MeMatrix3 J, Jinv;
  for (int k = 0; k < 3; ++k) {
    MeVector3 e = {0, 0, 0}, col, t1, t2;
    e[k] = 1;
    MeMatrix3MultiplyVector(col, Iw, e);  // Iw e_k
    MeVector3Cross(t1, w, col);           // W Iw e_k
    MeVector3Cross(t2, L, e);             // [Iw w]x e_k
    for (int r = 0; r < 3; ++r) J[r][k] = col[r] + h * (t1[r] - t2[r]);
  }
  if (MeMatrix3Inverse(Jinv, J))
    MeMatrix3MultiplyVector(dw, Jinv, f);
  else
    MeVector3Set(dw, 0, 0, 0);  // J singular (see above)
}

}  // namespace

void predictVelocities(MdtBody *b, const MeVector3 gravity, MeReal h) {
  MeVector3 tmp;

  // Linear velocity.
  MeVector3 f;
  MeVector3Copy(f, b->force);
  if (b->linearDamping != 0) MeVector3MultiplyAdd(f, -b->linearDamping, b->velocity);
  MeVector3 a;
  MeVector3Copy(a, gravity);
  MeVector3MultiplyAdd(a, b->invMass, f);
  MeVector3Copy(b->vPred, b->velocity);
  MeVector3MultiplyAdd(b->vPred, h, a);
  MeVector3MultiplyAdd(b->vPred, b->invMass, b->impulse);

  // Angular velocity.
  MeVector3 tau;
  MeVector3Copy(tau, b->torque);
  if (b->angularDamping != 0) MeVector3MultiplyAdd(tau, -b->angularDamping, b->angularVelocity);
  MeVector3MultiplyScalar(tmp, tau, h);
  MeVector3Add(tmp, tmp, b->angularImpulse);
  MeVector3 dw;
  applyBodyTensor(dw, b, b->invInertia, tmp);
  MeVector3Add(b->wPred, b->angularVelocity, dw);
  if (b->fastSpinEnabled && gyroscopicActs(b, b->angularVelocity, h)) {
    MeMatrix3 Iw;  // world-frame inertia
    for (int k = 0; k < 3; ++k) {
      MeVector3 e = {0, 0, 0};
      e[k] = 1;
      applyBodyTensor(Iw[k], b, b->inertia, e);  // symmetric: row k = column k
    }
    gyroscopicStep(b, Iw, h, dw);
    MeVector3Add(b->wPred, b->wPred, dw);
  }

  // World-frame inverse inertia for the constraint response:
  // (R^T Ib R + h^2 K)^-1, with K the body's geometric stiffness (zero
  // unless the step's stabilisation filled it; see stabilize.cpp), scaled
  // down where needed so that tr(h^2 K) <= kMaxGeometricStiffness tr(Ib).
  if (MeMatrix3IsZero3(b->geomStiffness)) {
    bodyTensorInWorld(b->invInertiaWorld, b, b->invInertia);
    return;
  }
  MeMatrix3 Iw;
  bodyTensorInWorld(Iw, b, b->inertia);
  const MeReal scale = geometricStiffnessScale(Iw, b->geomStiffness, h);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Iw[r][k] += scale * b->geomStiffness[r][k];
  if (!MeMatrix3Inverse(b->invInertiaWorld, Iw)) {
    MeMatrix3MakeIdentity(b->invInertiaWorld);  // unreachable: Iw is positive definite
  }
}

void applyImpulse(MdtBody *b, const MeVector3 linear, const MeVector3 angular) {
  MeVector3MultiplyAdd(b->vPred, b->invMass, linear);
  MeVector3 dw;
  MeMatrix3MultiplyVector(dw, b->invInertiaWorld, angular);
  MeVector3Add(b->wPred, b->wPred, dw);
}

void advanceBody(MdtBody *b, MeReal h) {
  MeVector3 tmp;
  MeVector3 v1, w1;
  MeVector3Copy(v1, b->vPred);
  MeVector3Copy(w1, b->wPred);

  // Centre of mass and orientation from the new velocities; the body
  // origin follows the centre of mass: x = com - R c.
  MeVector3 x1;
  bodyCom(b, x1);
  MeVector3MultiplyAdd(x1, h, v1);
  MeVector4 q1;
  MeVector4Copy(q1, b->q);
  if (b->fastSpinEnabled) {
    // w' = par + perp, par along the fast-spin axis a. The spin is applied
    // FIRST, about a as it stands at the start of the step, then the turn
    // perp carries the spinning body (and a with it). For a wheel spinning
    // about its axle while the car turns this is the true motion
    // q' = turn(perp) turn(spin about a) q; spinning after the turn would
    // spin about the old axle direction a while the body's axle has already
    // moved, tilting the axle by ~|perp| |par| h^2 every step.
    MeVector3 par, perp;
    MeVector3MultiplyScalar(par, b->fastSpinAxis, MeVector3Dot(w1, b->fastSpinAxis));
    MeVector3Subtract(perp, w1, par);
    MeQuaternionFiniteRotation(q1, par, h);
    MeQuaternionFiniteRotation(q1, perp, h);
  } else if (!gyroscopicActs(b, w1, h)) {
    MeVector3 turn;
    plainRotationTurn(w1, h, turn);
    MeQuaternionFiniteRotation(q1, turn, h);
  } else {
    MeVector3 turn, wEndBody;
    freeRotationDrift(b, w1, h, turn, wEndBody);
    MeQuaternionFiniteRotation(q1, turn, h);
    // The angular velocity at the end of the turn, in the world frame.
    MeMatrix3 R1;
    MeMatrix4 tm1;
    MeQuaternionToTM(tm1, q1, b->position);
    MeMatrix4TMGetRotation(R1, tm1);
    MeMatrix3TransposeMultiplyVector(w1, R1, wEndBody);
  }

  {
    MeVector3 c, rc;
    MeMatrix4TMGetPosition(c, b->comTM);
    MeQuaternionRotateVector(rc, q1, c);
    MeVector3Subtract(x1, x1, rc);
  }
  const bool ok = MeVector3AllFinite(v1) && MeVector3AllFinite(w1) && MeVector3AllFinite(x1) && std::isfinite(q1[0]) &&
                  std::isfinite(q1[1]) && std::isfinite(q1[2]) && std::isfinite(q1[3]);
  if (ok) {
    const MeReal invH = (MeReal)1 / h;
    MeVector3Subtract(tmp, v1, b->velocity);
    MeVector3MultiplyScalar(b->acceleration, tmp, invH);
    MeVector3Subtract(tmp, w1, b->angularVelocity);
    MeVector3MultiplyScalar(b->angularAcceleration, tmp, invH);
    MeVector3Copy(b->velocity, v1);
    MeVector3Copy(b->angularVelocity, w1);
    MeVector3Copy(b->position, x1);
    MeVector4Copy(b->q, q1);
    updateTransform(b);
  } else {
    // A defined outcome for a blow-up: the body keeps its last finite pose,
    // comes to rest and is disabled; the world keeps stepping.
    MeWarning(0,
              "MdtWorldStep: the state of body %p overflowed (non-finite velocity or pose); "
              "it was stopped and disabled at its last finite pose",
              (void *)b);
    MeVector3Set(b->velocity, 0, 0, 0);
    MeVector3Set(b->angularVelocity, 0, 0, 0);
    MeVector3Set(b->acceleration, 0, 0, 0);
    MeVector3Set(b->angularAcceleration, 0, 0, 0);
    MdtBodyDisable(b);
  }

  // The accumulators hold what was applied over this step only.
  MeVector3Set(b->force, 0, 0, 0);
  MeVector3Set(b->torque, 0, 0, 0);
  MeVector3Set(b->impulse, 0, 0, 0);
  MeVector3Set(b->angularImpulse, 0, 0, 0);
}

}  // namespace karma::mdt
