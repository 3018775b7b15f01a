// hinge.cpp: the hinge joint.
//
// Rows: the three ball-and-socket rows at the hinge point, then two angular
// rows about p and q, unit vectors orthogonal to body 0's axis a0, that keep
// body 1's axis a1 parallel to a0 (error (a0 x a1) . p and . q: turning
// body 0 about a0 x a1 brings a0 onto a1), then the limit's rows on the
// hinge angle, whose rate is a0 . (w0 - w1).
#include "MdtHinge.h"
#include "bcl_type.h"

using namespace karma::mdt;

struct MdtHinge : MdtConstraint {
  MdtLimit limit;
};

namespace {

void reset(MdtConstraint *c) { MdtLimitReset(&as<MdtHinge>(c)->limit); }

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *h = as<MdtHinge>(c);
  addPointRows(sink, ctx, anchorsOf(c));
  MeVector3 a0, a1, p, q, x;
  attachmentAxis(c, 0, a0);
  attachmentAxis(c, 1, a1);
  MeVector3PlaneSpace(a0, p, q);
  MeVector3Cross(x, a0, a1);
  addAngularRow(sink, ctx, p, MeVector3Dot(x, p));
  addAngularRow(sink, ctx, q, MeVector3Dot(x, q));
  MeReal j[4][3] = {{0, 0, 0}, {a0[0], a0[1], a0[2]}, {0, 0, 0}, {-a0[0], -a0[1], -a0[2]}};
  const MeReal angle = unwrapAngle(&h->limit, twistAngle(c, a0));
  addLimitRows(&h->limit, c, sink, ctx, j, angle, true);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kHingeType = {
    MdtConstraintTypeHinge, "Hinge", sizeof(MdtHinge), 7, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Hinge, kHingeType)

extern "C" {

void MEAPI MdtHingeSetAxis(const MdtHingeID j, const MeReal x, const MeReal y, const MeReal z) {
  if (!checkType(j, kHingeType, "MdtHingeSetAxis")) return;
  MdtConstraintSetAxis(j, x, y, z);
  j->limit.rawValid = FALSE;
}

void MEAPI MdtHingeGetAxis(const MdtHingeID j, MeVector3 axis) {
  if (!checkType(j, kHingeType, "MdtHingeGetAxis")) return;
  MdtConstraintGetAxis(j, axis);
}

MdtLimitID MEAPI MdtHingeGetLimit(const MdtHingeID j) {
  if (!checkType(j, kHingeType, "MdtHingeGetLimit")) return nullptr;
  return &j->limit;
}

void MEAPI MdtHingeSetLimit(const MdtHingeID j, const MdtLimitID limit) {
  if (!checkType(j, kHingeType, "MdtHingeSetLimit")) return;
  ME_REQUIRE_ARG(limit != nullptr, "MdtHingeSetLimit", "limit is NULL");
  j->limit = *limit;
}

MeReal MEAPI MdtHingeGetAngle(const MdtHingeID j) {
  if (!checkType(j, kHingeType, "MdtHingeGetAngle")) return 0;
  MeVector3 a0;
  attachmentAxis(j, 0, a0);
  return unwrapAngle(&j->limit, twistAngle(j, a0)) + j->limit.offset;
}

MeReal MEAPI MdtHingeGetAngleRate(const MdtHingeID j) {
  if (!checkType(j, kHingeType, "MdtHingeGetAngleRate")) return 0;
  MeVector3 a0, w = {0, 0, 0};
  attachmentAxis(j, 0, a0);
  if (j->body[0]) MeVector3Add(w, w, j->body[0]->angularVelocity);
  if (j->body[1]) MeVector3Subtract(w, w, j->body[1]->angularVelocity);
  return MeVector3Dot(a0, w);
}

}  // extern "C"
