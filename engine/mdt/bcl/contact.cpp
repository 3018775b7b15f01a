// contact.cpp: the contact constraint.
//
// Rows, at the contact point p (body 0's attachment point; against the world,
// body 0's surface point p - (depth/2) n) with normal n (from body 1 into
// body 0), in this order:
//   normal     n . (v0 + w0 x r0 - v1 - w1 x r1) >= speed, force in
//              [-maxAdhesive, inf) (in [0, inf) while apart); softness =
//              params.softness or epsilon;
//              touching (depth >= 0): speed = max(gamma * depth / h,
//              restitution * impact speed when the bodies approach faster
//              than velThreshold);
//              speculative (depth < 0, the shapes a gap g = -depth apart):
//              speed = -g / h, so the bodies may close the gap within the
//              step but no further (the row pushes only if they would);
//              an impact within the step (|vrel| h >= g, vrel the mean of
//              J v at the step's start and after the forces) with
//              restitution e bounces at t* = g / |vrel|: speed =
//              e |vrel| - (1 + e) g / h
//              puts the body where the bounce takes it by the step's end,
//              and after the positions move the bounce speed e |vrel|
//              itself is given (Row::bounceAfter, step/bounce.cpp);
//   primary    along d1 (Friction1D and 2D), target speed slide1, softness
//              slip1 / h (velocity = slip * force) or epsilon; force bound
//              friction1 (Box) or frictionCoefficient1 * normal force
//              (NormalForce, tied to the normal row);
//   secondary  along d2 = n x d1 (Friction2D), likewise.
// d1 is the user's direction when set, else last step's d1 carried onto the
// new tangent plane, else anyOrthogonal(n) (contactDirections): a contact's
// friction rows turn with its normal, and A changes smoothly at rest.
// Rows only for effects that act: a friction direction whose force bound is
// identically zero (Box model with friction 0, NormalForce model with
// coefficient 0) writes no row, since its impulse would be 0 whatever the
// solve (lo = hi = 0); a contact with zero friction in every direction of
// its type writes its normal row alone, exactly as MdtContactTypeFrictionZero.
// A contact without restitution does no bounce work: no relative velocity
// is measured for it and it never asks for a bounce (Row::bounceAfter = 0).
// Warm start: each row starts from the contact's own memory of last step
// (warmNormal; friction: warmFriction projected on d1 and d2).
#include <cmath>

#include "active_sets.h"
#include "contact_internal.h"

using namespace karma::mdt;

