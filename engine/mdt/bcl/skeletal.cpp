// skeletal.cpp: the skeletal joint's rows (see MdtSkeletal.h).
//
// Rows, in this order:
//   0-2  ball and socket: p0 = p1;
//   3    the cone, when reached: coordinate c = theta - limit(psi) <= 0.
//        With w = w1 - w0, u = a0 x a1 / sin(theta), v = a1 x u:
//          d(theta)/dt = u . w,   d(psi)/dt = v . w / sin(theta),
//          dc/dt = g . w,  g = u - limit'(psi) v / sin(theta),
//          limit'(psi) = -limit^3 sin(psi) cos(psi) (1/S^2 - 1/P^2).
//        c and g are divided by |g| (c then reads as an angle along the
//        cone's normal) and handed to addLimitRows as an upper stop at 0;
//   4    the twist, when it reaches +-T: with q = (qw, qx, qy, qz) the
//        relative quaternion in frame 0 (w >= 0), twist = 2 atan2(qx, qw),
//        whose rate is exactly ((a0 + a1) / (1 + a0 . a1)) . w (turning body
//        1 about a0 or about a1 both add to it one for one; turning about u
//        does not). A stop pair at -+T via addLimitRows.
// Stops are hard (restitution 0) or damped springs per the stiffness.
#include <cmath>

#include "frame_rotation.h"
#include "joint_input.h"
#include "skeletal.h"

using namespace karma::mdt;

namespace karma::mdt {

SkeletalAngles skeletalAngles(const MdtSkeletal *j) {
  MeMatrix3 F0;
  frameRows(j, 0, F0);
  MeVector3 a1;
  attachmentAxis(j, 1, a1);
  const MeReal x = MeVector3Dot(a1, F0[0]), y = MeVector3Dot(a1, F0[1]), z = MeVector3Dot(a1, F0[2]);
  SkeletalAngles s;
  s.theta = std::atan2(std::sqrt(y * y + z * z), x);
  s.psi = std::atan2(z, y);
  MeVector4 q;
  relativeQuaternion(j, q);
  s.twist = 2 * std::atan2(q[1], q[0]);
  return s;
}

}  // namespace karma::mdt

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtSkeletal>(c);
  j->primary = j->secondary = j->twist = (MeReal)(ME_PI / 4);
  j->coneStiffness = j->twistStiffness = MEINFINITY;
  j->coneDamping = j->twistDamping = 0;
}

// A limit with stops at lo and hi (hard or soft) and no motor.
MdtLimit stopsAt(MeReal lo, MeReal hi, MeReal k, MeReal d) {
  MdtLimit l;
  MdtLimitReset(&l);
  l.limited = TRUE;
  l.limit[0].stop = lo;
  l.limit[1].stop = hi;
  for (MdtSingleLimit &s : l.limit) {
    s.stiffness = k;
    s.damping = d;
    s.restitution = 0;
  }
  return l;
}

void angularJacobian(MeReal jac[4][3], const MeVector3 e) {
  MeVector3Set(jac[0], 0, 0, 0);
  MeVector3MultiplyScalar(jac[1], e, -1);
  MeVector3Set(jac[2], 0, 0, 0);
  MeVector3Copy(jac[3], e);
}

void addConeRow(MdtSkeletal *j, const SkeletalAngles &s, RowSink &sink, const StepContext &ctx) {
  const MeReal P = j->primary, S = j->secondary, pi = (MeReal)ME_PI;
  if (P >= pi && S >= pi) return;
  const MeReal cp = std::cos(s.psi), sp = std::sin(s.psi);
  const MeReal inv = cp * cp / (P * P) + sp * sp / (S * S);
  const MeReal limit = 1 / std::sqrt(inv);
  const MeReal sinT = std::sin(s.theta);
  if (sinT < (MeReal)1e-6 && s.theta < limit) return;  // on the axis: inside
  MeVector3 a0, a1, u, v, g;
  attachmentAxis(j, 0, a0);
  attachmentAxis(j, 1, a1);
  MeVector3Cross(u, a0, a1);
  if (sinT > (MeReal)1e-6)
    MeVector3Scale(u, 1 / MeVector3Magnitude(u));
  else
    anyOrthogonal(a0, u);
  MeVector3Cross(v, a1, u);
  MeVector3Copy(g, u);
  if (sinT > (MeReal)1e-3) {
    const MeReal slope = -limit * limit * limit * sp * cp * (1 / (S * S) - 1 / (P * P));
    MeVector3MultiplyAdd(g, -slope / sinT, v);
  }
  const MeReal norm = MeVector3Magnitude(g);
  MeVector3Scale(g, 1 / norm);
  MeReal jac[4][3];
  angularJacobian(jac, g);
  MdtLimit l = stopsAt(-MEINFINITY, 0, j->coneStiffness, j->coneDamping);
  l.limit[0].stiffness = l.limit[0].damping = 0;  // one-sided
  addLimitRows(&l, j, sink, ctx, jac, (s.theta - limit) / norm, true);
}

void addTwistRow(MdtSkeletal *j, const SkeletalAngles &s, RowSink &sink, const StepContext &ctx) {
  if (j->twist >= (MeReal)ME_PI) return;
  MeVector3 a0, a1, e;
  attachmentAxis(j, 0, a0);
  attachmentAxis(j, 1, a1);
  const MeReal den = 1 + MeVector3Dot(a0, a1);
  if (den < (MeReal)1e-3) return;  // a1 opposite a0: the twist is undefined
  MeVector3Add(e, a0, a1);
  MeVector3Scale(e, 1 / den);
  MeReal jac[4][3];
  angularJacobian(jac, e);
  MdtLimit l = stopsAt(-j->twist, j->twist, j->twistStiffness, j->twistDamping);
  addLimitRows(&l, j, sink, ctx, jac, s.twist, true);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtSkeletal>(c);
  addPointRows(sink, ctx, anchorsOf(c));
  const SkeletalAngles s = skeletalAngles(j);
  addConeRow(j, s, sink, ctx);
  addTwistRow(j, s, sink, ctx);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kSkeletalType = {
    MdtConstraintTypeSkeletal, "Skeletal", sizeof(MdtSkeletal), 5, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Skeletal, kSkeletalType)
