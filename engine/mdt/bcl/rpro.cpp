// rpro.cpp: the RPRO joint's rows (see MdtRPROJoint.h).
//
// F0 = (e0, e1, e2) body 0's attachment axes (world), p0, p1 the points.
// Rows, in this order:
//   0-2  linear along e_k: e_k . (p1 - p0) -> 0, body 0's lever arm taken to
//        p1 (as in the prismatic joint); force bounds +-linearStrength[k];
//   3-5  angular about e_k. With c the present relative quaternion and q the
//        target (both in F0 axes), the turn still to make is
//        qe = q c^-1 (Hamilton), rotation vector phi (F0 axes). The rows ask
//        for w1 - w0 = W + gamma phi / h, i.e. J v = e_k . (w0 - w1) =
//        -W[k] - gamma phi[k] / h; torque bounds +-angularStrength[k].
// A saturated row (its bound reached) simply gives way: the error it leaves
// is corrected by gamma once the load falls back under the strength.
#include "frame_rotation.h"
#include "rpro.h"

using namespace karma::mdt;

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtRPROJoint>(c);
  MeQuaternionMakeIdentity(j->relativeQ);
  MeVector3Set(j->relativeW, 0, 0, 0);
  MeVector3Set(j->linearStrength, MEINFINITY, MEINFINITY, MEINFINITY);
  MeVector3Set(j->angularStrength, MEINFINITY, MEINFINITY, MEINFINITY);
}

// Bodies' own axes at their centres of mass; the world's frame where body
// 0's is now.
void attach(MdtConstraint *c) {
  for (int i = 0; i < 2; ++i) {
    MeVector3Set(c->localAxis[i], 1, 0, 0);
    MeVector3Set(c->localOrtho[i], 0, 1, 0);
    MeVector3Set(c->localPos[i], 0, 0, 0);
    if (c->body[i]) MeMatrix4TMGetPosition(c->localPos[i], c->body[i]->comTM);
  }
  if (c->body[0] && !c->body[1]) {
    attachmentPoint(c, 0, c->localPos[1]);
    attachmentAxis(c, 0, c->localAxis[1]);
    attachmentOrtho(c, 0, c->localOrtho[1]);
  }
}

void bound(Row &row, MeReal strength) {
  if (strength >= MEINFINITY) return;
  row.lo = -strength;
  row.hi = strength;
  row.role = RowRole::Limit;  // bounded: never capped, like a motor
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtRPROJoint>(c);
  MeMatrix3 F0;
  frameRows(c, 0, F0);
  Anchors a = anchorsOf(c);
  MeVector3 x0;
  bodyOrigin(c, 0, x0);
  MeVector3Subtract(a.r[0], a.p[1], x0);
  for (int k = 0; k < 3; ++k) bound(addLinearRow(sink, ctx, a, F0[k]), j->linearStrength[k]);

  MeVector4 cur, inv, err;
  MeVector3 phi;
  relativeQuaternion(c, cur);
  MeQuaternionConjugate(inv, cur);
  MeQuaternionMultiply(err, inv, j->relativeQ);  // "c^-1, then q" = q c^-1
  rotationVector(err, phi);
  for (int k = 0; k < 3; ++k) {
    Row &row = addAngularRow(sink, ctx, F0[k], -phi[k]);
    row.speed -= j->relativeW[k];
    bound(row, j->angularStrength[k]);
  }
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kRPROJointType = {MdtConstraintTypeRPROJoint,
                                              "RPROJoint",
                                              sizeof(MdtRPROJoint),
                                              6,
                                              nullptr,
                                              reset,
                                              addRows,
                                              nullptr,
                                              nullptr,
                                              attach};
}

MDT_DEFINE_CONSTRAINT_TYPE(RPROJoint, kRPROJointType)