namespace karma::mdt {

void resetContact(MdtContact *c) {
  MdtContactParamsReset(&c->params);
  MeVector3Set(c->normal, 0, 1, 0);
  MeVector3Set(c->direction, 0, 0, 0);
  c->directionSet = FALSE;
  c->penetration = 0;
  if (!c->owner) c->next = nullptr;  // a group's contact keeps its place in the group's list
  c->normalForce = 0;
  c->feature = 0;
  c->warmNormal = 0;
  MeVector3Set(c->warmFriction, 0, 0, 0);
  MeVector3Set(c->frictionAxis, 0, 0, 0);
}

bool frictionActs(const MdtContactParams &p, int direction) {
  if ((int)p.type <= direction) return false;
  const bool box = (direction == 0 ? p.model1 : p.model2) == MdtFrictionModelBox;
  const MeReal bound = box ? (direction == 0 ? p.friction1 : p.friction2)
                           : (direction == 0 ? p.frictionCoefficient1 : p.frictionCoefficient2);
  return bound > 0;
}

int contactRowCount(const MdtContact *c) {
  return 1 + (frictionActs(c->params, 0) ? 1 : 0) + (frictionActs(c->params, 1) ? 1 : 0);
}

int storeContactImpulses(MdtContact *c, const Row *rows, const MeReal *impulse, int n) {
  const int written = contactRowCount(c);
  const int count = written < n ? written : n;
  c->warmNormal = count > 0 ? impulse[0] : 0;
  MeVector3Set(c->warmFriction, 0, 0, 0);
  // A friction row's linear Jacobian on body 0 is its direction (frictionRow).
  for (int r = 1; r < count; ++r) MeVector3MultiplyAdd(c->warmFriction, impulse[r], rows[r].J[0]);
  return count;
}

namespace {

// A kept friction axis is given up once its part in the tangent plane is
// this short: the normal has turned by 60 degrees towards it.
constexpr MeReal kKeptAxisShortest = (MeReal)0.5;

// out = the part of v in the plane normal to the unit n, normalised; false
// (out unnormalised) when that part is not longer than `shortest` (> 0, so
// a zero, denormal or NaN length is never divided by).
bool tangentPart(const MeVector3 v, const MeVector3 n, MeReal shortest, MeVector3 out) {
  MeVector3Copy(out, v);
  MeVector3MultiplyAdd(out, -MeVector3Dot(out, n), n);
  const MeReal length = MeVector3Magnitude(out);  // MeVector3Normalize's, computed once
  if (!(length > shortest)) return false;
  MeVector3Scale(out, 1 / length);
  return true;
}

}  // namespace

void contactDirections(const MdtContact *c, MeVector3 d1, MeVector3 d2) {
  // A zero frictionAxis (no rows yet) has no tangent part: never kept.
  const bool user = c->directionSet && tangentPart(c->direction, c->normal, (MeReal)1e-6, d1);
  if (!user && !tangentPart(c->frictionAxis, c->normal, kKeptAxisShortest, d1)) anyOrthogonal(c->normal, d1);
  MeVector3Cross(d2, c->normal, d1);
}

namespace {

// J v* of a row: the velocities predicted from the forces (the step's
// stage 2 runs before the rows are written).
MeReal predictedRowVelocity(const MdtContact *c, const Row &row) {
  MeReal v = 0;
  for (int i = 0; i < 2; ++i) {
    const MdtBody *b = c->body[i];
    if (!b || !b->enabled) continue;
    v += MeVector3Dot(row.J[2 * i], b->vPred) + MeVector3Dot(row.J[2 * i + 1], b->wPred);
  }
  return v;
}

void frictionRow(MdtContact *c, RowSink &sink, const StepContext &ctx, const Anchors &a, const MeVector3 d,
                 int normalRow, MdtFrictionModel model, MeReal limit, MeReal coefficient, MeReal slip, MeReal slide) {
  Row &row = addLinearJacobianRow(sink, ctx, a, d);
  row.role = RowRole::ContactFriction;
  row.contact = c;
  row.depth = c->penetration;
  row.speed = slide;
  row.warm = MeVector3Dot(c->warmFriction, d);
  row.warmSet = true;
  if (slip > 0) row.softness = slip * ctx.invH;
  if (model == MdtFrictionModelNormalForce) {
    row.friction = normalRow;
    row.mu = coefficient;
  } else {
    row.lo = -limit;
    row.hi = limit;
  }
}

// The restitution of a touching contact (depth >= 0): e times the approach
// speed when the bodies approach faster than velThreshold, else 0.
MeReal touchingBounce(const MdtContact *c, const Row &n) {
  const MdtContactParams &prm = c->params;
  const MeReal vrel = rowVelocity(c, n);  // > 0: separating
  return vrel < -prm.velThreshold ? -prm.restitution * vrel : 0;
}

// The restitution of a contact found apart (depth < 0, gap g = -depth):
// when the impact falls within the step, at t = g / |vrel|, the step's
// velocity takes the body where the bounce would have by the step's end and
// the bounce speed itself is given after the positions move (bounceAfter);
// otherwise the row keeps its speed -g / h.
void speculativeBounce(const MdtContact *c, Row &n, const StepContext &ctx) {
  const MdtContactParams &prm = c->params;
  // The approach over the step is the mean of the velocities at its start
  // and after the forces (gravity speeds a falling body up).
  const MeReal approach = (MeReal)0.5 * (rowVelocity(c, n) + predictedRowVelocity(c, n));
  const MeReal gap = -c->penetration;
  const bool impact = -approach * ctx.h >= gap;
  const MeReal bounce = approach < -prm.velThreshold ? -prm.restitution * approach : 0;
  if (impact && bounce > 0) {
    n.speed = bounce - gap * ctx.invH * (1 + prm.restitution);
    n.bounceAfter = bounce;
  }
}

}  // namespace

void addContactRows(MdtContact *c, RowSink &sink, const StepContext &ctx) {
  MeVector3 origin[2];
  for (int i = 0; i < 2; ++i) bodyOrigin(c, i, origin[i]);
  addContactRows(c, sink, ctx, origin);
}

void addContactRows(MdtContact *c, RowSink &sink, const StepContext &ctx, const MeVector3 origin[2]) {
  // Against the world, the body acts at its own surface point: the contact
  // position lies midway between the surfaces, depth d apart along n, so
  // body 0's point is p - (d/2) n. Friction then turns it about its true
  // lever arm (a wheel sunk by the contact's softness still rolls with its
  // radius). Between two bodies both act at p: equal and opposite impulses
  // on one line keep the pair's angular momentum.
  Anchors a;
  attachmentPoint(c, 0, a.p[0]);
  if (!c->body[1]) MeVector3MultiplyAdd(a.p[0], -(MeReal)0.5 * c->penetration, c->normal);
  MeVector3Copy(a.p[1], a.p[0]);
  for (int i = 0; i < 2; ++i) MeVector3Subtract(a.r[i], a.p[i], origin[i]);
  const MdtContactParams &prm = c->params;
  const int normalRow = sink.count();
  Row &n = addLinearJacobianRow(sink, ctx, a, c->normal);  // its speed is set below
  n.role = RowRole::ContactNormal;
  n.contact = c;
  n.depth = c->penetration;
  // Adhesion holds touching bodies only: a speculative row never pulls.
  n.lo = prm.max_adhesive_force > 0 && c->penetration >= 0 ? -prm.max_adhesive_force : 0;
  n.hi = MEINFINITY;
  if (prm.softness > 0) n.softness = prm.softness;
  n.warm = c->warmNormal;
  n.warmSet = true;
  if (c->penetration < 0) {
    n.speed = c->penetration * ctx.invH;  // -gap / h: close the gap, no further
    if (prm.restitution > 0) speculativeBounce(c, n, ctx);
  } else {
    const MeReal correct = ctx.gamma * ctx.invH * c->penetration;
    const MeReal bounce = prm.restitution > 0 ? touchingBounce(c, n) : 0;
    n.speed = bounce > correct ? bounce : correct;
  }
  const bool acts1 = frictionActs(prm, 0), acts2 = frictionActs(prm, 1);
  if (!acts1 && !acts2) return;
  MeVector3 d1, d2;
  contactDirections(c, d1, d2);
  MeVector3Copy(c->frictionAxis, d1);
  if (acts1)
    frictionRow(c, sink, ctx, a, d1, normalRow, prm.model1, prm.friction1, prm.frictionCoefficient1, prm.slip1,
                prm.slide1);
  if (acts2)
    frictionRow(c, sink, ctx, a, d2, normalRow, prm.model2, prm.friction2, prm.frictionCoefficient2, prm.slip2,
                prm.slide2);
}

}  // namespace karma::mdt

