// spring.cpp: the spring (distance) joint.
//
// p0, p1 the attachment points, d = |p1 - p0| the length, e = (p1 - p0)/d
// (the last direction when d ~ 0). With r_i = p_i - x_i,
//   dd/dt = e . (v1 + w1 x r1) - e . (v0 + w0 x r0),
// the Jacobian {-e, e x r0, e, r1 x e}.
//
// Rows: when both stops are at the same length L and of the same kind, one
// two-sided row: rigid (gamma (L - d) / h, less the chord correction of
// curvatureSpeed) for hard stops, or a damped
// spring (springRow, error L - d: force k (L - d)) for soft ones. Otherwise
// the limit's one-sided stop rows (addLimitRows). Then the motor, if on.
#include "MdtSpring.h"
#include "bcl_type.h"
#include "joint_input.h"

using namespace karma::mdt;

struct MdtSpring : MdtConstraint {
  MdtLimit limit;
  MeVector3 lastDirection;  // world
  MeBool lengthSet;         // SetNaturalLength was called
};

namespace {

bool hard(const MdtLimit &l, const MdtSingleLimit &s) {
  return s.stiffness > l.stiffnessThreshold || s.stiffness >= MEINFINITY;
}

MeReal length(const MdtConstraint *c) {
  MeVector3 p0, p1;
  attachmentPoint(c, 0, p0);
  attachmentPoint(c, 1, p1);
  return MeVector3Distance(p0, p1);
}

void followSeparation(MdtSpring *j) {
  if (j->lengthSet) return;
  const MeReal d = length(j);
  j->limit.limit[0].stop = d;
  j->limit.limit[1].stop = d;
}

void reset(MdtConstraint *c) {
  auto *j = as<MdtSpring>(c);
  MdtLimitReset(&j->limit);
  for (MdtSingleLimit &s : j->limit.limit) {
    s.stiffness = 10;
    s.damping = 1;
    s.restitution = 0;
  }
  j->limit.limited = TRUE;
  j->limit.calculatePosition = TRUE;
  MeVector3Set(j->lastDirection, 1, 0, 0);
  j->lengthSet = FALSE;
}

// Each body's own origin (Appendix A: pos1 = pos2 = (0, 0, 0)).
void attach(MdtConstraint *c) {
  for (int i = 0; i < 2; ++i) MeVector3Set(c->localPos[i], 0, 0, 0);
  followSeparation(as<MdtSpring>(c));
}

// A rod whose ends move apart sideways at u_perp lengthens by
// h^2 |u_perp|^2 / (2 d) in a step even at zero radial speed (the chord of
// the circle), which gamma alone only holds at ~(u h)^2 / (2 d gamma). The
// rod row asks for that much radial closing speed in advance:
// h |u_perp|^2 / (2 d).
MeReal curvatureSpeed(const MdtConstraint *c, const Anchors &a, const MeVector3 e, MeReal d, const StepContext &ctx) {
  if (!(d > 0)) return 0;
  MeVector3 u0, u1, u;
  pointVelocity(c, 0, a.p[0], u0);
  pointVelocity(c, 1, a.p[1], u1);
  MeVector3Subtract(u, u1, u0);
  MeVector3MultiplyAdd(u, -MeVector3Dot(u, e), e);
  return ctx.h * MeVector3Dot(u, u) / (2 * d);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *j = as<MdtSpring>(c);
  const Anchors a = anchorsOf(c);
  MeVector3 e;
  MeVector3Subtract(e, a.p[1], a.p[0]);
  const MeReal d = MeVector3Magnitude(e);
  if (d > (MeReal)1e-9 * (1 + MeVector3Magnitude(a.p[0]))) {
    MeVector3Scale(e, 1 / d);
    MeVector3Copy(j->lastDirection, e);
  } else {
    MeVector3Copy(e, j->lastDirection);
  }
  MeReal jac[4][3];
  MeVector3MultiplyScalar(jac[0], e, -1);
  MeVector3Cross(jac[1], e, a.r[0]);
  MeVector3Copy(jac[2], e);
  MeVector3Cross(jac[3], a.r[1], e);

  MdtLimit &l = j->limit;
  const MdtSingleLimit &lo = l.limit[0], &hi = l.limit[1];
  const bool twoSided = l.limited && lo.stop == hi.stop && hard(l, lo) == hard(l, hi) &&
                        (hard(l, lo) || (lo.stiffness == hi.stiffness && lo.damping == hi.damping));
  if (!twoSided) {
    // A side switched off must never be the "nearer" stop, or a string
    // (lower off) would have no speculative upper stop just short of L.
    MdtLimit stops = l;
    if (isInert(lo.stiffness, lo.damping)) stops.limit[0].stop = -MEINFINITY;
    if (isInert(hi.stiffness, hi.damping)) stops.limit[1].stop = MEINFINITY;
    addLimitRows(&stops, c, sink, ctx, jac, d, false);
    l.position = stops.position;
    l.velocity = stops.velocity;
    return;
  }
  if (hard(l, lo) || !isInert(lo.stiffness, lo.damping)) {
    Row &row = sink.add(ctx);
    for (int k = 0; k < 4; ++k) MeVector3Copy(row.J[k], jac[k]);
    const MeReal error = lo.stop - d;  // J v > 0 lengthens: reduces L - d
    if (hard(l, lo))
      row.speed = ctx.gamma * ctx.invH * error - curvatureSpeed(c, a, e, d, ctx);
    else
      springRow(row, ctx, lo.stiffness, lo.damping, error);
  }
  MdtLimit motor = l;  // the motor alone
  motor.limited = FALSE;
  addLimitRows(&motor, c, sink, ctx, jac, d, false);
  l.position = motor.position;
  l.velocity = motor.velocity;
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kSpringType = {
    MdtConstraintTypeSpring, "Spring", sizeof(MdtSpring), 2, nullptr, reset, addRows, nullptr, nullptr, attach};
}

MDT_DEFINE_CONSTRAINT_TYPE(Spring, kSpringType)

extern "C" {

void MEAPI MdtSpringSetPosition(const MdtSpringID j, const unsigned int i, const MeReal x, const MeReal y,
                                const MeReal z) {
  static const char *fn = "MdtSpringSetPosition";
  if (!checkType(j, kSpringType, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "position is not finite; ignored");
  const MeVector3 p = {x, y, z};
  pointToBodyFrame(j, (int)i, p, j->localPos[i]);
  followSeparation(j);
  j->warmRows = 0;
}

void MEAPI MdtSpringGetPosition(const MdtSpringID j, MeVector3 position, const unsigned int i) {
  static const char *fn = "MdtSpringGetPosition";
  if (!checkType(j, kSpringType, fn) || !bodyIndexOk(i, fn)) return;
  ME_REQUIRE_ARG(position != nullptr, fn, "position is NULL");
  attachmentPoint(j, (int)i, position);
}

MdtLimitID MEAPI MdtSpringGetLimit(const MdtSpringID j) {
  return checkType(j, kSpringType, "MdtSpringGetLimit") ? &j->limit : nullptr;
}

void MEAPI MdtSpringSetLimit(const MdtSpringID j, const MdtLimitID limit) {
  static const char *fn = "MdtSpringSetLimit";
  if (!checkType(j, kSpringType, fn)) return;
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  j->limit = *limit;
  j->lengthSet = TRUE;
}

void MEAPI MdtSpringSetNaturalLength(const MdtSpringID j, const MeReal L) {
  static const char *fn = "MdtSpringSetNaturalLength";
  if (!checkType(j, kSpringType, fn)) return;
  ME_REQUIRE_ARG(L >= 0 && realFinite(L), fn, "length %g must be finite and >= 0; ignored", (double)L);
  j->limit.limit[0].stop = L;
  j->limit.limit[1].stop = L;
  j->lengthSet = TRUE;
}

void MEAPI MdtSpringSetStiffness(const MdtSpringID j, const MeReal k) {
  static const char *fn = "MdtSpringSetStiffness";
  if (!checkType(j, kSpringType, fn) || !nonNegative(k, fn, "stiffness")) return;
  for (MdtSingleLimit &s : j->limit.limit) s.stiffness = k > MEINFINITY ? MEINFINITY : k;
}

void MEAPI MdtSpringSetDamping(const MdtSpringID j, const MeReal c) {
  static const char *fn = "MdtSpringSetDamping";
  if (!checkType(j, kSpringType, fn)) return;
  ME_REQUIRE_ARG(c >= 0 && realFinite(c), fn, "damping %g must be finite and >= 0; ignored", (double)c);
  for (MdtSingleLimit &s : j->limit.limit) s.damping = c;
}

MeReal MEAPI MdtSpringGetNaturalLength(const MdtSpringID j) {
  return checkType(j, kSpringType, "MdtSpringGetNaturalLength") ? j->limit.limit[1].stop : 0;
}
MeReal MEAPI MdtSpringGetStiffness(const MdtSpringID j) {
  return checkType(j, kSpringType, "MdtSpringGetStiffness") ? j->limit.limit[1].stiffness : 0;
}
MeReal MEAPI MdtSpringGetDamping(const MdtSpringID j) {
  return checkType(j, kSpringType, "MdtSpringGetDamping") ? j->limit.limit[1].damping : 0;
}
MeReal MEAPI MdtSpringGetLength(const MdtSpringID j) {
  return checkType(j, kSpringType, "MdtSpringGetLength") ? length(j) : 0;
}

}  // extern "C"
