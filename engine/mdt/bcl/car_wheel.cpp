// car_wheel.cpp: the car wheel joint's rows (geometry in car_wheel.h).
//
// Rows, in this order:
//   0-1  linear rows along u, w (unit, orthogonal to s): u . (p1 - p0) = 0,
//        the chassis's lever arm taken to p1 (as the prismatic joint), so
//        the wheel centre stays on the steering line;
//   2    s perpendicular to h: one angular row about e = s x h / |s x h|,
//        error -asin(s . h) (as the universal joint);
//   3    steering locked: angular row about s with error phi (phi -> 0);
//        else the steering motor (MdtLimit rows, J = {0, -s, 0, s});
//   4    the hinge motor (J = {0, -h, 0, h}), when on;
//   5    the suspension spring, when Kp or Kd > 0: J v = dz/dt, a damped
//        spring (springRow) with error reference - z, force Kp (ref - z);
//   6    a suspension stop when the height reaches a limit (MdtLimit hard
//        stop, restitution 0), its softness replaced by limit_softness > 0.
#include <cmath>

#include "car_wheel.h"

using namespace karma::mdt;

namespace karma::mdt {

WheelGeometry wheelGeometry(const MdtCarWheel *j) {
  WheelGeometry g;
  MeVector3 a0, o0, x0, d;
  attachmentAxis(j, 0, a0);
  attachmentOrtho(j, 0, o0);
  MeVector3Cross(g.s, a0, o0);
  attachmentOrtho(j, 1, g.h);
  attachmentPoint(j, 0, g.a.p[0]);
  // The wheel is held at its centre of mass (the world: its attachment point).
  if (j->body[1])
    bodyCom(j->body[1], g.a.p[1]);
  else
    attachmentPoint(j, 1, g.a.p[1]);
  bodyOrigin(j, 0, x0);
  MeVector3Subtract(g.a.r[0], g.a.p[1], x0);
  MeVector3Set(g.a.r[1], 0, 0, 0);
  if (!j->body[1]) MeVector3Copy(g.a.r[1], g.a.p[1]);
  MeVector3Subtract(d, g.a.p[1], g.a.p[0]);
  g.height = MeVector3Dot(g.s, d);
  // z = s . (p1 - p0) with s turning with the chassis:
  //   dz/dt = -s . v0 + (s x r0) . w0 + s . v1 + (r1 x s) . w1.
  MeVector3MultiplyScalar(g.jHeight[0], g.s, -1);
  MeVector3Cross(g.jHeight[1], g.s, g.a.r[0]);
  MeVector3Copy(g.jHeight[2], g.s);
  MeVector3Cross(g.jHeight[3], g.a.r[1], g.s);
  return g;
}

MeReal wheelSteeringAngle(const MdtCarWheel *j) {
  MeVector3 a0, o0, s;
  attachmentAxis(j, 0, a0);
  attachmentOrtho(j, 0, o0);
  MeVector3Cross(s, a0, o0);
  return steeringAngleAbout(j, s);
}

MeReal steeringAngleAbout(const MdtCarWheel *j, const MeVector3 s) {
  // twistAngle measures from body 1's secondary (h) to body 0's (o0).
  return -twistAngle(j, s);
}

MeReal wheelHingeAngle(const MdtCarWheel *j) {
  MeVector3 a0, o0, s, a1, h, n1, p, q, t;
  attachmentAxis(j, 0, a0);
  attachmentOrtho(j, 0, o0);
  MeVector3Cross(s, a0, o0);
  attachmentAxis(j, 1, a1);
  attachmentOrtho(j, 1, h);
  MeVector3Cross(n1, a1, h);
  // Both references projected on the plane normal to h.
  MeVector3Copy(p, s);
  MeVector3MultiplyAdd(p, -MeVector3Dot(p, h), h);
  MeVector3Copy(q, n1);
  MeVector3Cross(t, p, q);
  MeReal angle = std::atan2(MeVector3Dot(t, h), MeVector3Dot(p, q));
  if (angle < 0) angle += (MeReal)(2 * ME_PI);
  return angle >= (MeReal)(2 * ME_PI) ? 0 : angle;
}

MeReal wheelRelativeRate(const MdtCarWheel *j, const MeVector3 e) {
  MeVector3 w = {0, 0, 0};
  if (j->body[1]) MeVector3Add(w, w, j->body[1]->angularVelocity);
  if (j->body[0]) MeVector3Subtract(w, w, j->body[0]->angularVelocity);
  return MeVector3Dot(e, w);
}

}  // namespace karma::mdt

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtCarWheel>(c);
  MdtLimitReset(&j->steer);
  MdtLimitReset(&j->hinge);
  MdtLimitReset(&j->suspension);
  // Appendix A: the steering motor holds the rate at 0 with up to 1e9.
  j->steer.motorMaxForce = (MeReal)1e9;
  j->steer.motorized = TRUE;
  j->steer.calculatePosition = TRUE;
  j->suspension.limited = TRUE;
  j->suspension.limit[0].stop = (MeReal)-1e9;
  j->suspension.limit[1].stop = (MeReal)1e9;
  j->suspension.limit[0].restitution = 0;
  j->suspension.limit[1].restitution = 0;
  j->steeringLocked = FALSE;
  j->kp = j->kd = 0;
  j->limitSoftness = 0;
  j->reference = 0;
}