namespace {

void reset(MdtConstraint *c) { resetContact(as<MdtContact>(c)); }

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) { addContactRows(as<MdtContact>(c), sink, ctx); }

void afterSolve(MdtConstraint *c, const Row *rows, const MeReal *impulse, int n, const StepContext &ctx) {
  auto *k = as<MdtContact>(c);
  k->normalForce = n > 0 ? impulse[0] * ctx.invH : 0;
  storeContactImpulses(k, rows, impulse, n);
}

// The normal n / |n|; a non-finite or (nearly) zero n is ignored with a
// warning naming fn.
void setNormal(MdtContact *c, const MeVector3 n, const char *fn) {
  ME_REQUIRE_ARG(realFinite3(n[0], n[1], n[2]), fn, "normal is not finite; ignored");
  const MeReal len = MeVector3Magnitude(n);
  ME_REQUIRE_ARG(len > (MeReal)1e-6, fn, "normal has zero length; ignored");
  MeVector3MultiplyScalar(c->normal, n, 1 / len);
}

// The contact parameters, copied; NULL is ignored with a warning naming fn.
void setParams(MdtContact *c, const MdtContactParams *p, const char *fn) {
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  c->params = *p;
}

// The penetration; a non-finite one is ignored with a warning naming fn.
void setPenetration(MdtContact *c, MeReal penetration, const char *fn) {
  ME_REQUIRE_ARG(realFinite(penetration), fn, "penetration is not finite; ignored");
  c->penetration = penetration;
}

