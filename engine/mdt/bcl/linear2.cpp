// linear2.cpp: the Linear2 joint -- body 0's attachment point p0 stays on a
// line fixed in body 1, through body 1's attachment point p1 along d1, body
// 1's primary axis.
//
// Rows, in this order: along u and w, unit and orthogonal to d1,
//   u . (p1 - p0) = 0,   w . (p1 - p0) = 0,
// both bodies' lever arms taken to p0 (the exact rate with u, w turning with
// body 1).
#include "MdtLinear2.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtLinear2 : MdtConstraint {};

namespace {

void reset(MdtConstraint *) {}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  Anchors a = anchorsOf(c);
  MeVector3 x1, d1, u, w;
  bodyOrigin(c, 1, x1);
  MeVector3Subtract(a.r[1], a.p[0], x1);  // body 1's lever arm to p0
  attachmentAxis(c, 1, d1);
  MeVector3PlaneSpace(d1, u, w);
  addLinearRow(sink, ctx, a, u);
  addLinearRow(sink, ctx, a, w);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kLinear2Type = {
    MdtConstraintTypeLinear2, "Linear2", sizeof(MdtLinear2), 2, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Linear2, kLinear2Type)

extern "C" {

void MEAPI MdtLinear2SetDirection(const MdtLinear2ID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtLinear2SetDirection";
  if (!checkType(j, kLinear2Type, fn)) return;
  MeVector3 d = {x, y, z};
  if (!unitDirection(d, fn, "the direction")) return;
  MdtConstraintSetAxis(j, d[0], d[1], d[2]);
}

void MEAPI MdtLinear2GetDirection(const MdtLinear2ID j, MeVector3 direction) {
  static const char *fn = "MdtLinear2GetDirection";
  if (!checkType(j, kLinear2Type, fn)) return;
  ME_REQUIRE_ARG(direction != nullptr, fn, "direction is NULL");
  attachmentAxis(j, 1, direction);
}

}  // extern "C"
