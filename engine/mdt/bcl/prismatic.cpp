// prismatic.cpp: the prismatic (slider) joint.
//
// Frames: a0, o0, n0 = a0 x o0 are body 0's attachment axes in the world, p0
// and p1 the attachment points. The slide axis is a0.
//
// Rows, in this order:
//   0-2  angular rows about a0, o0, n0 with the components of
//        frameRotationError: the relative orientation stays as it was set up;
//   3-4  linear rows along u, w (unit, orthogonal to a0):  u . (p1 - p0) = 0,
//        both bodies' lever arms taken to p1, which makes the Jacobian the
//        exact rate of u . (p1 - p0) with u turning with body 0;
//   5-6  the limit's rows (a stop and/or the motor) on the slide
//        s = a0 . (p0 - p1), whose rate has the same lever arms.
#include "MdtPrismatic.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtPrismatic : MdtConstraint {
  MdtLimit limit;
};

namespace {

void reset(MdtConstraint *c) { MdtLimitReset(&as<MdtPrismatic>(c)->limit); }

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtPrismatic>(c);
  MeVector3 a0, o0, n0, err;
  attachmentAxis(c, 0, a0);
  attachmentOrtho(c, 0, o0);
  MeVector3Cross(n0, a0, o0);
  frameRotationError(c, err);
  addAngularRow(sink, ctx, a0, MeVector3Dot(err, a0));
  addAngularRow(sink, ctx, o0, MeVector3Dot(err, o0));
  addAngularRow(sink, ctx, n0, MeVector3Dot(err, n0));

  Anchors a = anchorsOf(c);
  MeVector3 x0;
  bodyOrigin(c, 0, x0);
  MeVector3Subtract(a.r[0], a.p[1], x0);  // body 0's lever arm to p1
  MeVector3 u, w;
  MeVector3PlaneSpace(a0, u, w);
  addLinearRow(sink, ctx, a, u);
  addLinearRow(sink, ctx, a, w);

  MeReal jac[4][3];
  MeVector3Copy(jac[0], a0);
  MeVector3Cross(jac[1], a.r[0], a0);
  MeVector3MultiplyScalar(jac[2], a0, -1);
  MeVector3Cross(jac[3], a0, a.r[1]);
  MeVector3 gap;
  MeVector3Subtract(gap, a.p[0], a.p[1]);
  addLimitRows(&j->limit, c, sink, ctx, jac, MeVector3Dot(a0, gap), false);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kPrismaticType = {MdtConstraintTypePrismatic,
                                              "Prismatic",
                                              sizeof(MdtPrismatic),
                                              7,
                                              nullptr,
                                              reset,
                                              addRows,
                                              nullptr,
                                              nullptr,
                                              nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Prismatic, kPrismaticType)

extern "C" {

void MEAPI MdtPrismaticSetAxis(const MdtPrismaticID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtPrismaticSetAxis";
  if (!checkType(j, kPrismaticType, fn)) return;
  MeVector3 a = {x, y, z};
  if (!unitDirection(a, fn, "the axis")) return;
  MdtConstraintSetAxis(j, a[0], a[1], a[2]);
  // The present configuration becomes slide position zero, centred.
  MeVector3 p0;
  attachmentPoint(j, 0, p0);
  pointToBodyFrame(j, 1, p0, j->localPos[1]);
  j->warmRows = 0;
}

void MEAPI MdtPrismaticGetAxis(const MdtPrismaticID j, MeVector3 axis) {
  static const char *fn = "MdtPrismaticGetAxis";
  if (!checkType(j, kPrismaticType, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  attachmentAxis(j, 0, axis);
}

MdtLimitID MEAPI MdtPrismaticGetLimit(const MdtPrismaticID j) {
  if (!checkType(j, kPrismaticType, "MdtPrismaticGetLimit")) return nullptr;
  return &j->limit;
}

void MEAPI MdtPrismaticSetLimit(const MdtPrismaticID j, const MdtLimitID limit) {
  static const char *fn = "MdtPrismaticSetLimit";
  if (!checkType(j, kPrismaticType, fn)) return;
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  j->limit = *limit;
}

}  // extern "C"
