// angular3.cpp: the Angular3 joint (and Angular2 when rotation is enabled).
//
// Frames: a0, o0, n0 = a0 x o0 are body 0's attachment axes in the world;
// r is frameRotationError, the small rotation turning body 0's frame onto
// body 1's.
//
// Rows, in this order:
//   0    about a0 with error r . a0 -- left out while rotation is enabled;
//   1    about o0 with error r . o0;
//   2    about n0 with error r . n0.
// Each row is rigid when the stiffness is MEINFINITY, otherwise a damped
// spring (springRow) of that stiffness and damping, so a torque T about a
// locked axis settles at an angle T / stiffness (joint_input.h). The
// positions are free.
#include "MdtAngular3.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtAngular3 : MdtConstraint {
  MeBool rotationEnabled;
  MeReal stiffness;
  MeReal damping;
};

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtAngular3>(c);
  j->rotationEnabled = FALSE;
  j->stiffness = MEINFINITY;
  j->damping = MEINFINITY;
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtAngular3>(c);
  if (isInert(j->stiffness, j->damping)) return;
  MeVector3 axes[3], r;
  attachmentAxis(c, 0, axes[0]);
  attachmentOrtho(c, 0, axes[1]);
  MeVector3Cross(axes[2], axes[0], axes[1]);
  frameRotationError(c, r);
  for (int k = j->rotationEnabled ? 1 : 0; k < 3; ++k) {
    const MeReal error = MeVector3Dot(r, axes[k]);
    Row &row = addAngularRow(sink, ctx, axes[k], error);
    if (!isRigid(j->stiffness)) makeSpring(row, ctx, j->stiffness, j->damping, error);
  }
}

// Locking the axis again holds the present turn about it: body 1's secondary
// axis is moved onto body 0's (projected normal to body 1's primary axis), so
// the joint does not snap back through the turn made while it was free.
void relockTwist(MdtConstraint *c) {
  MeVector3 a1, o0;
  attachmentAxis(c, 1, a1);
  attachmentOrtho(c, 0, o0);
  MeVector3MultiplyAdd(o0, -MeVector3Dot(o0, a1), a1);
  if (MeVector3Magnitude(o0) < (MeReal)1e-3) return;
  MeVector3Normalize(o0);
  toBodyFrame(c, 1, o0, c->localOrtho[1]);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kAngular3Type = {
    MdtConstraintTypeAngular3, "Angular3", sizeof(MdtAngular3), 3, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Angular3, kAngular3Type)

extern "C" {

void MEAPI MdtAngular3EnableRotation(const MdtAngular3ID j, const MeBool on) {
  if (!checkType(j, kAngular3Type, "MdtAngular3EnableRotation")) return;
  if (j->rotationEnabled && !on) relockTwist(j);
  j->rotationEnabled = on ? TRUE : FALSE;
  j->warmRows = 0;
}

MeBool MEAPI MdtAngular3RotationIsEnabled(const MdtAngular3ID j) {
  if (!checkType(j, kAngular3Type, "MdtAngular3RotationIsEnabled")) return FALSE;
  return j->rotationEnabled;
}

void MEAPI MdtAngular3SetAxis(const MdtAngular3ID j, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtAngular3SetAxis";
  if (!checkType(j, kAngular3Type, fn)) return;
  MeVector3 a = {x, y, z};
  if (!unitDirection(a, fn, "the axis")) return;
  MdtConstraintSetAxis(j, a[0], a[1], a[2]);
  j->warmRows = 0;
}

void MEAPI MdtAngular3GetAxis(const MdtAngular3ID j, MeVector3 axis) {
  static const char *fn = "MdtAngular3GetAxis";
  if (!checkType(j, kAngular3Type, fn)) return;
  ME_REQUIRE_ARG(axis != nullptr, fn, "axis is NULL");
  attachmentAxis(j, 0, axis);
}

void MEAPI MdtAngular3SetStiffness(const MdtAngular3ID j, const MeReal k) {
  static const char *fn = "MdtAngular3SetStiffness";
  if (!checkType(j, kAngular3Type, fn) || !nonNegative(k, fn, "stiffness")) return;
  j->stiffness = k > MEINFINITY ? MEINFINITY : k;
}

MeReal MEAPI MdtAngular3GetStiffness(const MdtAngular3ID j) {
  if (!checkType(j, kAngular3Type, "MdtAngular3GetStiffness")) return 0;
  return j->stiffness;
}

void MEAPI MdtAngular3SetDamping(const MdtAngular3ID j, const MeReal d) {
  static const char *fn = "MdtAngular3SetDamping";
  if (!checkType(j, kAngular3Type, fn) || !nonNegative(d, fn, "damping")) return;
  j->damping = d > MEINFINITY ? MEINFINITY : d;
}

MeReal MEAPI MdtAngular3GetDamping(const MdtAngular3ID j) {
  if (!checkType(j, kAngular3Type, "MdtAngular3GetDamping")) return 0;
  return j->damping;
}

}  // extern "C"