void destroy(MdtConstraint *c) {
  auto *contact = as<MdtContact>(c);
  if (contact->owner) MdtContactGroupRemoveContact(static_cast<MdtContactGroup *>(contact->owner), contact);
}

}  // namespace

namespace karma::mdt {
extern const ConstraintType kContactType = {
    MdtConstraintTypeContact, "Contact", sizeof(MdtContact), 3, nullptr, reset, addRows, afterSolve, destroy, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(Contact, kContactType)

extern "C" {

void MEAPI MdtContactSetNormal(const MdtContactID c, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtContactSetNormal";
  if (!checkType(c, kContactType, fn)) return;
  const MeVector3 n = {x, y, z};
  setNormal(c, n, fn);
}

void MEAPI MdtContactGetNormal(const MdtContactID c, MeVector3 normal) {
  if (!checkType(c, kContactType, "MdtContactGetNormal")) return;
  MeVector3Copy(normal, c->normal);
}

void MEAPI MdtContactSetDirection(const MdtContactID c, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtContactSetDirection";
  if (!checkType(c, kContactType, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "direction is not finite; ignored");
  MeVector3 d = {x, y, z};
  ME_REQUIRE_ARG(MeVector3Magnitude(d) > (MeReal)1e-6, fn, "direction has zero length; ignored");
  MeVector3Normalize(d);
  MeVector3Copy(c->direction, d);
  c->directionSet = TRUE;
}

void MEAPI MdtContactGetDirection(const MdtContactID c, MeVector3 direction) {
  if (!checkType(c, kContactType, "MdtContactGetDirection")) return;
  MeVector3 d2;
  contactDirections(c, direction, d2);
}

void MEAPI MdtContactSetPenetration(const MdtContactID c, const MeReal penetration) {
  static const char *fn = "MdtContactSetPenetration";
  if (!checkType(c, kContactType, fn)) return;
  setPenetration(c, penetration, fn);
}

MeReal MEAPI MdtContactGetPenetration(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactGetPenetration")) return 0;
  return c->penetration;
}

MdtContactParamsID MEAPI MdtContactGetParams(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactGetParams")) return nullptr;
  return &c->params;
}

void MEAPI MdtContactSetParams(const MdtContactID c, const MdtContactParamsID p) {
  static const char *fn = "MdtContactSetParams";
  if (!checkType(c, kContactType, fn)) return;
  setParams(c, p, fn);
}

MdtContactID MEAPI MdtContactGetNext(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactGetNext")) return nullptr;
  return c->next;
}

void MEAPI MdtContactSetNext(const MdtContactID c, const MdtContactID next) {
  static const char *fn = "MdtContactSetNext";
  if (!checkType(c, kContactType, fn)) return;
  ME_REQUIRE_ARG(c->owner == nullptr, fn,
                 "the contact belongs to a contact group, which keeps its list (MdtContactGroupAppendContact, "
                 "MdtContactGroupRemoveContact); ignored");
  c->next = next;
}

void MEAPI MdtContactSetFeature(const MdtContactID c, const MeU32 feature) {
  if (!checkType(c, kContactType, "MdtContactSetFeature")) return;
  c->feature = feature;
}

MeU32 MEAPI MdtContactGetFeature(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactGetFeature")) return 0;
  return c->feature;
}

MeReal MEAPI MdtContactGetImpulse(const MdtContactID c, MeVector3 friction) {
  if (!checkType(c, kContactType, "MdtContactGetImpulse")) return 0;
  if (friction) MeVector3Copy(friction, c->warmFriction);
  return c->warmNormal;
}

void MEAPI MdtContactClearImpulse(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactClearImpulse")) return;
  c->warmNormal = 0;
  MeVector3Set(c->warmFriction, 0, 0, 0);
}

MeReal MEAPI MdtContactGetNormalForce(const MdtContactID c) {
  if (!checkType(c, kContactType, "MdtContactGetNormalForce")) return 0;
  return c->normalForce;
}

// The five setters' effects (bridge/mdt_bridge.h), through the helpers they
// use, each field with its own check.
void MEAPI MdtContactSetFromCollision(const MdtContactID c, const MeVector3 position, const MeVector3 normal,
                                      const MeReal penetration, const MdtContactParams *params, const MeU32 feature) {
  static const char *fn = "MdtContactSetFromCollision";
  if (!checkType(c, kContactType, fn)) return;
  setWorldPosition(c, position, fn);
  setNormal(c, normal, fn);
  setPenetration(c, penetration, fn);
  setParams(c, params, fn);
  c->feature = feature;
}

}  // extern "C"

namespace {

// A body's contacts are walked along its constraint list (active_sets.h),
// so a walk costs the body's constraints, not the world's. The contacts
// reached, in the list's order: each enabled stand-alone contact, and the
// contacts of each enabled group in the group's order (a group's contacts
// act between its bodies). An owned contact may still be linked from when
// it stood alone; it is reached through its group only.
bool liveAlone(const MdtConstraint *con) { return con->type == &kContactType && !con->owner && con->enabled; }

MdtContact *firstOfLiveGroup(const MdtConstraint *con) {
  if (con->type != &kContactGroupType || !con->enabled) return nullptr;
  return static_cast<const MdtContactGroup *>(con)->first;
}

// The first contact reached from `con` on, along body's list.
MdtContactID firstFrom(const MdtBody *body, MdtConstraint *con) {
  for (; con; con = nextAtBody(con, body)) {
    if (liveAlone(con)) return static_cast<MdtContact *>(con);
    if (MdtContact *first = firstOfLiveGroup(con)) return first;
  }
  return nullptr;
}

// The list entry through which `c` is reached from body: c itself or its
// group; nullptr when neither is on body's list.
MdtConstraint *entryOf(const MdtBody *body, MdtContact *c) {
  MdtConstraint *entry = c->owner ? c->owner : c;
  return entry->linked[0] == body || entry->linked[1] == body ? entry : nullptr;
}

}  // namespace

extern "C" {

MdtContactID MEAPI MdtBodyGetFirstContact(const MdtBodyID body) {
  ME_REQUIRE_ARG_RET(body != nullptr, nullptr, "MdtBodyGetFirstContact", "body is NULL");
  return firstFrom(body, body->firstConstraint);
}

MdtContactID MEAPI MdtBodyGetNextContact(const MdtBodyID body, const MdtContactID c) {
  ME_REQUIRE_ARG_RET(body != nullptr && c != nullptr, nullptr, "MdtBodyGetNextContact", "NULL argument");
  static const char *fn = "MdtBodyGetNextContact";
  if (!checkType(c, kContactType, fn)) return nullptr;
  MdtConstraint *entry = entryOf(body, c);
  ME_REQUIRE_ARG_RET(entry != nullptr, nullptr, fn, "the contact does not act on this body");
  if (c->owner && c->owner->enabled && c->next) return c->next;
  return firstFrom(body, nextAtBody(entry, body));
}

}  // extern "C"
