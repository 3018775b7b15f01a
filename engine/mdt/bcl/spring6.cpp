// spring6.cpp: the six-degree-of-freedom spring (see MdtSpring6.h).
//
// Frames: F0 = (e0, e1, e2) body 0's attachment axes in the world, p0, p1
// the attachment points.
// Rows, in this order, each left out when its axis is free (isInert):
//   0-2  linear along e_k with error e_k . (p1 - p0), body 0's lever arm
//        taken to p1 (so J v is the exact rate of e_k . (p1 - p0) with e_k
//        turning with body 0, as in the prismatic joint);
//   3-5  angular about e_k with error phi_k, phi the exact rotation vector of
//        the relative rotation in frame 0 (frame_rotation.h). Its rate is
//        e_k . (w1 - w0) to first order; at rest the torque K phi_k is exact.
// Rigid rows (K = MEINFINITY) use the world's softness and gamma; the others
// are damped springs (makeSpring), force K * error.
#include "MdtSpring6.h"
#include "bcl_type.h"
#include "frame_rotation.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtSpring6 : MdtConstraint {
  MeReal k[6], c[6];  // linear x, y, z then angular x, y, z
};

namespace karma::mdt {
extern const ConstraintType kSpring6Type;
}

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtSpring6>(c);
  for (int i = 0; i < 6; ++i) j->k[i] = j->c[i] = MEINFINITY;
}

void finish(const MdtSpring6 *j, int i, Row &row, const StepContext &ctx, MeReal error) {
  if (!isRigid(j->k[i])) makeSpring(row, ctx, j->k[i], j->c[i], error);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtSpring6>(c);
  MeMatrix3 F0;
  frameRows(c, 0, F0);
  Anchors a = anchorsOf(c);
  MeVector3 x0, gap;
  bodyOrigin(c, 0, x0);
  MeVector3Subtract(a.r[0], a.p[1], x0);
  MeVector3Subtract(gap, a.p[1], a.p[0]);
  for (int i = 0; i < 3; ++i) {
    if (isInert(j->k[i], j->c[i])) continue;
    Row &row = addLinearRow(sink, ctx, a, F0[i]);
    finish(j, i, row, ctx, MeVector3Dot(F0[i], gap));
  }
  MeVector4 q;
  MeVector3 phi;
  relativeQuaternion(c, q);
  rotationVector(q, phi);  // frame 0 coordinates
  for (int i = 0; i < 3; ++i) {
    if (isInert(j->k[3 + i], j->c[3 + i])) continue;
    Row &row = addAngularRow(sink, ctx, F0[i], phi[i]);
    finish(j, 3 + i, row, ctx, phi[i]);
  }
}

bool axisOk(unsigned axis, const char *fn) {
  if (axis > 2) {
    MeWarning(0, "%s: axis %u is not 0, 1 or 2; ignored", fn, axis);
    return false;
  }
  return true;
}

// Stiffness (damping when `damping`) of axis `axis` of the linear (first =
// 0) or angular (first = 3) springs.
void setValue(MdtSpring6 *j, bool damping, int first, unsigned axis, MeReal v, const char *fn) {
  if (!checkType(j, kSpring6Type, fn) || !axisOk(axis, fn) || !nonNegative(v, fn, damping ? "damping" : "stiffness"))
    return;
  MeReal *arr = damping ? j->c : j->k;
  arr[first + (int)axis] = v > MEINFINITY ? MEINFINITY : v;
  j->warmRows = 0;
}

MeReal getValue(const MdtSpring6 *j, bool damping, int first, unsigned axis, const char *fn) {
  if (!checkType(j, kSpring6Type, fn) || !axisOk(axis, fn)) return 0;
  return (damping ? j->c : j->k)[first + (int)axis];
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kSpring6Type = {
    MdtConstraintTypeSpring6, "Spring6", sizeof(MdtSpring6), 6, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Spring6, kSpring6Type)

extern "C" {

void MEAPI MdtSpring6SetAxes(const MdtSpring6ID j, const MeReal px, const MeReal py, const MeReal pz, const MeReal ox,
                             const MeReal oy, const MeReal oz) {
  static const char *fn = "MdtSpring6SetAxes";
  if (!checkType(j, kSpring6Type, fn)) return;
  MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
  if (!orthogonalAxes(p, o, fn)) return;
  setWorldAxes(j, p, o);
  j->warmRows = 0;
}

void MEAPI MdtSpring6GetAxes(const MdtSpring6ID j, MeVector3 primary, MeVector3 secondary) {
  static const char *fn = "MdtSpring6GetAxes";
  if (!checkType(j, kSpring6Type, fn)) return;
  ME_REQUIRE_ARG(primary != nullptr && secondary != nullptr, fn, "NULL argument");
  attachmentAxis(j, 0, primary);
  attachmentOrtho(j, 0, secondary);
}

void MEAPI MdtSpring6SetLinearStiffness(const MdtSpring6ID j, const unsigned int a, const MeReal k) {
  setValue(j, false, 0, a, k, "MdtSpring6SetLinearStiffness");
}
void MEAPI MdtSpring6SetLinearDamping(const MdtSpring6ID j, const unsigned int a, const MeReal c) {
  setValue(j, true, 0, a, c, "MdtSpring6SetLinearDamping");
}
void MEAPI MdtSpring6SetAngularStiffness(const MdtSpring6ID j, const unsigned int a, const MeReal k) {
  setValue(j, false, 3, a, k, "MdtSpring6SetAngularStiffness");
}
void MEAPI MdtSpring6SetAngularDamping(const MdtSpring6ID j, const unsigned int a, const MeReal c) {
  setValue(j, true, 3, a, c, "MdtSpring6SetAngularDamping");
}
MeReal MEAPI MdtSpring6GetLinearStiffness(const MdtSpring6ID j, const unsigned int a) {
  return getValue(j, false, 0, a, "MdtSpring6GetLinearStiffness");
}
MeReal MEAPI MdtSpring6GetLinearDamping(const MdtSpring6ID j, const unsigned int a) {
  return getValue(j, true, 0, a, "MdtSpring6GetLinearDamping");
}
MeReal MEAPI MdtSpring6GetAngularStiffness(const MdtSpring6ID j, const unsigned int a) {
  return getValue(j, false, 3, a, "MdtSpring6GetAngularStiffness");
}
MeReal MEAPI MdtSpring6GetAngularDamping(const MdtSpring6ID j, const unsigned int a) {
  return getValue(j, true, 3, a, "MdtSpring6GetAngularDamping");
}

}  // extern "C"