void angularJacobian(MeReal jac[4][3], const MeVector3 e) {
  MeVector3Set(jac[0], 0, 0, 0);
  MeVector3MultiplyScalar(jac[1], e, -1);
  MeVector3Set(jac[2], 0, 0, 0);
  MeVector3Copy(jac[3], e);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtCarWheel>(c);
  const WheelGeometry g = wheelGeometry(j);
  MeVector3 u, w, e;
  MeVector3PlaneSpace(g.s, u, w);
  addLinearRow(sink, ctx, g.a, u);
  addLinearRow(sink, ctx, g.a, w);

  MeVector3Cross(e, g.s, g.h);
  const MeReal len = MeVector3Magnitude(e);
  if (len > (MeReal)1e-6)
    MeVector3Scale(e, 1 / len);
  else
    anyOrthogonal(g.s, e);
  MeReal sh = MeVector3Dot(g.s, g.h);
  sh = sh > 1 ? 1 : (sh < -1 ? -1 : sh);
  addAngularRow(sink, ctx, e, -std::asin(sh));

  MeReal jac[4][3];
  const MeReal phi = steeringAngleAbout(j, g.s);
  if (j->steeringLocked) {
    addAngularRow(sink, ctx, g.s, phi);  // J v = s . (w0 - w1) = -d(phi)/dt
  } else {
    angularJacobian(jac, g.s);
    addLimitRows(&j->steer, c, sink, ctx, jac, phi, true);
  }
  // The hinge angle (an atan2 and both frames) only when the hinge limit
  // needs it: a wheel driven by torque keeps no hinge position.
  if (limitTracked(j->hinge)) {
    angularJacobian(jac, g.h);
    addLimitRows(&j->hinge, c, sink, ctx, jac, wheelHingeAngle(j), true);
  }

  if (j->kp > 0 || j->kd > 0) {
    Row &row = sink.add(ctx);
    for (int k = 0; k < 4; ++k) MeVector3Copy(row.J[k], g.jHeight[k]);
    springRow(row, ctx, j->kp, j->kd, j->reference - g.height);
  }
  const int before = sink.count();
  MdtLimit stops = j->suspension;
  stops.motorized = FALSE;
  addLimitRows(&stops, c, sink, ctx, g.jHeight, g.height, false);
  j->suspension.position = stops.position;
  j->suspension.velocity = stops.velocity;
  if (j->limitSoftness > 0)
    for (int k = before; k < sink.count(); ++k) sink.rows()[k].softness = j->limitSoftness;
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kCarWheelType = {
    MdtConstraintTypeCarWheel, "CarWheel", sizeof(MdtCarWheel), 7, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(CarWheel, kCarWheelType)
