// universal.cpp: the universal (Cardan) joint.
//
// The cross of the joint is body 0's primary axis a0 and body 1's SECONDARY
// axis b1 (so that the frames MdtConstraintSetBodies gives -- world x and y
// in both bodies -- are the guide's defaults: x in body 0, y in body 1).
//
// Rows, in this order:
//   0-2  ball-and-socket rows:  p0 - p1 = 0;
//   3    one angular row about e = (a0 x b1) / |a0 x b1| keeping a0 and b1
//        perpendicular. With delta = asin(a0 . b1) the deviation from
//        perpendicular, d(delta)/dt = e . (w0 - w1), so the row's error is
//        -delta. When a0 and b1 are parallel (the worst violation) e is any
//        direction orthogonal to a0.
#include <cmath>

#include "MdtUniversal.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtUniversal : MdtConstraint {};

namespace {

void reset(MdtConstraint *) {}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  addPointRows(sink, ctx, anchorsOf(c));
  MeVector3 a0, b1, e;
  attachmentAxis(c, 0, a0);
  attachmentOrtho(c, 1, b1);
  MeVector3Cross(e, a0, b1);
  const MeReal len = MeVector3Magnitude(e);
  if (len > (MeReal)1e-6)
    MeVector3Scale(e, 1 / len);
  else
    anyOrthogonal(a0, e);
  MeReal s = MeVector3Dot(a0, b1);
  s = s > 1 ? 1 : (s < -1 ? -1 : s);
  addAngularRow(sink, ctx, e, -std::asin(s));
}

// Body i's universal axis: the primary for body 0, the secondary for body 1.
// Sets it to world direction d (unit), keeping the other axis of that body's
// frame as close to what it was as orthogonality allows.
void setBodyCrossAxis(MdtConstraint *c, int i, const MeVector3 d) {
  MeVector3 other;
  if (i == 0)
    attachmentOrtho(c, 0, other);
  else
    attachmentAxis(c, 1, other);
  MeVector3MultiplyAdd(other, -MeVector3Dot(other, d), d);
  if (MeVector3Magnitude(other) < (MeReal)1e-3)
    anyOrthogonal(d, other);
  else
    MeVector3Normalize(other);
  const MeReal *primary = i == 0 ? d : other;
  const MeReal *ortho = i == 0 ? other : d;
  toBodyFrame(c, i, primary, c->localAxis[i]);
  toBodyFrame(c, i, ortho, c->localOrtho[i]);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kUniversalType = {MdtConstraintTypeUniversal,
                                              "Universal",
                                              sizeof(MdtUniversal),
                                              4,
                                              nullptr,
                                              reset,
                                              addRows,
                                              nullptr,
                                              nullptr,
                                              nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Universal, kUniversalType)

extern "C" {

void MEAPI MdtUniversalSetAxis(const MdtUniversalID j, const unsigned int bodyindex, const MeReal x, const MeReal y,
                               const MeReal z) {
  static const char *fn = "MdtUniversalSetAxis";
  if (!checkType(j, kUniversalType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  MeVector3 d = {x, y, z};
  if (!unitDirection(d, fn, "the axis")) return;
  setBodyCrossAxis(j, (int)bodyindex, d);
  j->warmRows = 0;
}

void MEAPI MdtUniversalGetAxis(const MdtUniversalID j, const unsigned int bodyindex, MeVector3 axis) {
  static const char *fn = "MdtUniversalGetAxis";
  if (!checkType(j, kUniversalType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  if (bodyindex == 0)
    attachmentAxis(j, 0, axis);
  else
    attachmentOrtho(j, 1, axis);
}

void MEAPI MdtUniversalSetAxes(const MdtUniversalID j, const unsigned int bodyindex, const MeReal px, const MeReal py,
                               const MeReal pz, const MeReal ox, const MeReal oy, const MeReal oz) {
  static const char *fn = "MdtUniversalSetAxes";
  if (!checkType(j, kUniversalType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
  if (!unitDirection(p, fn, "the primary axis") || !unitDirection(o, fn, "the secondary axis")) return;
  const MeReal cosine = MeVector3Dot(p, o);
  if (std::fabs(cosine) > (MeReal)1e-3) {
    MeWarning(0, "%s: the axes are not orthogonal (cosine %g); ignored", fn, (double)cosine);
    return;
  }
  MdtConstraintBodySetAxes(j, bodyindex, p[0], p[1], p[2], o[0], o[1], o[2]);
  j->warmRows = 0;
}

void MEAPI MdtUniversalGetAxes(const MdtUniversalID j, const unsigned int bodyindex, MeVector3 primary,
                               MeVector3 ortho) {
  static const char *fn = "MdtUniversalGetAxes";
  if (!checkType(j, kUniversalType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(primary != nullptr && ortho != nullptr, fn, "NULL argument");
  attachmentAxis(j, (int)bodyindex, primary);
  attachmentOrtho(j, (int)bodyindex, ortho);
}

}  // extern "C"
