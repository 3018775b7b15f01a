// cone_limit.cpp: the cone limit, a one-sided limit on the angle between
// body 0's primary axis a0 and body 1's primary axis a1.
//
// theta = angle(a0, a1) in [0, pi], alpha the cone half-angle. With
// n = (a1 x a0) / |a1 x a0|, d(theta)/dt = n . (w0 - w1).
//
// Rows: none while the cone is clear or alpha = pi, else one angular row about -n
// (J v = -d(theta)/dt), force bounds [0, inf):
//   hard (stiffness MEINFINITY): written when theta + h * d(theta)/dt >=
//        alpha, i.e. when the axis reaches the cone within this step. Speed
//        (alpha - theta) / h while still inside (it may arrive but not pass),
//        gamma * (theta - alpha) / h once over. No rebound.
//   soft (finite stiffness): written while theta >= alpha, a damped spring
//        (joint_input.h) on theta - alpha.
// When a0 and a1 are (anti)parallel, n is any direction orthogonal to a0.
#include <cmath>

#include "MdtConeLimit.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtConeLimit : MdtConstraint {
  MeReal halfAngle;
  MeReal stiffness;
  MeReal damping;
};

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtConeLimit>(c);
  j->halfAngle = (MeReal)ME_PI;
  j->stiffness = MEINFINITY;
  j->damping = MEINFINITY;
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtConeLimit>(c);
  // A half-angle of pi is no limit (the angle never exceeds it).
  if (isInert(j->stiffness, j->damping) || j->halfAngle >= (MeReal)ME_PI) return;
  MeVector3 a0, a1, n;
  attachmentAxis(c, 0, a0);
  attachmentAxis(c, 1, a1);
  MeVector3Cross(n, a1, a0);
  const MeReal sinT = MeVector3Magnitude(n);
  const MeReal theta = std::atan2(sinT, MeVector3Dot(a0, a1));
  if (sinT > (MeReal)1e-6)
    MeVector3Scale(n, 1 / sinT);
  else
    anyOrthogonal(a0, n);
  MeVector3 w = {0, 0, 0};
  if (c->body[0]) MeVector3Add(w, w, c->body[0]->angularVelocity);
  if (c->body[1]) MeVector3Subtract(w, w, c->body[1]->angularVelocity);
  const MeReal rate = MeVector3Dot(n, w);
  const MeReal over = theta - j->halfAngle;
  const bool rigid = isRigid(j->stiffness);
  if (rigid ? over + ctx.h * rate < 0 : over < 0) return;
  MeVector3 e;
  MeVector3MultiplyScalar(e, n, -1);
  Row &row = addAngularRow(sink, ctx, e, over);
  row.role = RowRole::Limit;
  row.lo = 0;
  row.hi = MEINFINITY;
  if (!rigid)
    makeSpring(row, ctx, j->stiffness, j->damping, over);
  else if (over < 0)
    row.speed = over * ctx.invH;
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kConeLimitType = {MdtConstraintTypeConeLimit,
                                              "ConeLimit",
                                              sizeof(MdtConeLimit),
                                              1,
                                              nullptr,
                                              reset,
                                              addRows,
                                              nullptr,
                                              nullptr,
                                              nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(ConeLimit, kConeLimitType)

extern "C" {

void MEAPI MdtConeLimitSetConeHalfAngle(const MdtConeLimitID j, const MeReal theta) {
  static const char *fn = "MdtConeLimitSetConeHalfAngle";
  if (!checkType(j, kConeLimitType, fn)) return;
  ME_REQUIRE_ARG(theta > 0 && theta <= (MeReal)ME_PI, fn, "half-angle %g must be in (0, pi]; ignored", (double)theta);
  j->halfAngle = theta;
}

MeReal MEAPI MdtConeLimitGetConeHalfAngle(const MdtConeLimitID j) {
  if (!checkType(j, kConeLimitType, "MdtConeLimitGetConeHalfAngle")) return 0;
  return j->halfAngle;
}

void MEAPI MdtConeLimitSetStiffness(const MdtConeLimitID j, const MeReal k) {
  static const char *fn = "MdtConeLimitSetStiffness";
  if (!checkType(j, kConeLimitType, fn) || !nonNegative(k, fn, "stiffness")) return;
  j->stiffness = k > MEINFINITY ? MEINFINITY : k;
}

MeReal MEAPI MdtConeLimitGetStiffness(const MdtConeLimitID j) {
  if (!checkType(j, kConeLimitType, "MdtConeLimitGetStiffness")) return 0;
  return j->stiffness;
}

void MEAPI MdtConeLimitSetDamping(const MdtConeLimitID j, const MeReal d) {
  static const char *fn = "MdtConeLimitSetDamping";
  if (!checkType(j, kConeLimitType, fn) || !nonNegative(d, fn, "damping")) return;
  j->damping = d > MEINFINITY ? MEINFINITY : d;
}

MeReal MEAPI MdtConeLimitGetDamping(const MdtConeLimitID j) {
  if (!checkType(j, kConeLimitType, "MdtConeLimitGetDamping")) return 0;
  return j->damping;
}

void MEAPI MdtConeLimitSetAxis(const MdtConeLimitID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtConeLimitSetAxis";
  if (!checkType(j, kConeLimitType, fn)) return;
  MeVector3 a = {x, y, z};
  if (!unitDirection(a, fn, "the axis")) return;
  MdtConstraintSetAxis(j, a[0], a[1], a[2]);
}

void MEAPI MdtConeLimitBodySetAxis(const MdtConeLimitID j, const unsigned int bodyindex, const MeReal x, const MeReal y,
                                   const MeReal z) {
  static const char *fn = "MdtConeLimitBodySetAxis";
  if (!checkType(j, kConeLimitType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  MeVector3 a = {x, y, z}, o;
  if (!unitDirection(a, fn, "the axis")) return;
  anyOrthogonal(a, o);
  MdtConstraintBodySetAxes(j, bodyindex, a[0], a[1], a[2], o[0], o[1], o[2]);
}

void MEAPI MdtConeLimitGetAxis(const MdtConeLimitID j, const unsigned int bodyindex, MeVector3 axis) {
  static const char *fn = "MdtConeLimitGetAxis";
  if (!checkType(j, kConeLimitType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  attachmentAxis(j, (int)bodyindex, axis);
}

MeReal MEAPI MdtConeLimitGetAngle(const MdtConeLimitID j) {
  if (!checkType(j, kConeLimitType, "MdtConeLimitGetAngle")) return 0;
  MeVector3 a0, a1, x;
  attachmentAxis(j, 0, a0);
  attachmentAxis(j, 1, a1);
  MeVector3Cross(x, a0, a1);
  return std::atan2(MeVector3Magnitude(x), MeVector3Dot(a0, a1));
}

}  // extern "C"
