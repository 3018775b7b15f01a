// fixed_path.cpp: the fixed-path joint -- a ball and socket whose
// attachment points move within their bodies.
//
// Each body i has an attachment point p_i and a path velocity u_i, the
// velocity of that point relative to body i, stored in body i's frame (R_i
// its rotation; the world frame for the world). The joint holds p0 = p1, so
//   d/dt (p0 - p1) = v0 + w0 x r0 + R0 u0 - v1 - w1 x r1 - R1 u1 = 0.
//
// Rows, in this order: along world x, y, z (k = 0..2),
//   J v = e_k . (v0 + w0 x r0 - v1 - w1 x r1)
//       = e_k . (R1 u1 - R0 u0) + gamma * e_k . (p1 - p0) / h.
// After the solve each point advances by h * u_i within its body, so a
// constant path velocity needs no further calls; an animation that sets
// the position every step simply overrides it.
#include "MdtFixedPath.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtFixedPath : MdtConstraint {
  MeVector3 pathVelocity[2];  // body frames
};

namespace {

void reset(MdtConstraint *c) {
  auto *j = as<MdtFixedPath>(c);
  for (int i = 0; i < 2; ++i) MeVector3Set(j->pathVelocity[i], 0, 0, 0);
}

// R_i u_i: body i's path velocity in the world frame.
void worldPathVelocity(const MdtFixedPath *j, int i, MeVector3 out) {
  if (j->body[i])
    MeMatrix4TMRotate(out, j->body[i]->tm, j->pathVelocity[i]);
  else
    MeVector3Copy(out, j->pathVelocity[i]);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtFixedPath>(c);
  const Anchors a = anchorsOf(c);
  MeVector3 u0, u1, du;
  worldPathVelocity(j, 0, u0);
  worldPathVelocity(j, 1, u1);
  MeVector3Subtract(du, u1, u0);
  for (int k = 0; k < 3; ++k) {
    MeVector3 e = {0, 0, 0};
    e[k] = 1;
    Row &row = addLinearRow(sink, ctx, a, e);
    row.speed += du[k];
  }
}

void afterSolve(MdtConstraint *c, const Row *, const MeReal *, int, const StepContext &ctx) {
  auto *j = as<MdtFixedPath>(c);
  for (int i = 0; i < 2; ++i) MeVector3MultiplyAdd(j->localPos[i], ctx.h, j->pathVelocity[i]);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kFixedPathType = {MdtConstraintTypeFixedPath,
                                              "FixedPath",
                                              sizeof(MdtFixedPath),
                                              3,
                                              nullptr,
                                              reset,
                                              addRows,
                                              afterSolve,
                                              nullptr,
                                              nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(FixedPath, kFixedPathType)

extern "C" {

void MEAPI MdtFixedPathSetPosition(const MdtFixedPathID j, const unsigned int bodyindex, const MeReal x, const MeReal y,
                                   const MeReal z) {
  static const char *fn = "MdtFixedPathSetPosition";
  if (!checkType(j, kFixedPathType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "position is not finite; ignored");
  MdtConstraintBodySetPosition(j, bodyindex, x, y, z);
}

void MEAPI MdtFixedPathGetPosition(const MdtFixedPathID j, const unsigned int bodyindex, MeVector3 position) {
  static const char *fn = "MdtFixedPathGetPosition";
  if (!checkType(j, kFixedPathType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(position != nullptr, fn, "position is NULL");
  attachmentPoint(j, (int)bodyindex, position);
}

void MEAPI MdtFixedPathSetVelocity(const MdtFixedPathID j, const unsigned int bodyindex, const MeReal x, const MeReal y,
                                   const MeReal z) {
  static const char *fn = "MdtFixedPathSetVelocity";
  if (!checkType(j, kFixedPathType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "velocity is not finite; ignored");
  MeVector3Set(j->pathVelocity[bodyindex], x, y, z);
}

void MEAPI MdtFixedPathGetVelocity(const MdtFixedPathID j, const unsigned int bodyindex, MeVector3 velocity) {
  static const char *fn = "MdtFixedPathGetVelocity";
  if (!checkType(j, kFixedPathType, fn) || !bodyIndexOk(bodyindex, fn)) return;
  ME_REQUIRE_ARG(velocity != nullptr, fn, "velocity is NULL");
  MeVector3Copy(velocity, j->pathVelocity[bodyindex]);
}

}  // extern "C"
