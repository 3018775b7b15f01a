// rows.cpp: shared Jacobian building blocks (see rows.h).
#include <cmath>

#include "rows.h"

namespace karma::mdt {

Anchors anchorsOf(const MdtConstraint *c) {
  Anchors a;
  for (int i = 0; i < 2; ++i) {
    attachmentPoint(c, i, a.p[i]);
    MeVector3 x;
    bodyOrigin(c, i, x);
    MeVector3Subtract(a.r[i], a.p[i], x);
  }
  return a;
}

Row &addLinearRow(RowSink &sink, const StepContext &ctx, const Anchors &a, const MeVector3 d) {
  Row &row = addLinearJacobianRow(sink, ctx, a, d);
  MeVector3 gap;
  MeVector3Subtract(gap, a.p[1], a.p[0]);
  row.speed = ctx.gamma * ctx.invH * MeVector3Dot(d, gap);
  return row;
}

Row &addAngularRow(RowSink &sink, const StepContext &ctx, const MeVector3 e, MeReal error) {
  Row &row = sink.add(ctx);
  MeVector3Copy(row.J[1], e);
  MeVector3MultiplyScalar(row.J[3], e, -1);
  row.speed = ctx.gamma * ctx.invH * error;
  return row;
}

void addPointRows(RowSink &sink, const StepContext &ctx, const Anchors &a) {
  for (int k = 0; k < 3; ++k) {
    MeVector3 d = {0, 0, 0};
    d[k] = 1;
    addLinearRow(sink, ctx, a, d);
  }
}

void frameRotationError(const MdtConstraint *c, MeVector3 out) {
  MeVector3 a0, a1, o0, o1, n0, n1, t;
  attachmentAxis(c, 0, a0);
  attachmentAxis(c, 1, a1);
  attachmentOrtho(c, 0, o0);
  attachmentOrtho(c, 1, o1);
  MeVector3Cross(n0, a0, o0);
  MeVector3Cross(n1, a1, o1);
  MeVector3Cross(out, a0, a1);
  MeVector3Cross(t, o0, o1);
  MeVector3Add(out, out, t);
  MeVector3Cross(t, n0, n1);
  MeVector3Add(out, out, t);
  MeVector3Scale(out, (MeReal)0.5);
}

MeReal twistAngle(const MdtConstraint *c, const MeVector3 a) {
  MeVector3 o0, o1, t;
  attachmentOrtho(c, 0, o0);
  attachmentOrtho(c, 1, o1);
  MeVector3MultiplyAdd(o0, -MeVector3Dot(o0, a), a);
  MeVector3MultiplyAdd(o1, -MeVector3Dot(o1, a), a);
  MeVector3Cross(t, o1, o0);
  return std::atan2(MeVector3Dot(t, a), MeVector3Dot(o1, o0));
}

void springRow(Row &row, const StepContext &ctx, MeReal k, MeReal c, MeReal error) {
  const MeReal hk = ctx.h * k;
  const MeReal denom = hk + c;
  row.softness = (MeReal)1 / (ctx.h * denom);
  row.speed = k * error / denom;
}

MeReal rowVelocity(const MdtConstraint *c, const Row &row) {
  MeReal v = 0;
  for (int i = 0; i < 2; ++i) {
    const MdtBody *b = c->body[i];
    if (!b) continue;
    v += MeVector3Dot(row.J[2 * i], b->velocity) + MeVector3Dot(row.J[2 * i + 1], b->angularVelocity);
  }
  return v;
}

MeReal unwrapAngle(MdtLimit *limit, MeReal raw) {
  const MeReal twoPi = (MeReal)(2 * ME_PI);
  if (limit->rawValid) {
    const MeReal d = raw - limit->rawPrevious;
    if (d > (MeReal)ME_PI) limit->turns -= 1;
    if (d < -(MeReal)ME_PI) limit->turns += 1;
  }
  limit->rawPrevious = raw;
  limit->rawValid = TRUE;
  return raw + twoPi * limit->turns;
}

namespace {

// A stop is hard above the threshold; an infinite stiffness is always hard
// (with the default threshold of MEINFINITY this is how hard stops are made).
bool isHard(const MdtSingleLimit &sl, MeReal threshold) {
  return sl.stiffness > threshold || sl.stiffness >= MEINFINITY;
}

// One side of a limit. `sign` is +1 for the lower stop (the row pushes the
// coordinate up) and -1 for the upper stop. `gap` is the distance left
// before the stop (negative: past it), `rate` the coordinate's rate.
//
// Rows only for effects that act. The guide: a limited joint costs a row
// only while it "is at (or beyond) one of its limits", a motor only while
// the joint "is actuated" (user guide, Constraints: Powering Joints; Appendix
// D, Hinge). Here, "at" a hard stop means within reach this step:
//   hard:  a row iff gap - approach * h <= 0 (the coordinate, moving at its
//          current rate, would reach or pass the stop within the step; a
//          bounce is then asked in that same row);
//   soft:  a row iff gap <= 0 (the spring acts only past the stop);
//   a side with stiffness and damping both 0 never makes a row;
//   only the nearer stop is examined (addLimitRows).
// A joint far from its stops therefore writes no limit row at all, and a
// motor writes its row only when it is on: motorized and motorMaxForce > 0
// (addLimitRows).
//
// Hard stops act speculatively: a row appears as soon as the coordinate
// would pass the stop within this step, and then lets it close at most the
// gap (speed -gap/h), so a stop of restitution 0 is reached, not overshot and
// pushed back. Restitution e asks for a rebound of e times the approach
// speed; past the stop, gamma removes the overshoot. Soft stops are damped
// springs that act only past the stop.
void addStopRow(const MdtSingleLimit &sl, MeReal threshold, const MeReal jAxis[4][3], MeReal sign, MeReal gap,
                MeReal rate, RowSink &sink, const StepContext &ctx) {
  if (sl.stiffness <= 0 && sl.damping <= 0) return;  // this side is switched off
  const bool hard = isHard(sl, threshold);
  const MeReal approach = -sign * rate;                     // > 0 when closing on (or going past) the stop
  if (hard ? gap - approach * ctx.h > 0 : gap > 0) return;  // not reached this step
  Row &row = sink.add(ctx);
  for (int k = 0; k < 4; ++k) MeVector3MultiplyScalar(row.J[k], jAxis[k], sign);
  row.role = RowRole::Limit;
  row.lo = 0;
  row.hi = MEINFINITY;
  if (hard) {
    const MeReal bounce = approach > 0 ? sl.restitution * approach : 0;
    const MeReal close = gap > 0 ? -gap * ctx.invH : ctx.gamma * ctx.invH * -gap;
    row.speed = bounce > close ? bounce : close;
  } else {
    springRow(row, ctx, sl.stiffness, sl.damping, -gap);
  }
}

}  // namespace

void addLimitRows(MdtLimit *limit, const MdtConstraint *c, RowSink &sink, const StepContext &ctx,
                  const MeReal jAxis[4][3], MeReal measured, bool /*angular*/) {
  Row probe{};
  for (int k = 0; k < 4; ++k) MeVector3Copy(probe.J[k], jAxis[k]);
  const MeReal rate = rowVelocity(c, probe);
  limit->position = measured + limit->offset;
  limit->velocity = rate;
  const MeReal p = limit->position;
  bool atLower = false, atUpper = false;
  if (limit->limited) {
    const MdtSingleLimit &lo = limit->limit[0];
    const MdtSingleLimit &hi = limit->limit[1];
    // The nearer stop (both only if the range is empty, which SetLower/
    // SetUpperLimit prevent).
    const int before = sink.count();
    if (p - lo.stop <= hi.stop - p) {
      addStopRow(lo, limit->stiffnessThreshold, jAxis, 1, p - lo.stop, rate, sink, ctx);
      atLower = sink.count() > before;
    } else {
      addStopRow(hi, limit->stiffnessThreshold, jAxis, -1, hi.stop - p, rate, sink, ctx);
      atUpper = sink.count() > before;
    }
  }
  if (limit->motorized && limit->motorMaxForce > 0) {
    // A motor pushing into a hard stop it already touches adds nothing.
    const bool intoLower =
        atLower && limit->motorDesiredVelocity < 0 && isHard(limit->limit[0], limit->stiffnessThreshold);
    const bool intoUpper =
        atUpper && limit->motorDesiredVelocity > 0 && isHard(limit->limit[1], limit->stiffnessThreshold);
    if (!intoLower && !intoUpper) {
      Row &row = sink.add(ctx);
      for (int k = 0; k < 4; ++k) MeVector3Copy(row.J[k], jAxis[k]);
      row.role = RowRole::Limit;
      row.speed = limit->motorDesiredVelocity;
      row.lo = -limit->motorMaxForce;
      row.hi = limit->motorMaxForce;
    }
  }
}

}  // namespace karma::mdt
