// linear1.cpp: the Linear1 joint -- body 0's attachment point p0 stays on a
// plane fixed in body 1, through body 1's attachment point p1 with normal
// n1, body 1's primary axis.
//
// Row (one):  n1 . (p1 - p0) = 0, both bodies' lever arms taken to p0, which
// makes the Jacobian the exact rate of n1 . (p0 - p1) with n1 turning with
// body 1.
#include "MdtLinear1.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtLinear1 : MdtConstraint {};

namespace {

void reset(MdtConstraint *) {}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  Anchors a = anchorsOf(c);
  MeVector3 x1, n1;
  bodyOrigin(c, 1, x1);
  MeVector3Subtract(a.r[1], a.p[0], x1);  // body 1's lever arm to p0
  attachmentAxis(c, 1, n1);
  addLinearRow(sink, ctx, a, n1);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kLinear1Type = {
    MdtConstraintTypeLinear1, "Linear1", sizeof(MdtLinear1), 1, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Linear1, kLinear1Type)

extern "C" {

void MEAPI MdtLinear1SetAxis(const MdtLinear1ID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtLinear1SetAxis";
  if (!checkType(j, kLinear1Type, fn)) return;
  MeVector3 n = {x, y, z};
  if (!unitDirection(n, fn, "the plane normal")) return;
  MdtConstraintSetAxis(j, n[0], n[1], n[2]);
}

void MEAPI MdtLinear1GetAxis(const MdtLinear1ID j, MeVector3 axis) {
  static const char *fn = "MdtLinear1GetAxis";
  if (!checkType(j, kLinear1Type, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  attachmentAxis(j, 1, axis);
}

}  // extern "C"
