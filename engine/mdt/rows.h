// rows.h: Jacobian building blocks shared by the constraint types. Each
// function appends rows to a RowSink following the row protocol of
// constraint.h; "error" always means the quantity a positive J v reduces.
#pragma once

#include "constraint.h"

namespace karma::mdt {

// Attachment points p0, p1 and the lever arms r0 = p0 - x0, r1 = p1 - x1.
struct Anchors {
  MeVector3 p[2];
  MeVector3 r[2];
};
Anchors anchorsOf(const MdtConstraint *c);

// One linear row along world direction d acting at the anchors:
//   J v = d . (v0 + w0 x r0) - d . (v1 + w1 x r1),
// driving d . (p1 - p0) (the separation to close) with gamma.
Row &addLinearRow(RowSink &sink, const StepContext &ctx, const Anchors &a, const MeVector3 d);

// The same row's J alone, its speed left at 0: for a caller that sets the
// speed itself (contacts). Inline, so that a caller's anchors can stay in
// registers: read back from memory as wider loads than the stores that
// wrote them, they stall (store forwarding fails).
inline Row &addLinearJacobianRow(RowSink &sink, const StepContext &ctx, const Anchors &a, const MeVector3 d) {
  Row &row = sink.add(ctx);
  MeVector3Copy(row.J[0], d);
  MeVector3Cross(row.J[1], a.r[0], d);
  MeVector3MultiplyScalar(row.J[2], d, -1);
  MeVector3Cross(row.J[3], d, a.r[1]);  // -(r1 x d)
  return row;
}

// One angular row about world axis e: J v = e . (w0 - w1), with target
// speed gamma * error / h.
Row &addAngularRow(RowSink &sink, const StepContext &ctx, const MeVector3 e, MeReal error);

// The three rows that make the anchors coincide (ball and socket).
void addPointRows(RowSink &sink, const StepContext &ctx, const Anchors &a);

// The rotation that turns body 0's attachment frame onto body 1's (small
// angle approximation: 0.5 * sum of frame axis cross products). Its
// component along any axis is the error of an angular row about that axis.
void frameRotationError(const MdtConstraint *c, MeVector3 out);

// Signed angle from body 1's secondary axis to body 0's about world axis a
// (both projected onto the plane normal to a); its rate is a . (w0 - w1).
MeReal twistAngle(const MdtConstraint *c, const MeVector3 a);

// Softness and speed of a damped spring row (stiffness k >= 0, damping
// c >= 0, not both zero) holding `error` towards zero:
//   softness = 1 / (h (h k + c)),   speed = k * error / (h k + c),
// so the row's force settles at k * error.
void springRow(Row &row, const StepContext &ctx, MeReal k, MeReal c, MeReal error);

// The J v of a row with the bodies' current velocities.
MeReal rowVelocity(const MdtConstraint *c, const Row &row);

// Whether a limit's position is kept (MdtLimitCalculatePosition, set by
// activating its stops or its motor): a limit with none of the three
// writes no row and need not be measured.
inline bool limitTracked(const MdtLimit &l) { return l.calculatePosition || l.limited || l.motorized; }

// The rows of a limit and motor on a joint coordinate whose rate is
// jAxis . v (jAxis: a row Jacobian, as in Row::J) and whose measured value
// is `measured` (user position = measured + offset, angles unwrapped by the
// caller when `angular`). Updates limit->position and limit->velocity.
void addLimitRows(MdtLimit *limit, const MdtConstraint *c, RowSink &sink, const StepContext &ctx,
                  const MeReal jAxis[4][3], MeReal measured, bool angular);

// Feeds a raw angle in (-pi, pi] through the limit's turn counter and
// returns the continuous angle.
MeReal unwrapAngle(MdtLimit *limit, MeReal raw);

}  // namespace karma::mdt
