// constraint_frames.cpp: the attachment frames of a constraint (one point and
// two orthogonal axes per body, stored in the body's frame) and the base API
// that sets and reads them in world coordinates.
#include <cmath>

#include "MeMessage.h"
#include "constraint.h"

namespace karma::mdt {

void resetKeepingBodies(MdtConstraint *c) {
  MdtBodyID b0 = c->body[0], b1 = c->body[1];
  resetBase(c);
  c->body[0] = b0;
  c->body[1] = b1;
  attachDefault(c);
  c->type->reset(c);
  if (c->type->attach) c->type->attach(c);
}

void toBodyFrame(const MdtConstraint *c, int i, const MeVector3 world, MeVector3 local) {
  if (c->body[i])
    MeMatrix4TMInverseRotate(local, c->body[i]->tm, world);
  else
    MeVector3Copy(local, world);
}

void pointToBodyFrame(const MdtConstraint *c, int i, const MeVector3 world, MeVector3 local) {
  if (c->body[i])
    MeMatrix4TMInverseTransform(local, c->body[i]->tm, world);
  else
    MeVector3Copy(local, world);
}

void attachmentPoint(const MdtConstraint *c, int i, MeVector3 out) {
  if (c->body[i])
    MeMatrix4TMTransform(out, c->body[i]->tm, c->localPos[i]);
  else
    MeVector3Copy(out, c->localPos[i]);
}

void attachmentAxis(const MdtConstraint *c, int i, MeVector3 out) {
  if (c->body[i])
    MeMatrix4TMRotate(out, c->body[i]->tm, c->localAxis[i]);
  else
    MeVector3Copy(out, c->localAxis[i]);
}

void attachmentOrtho(const MdtConstraint *c, int i, MeVector3 out) {
  if (c->body[i])
    MeMatrix4TMRotate(out, c->body[i]->tm, c->localOrtho[i]);
  else
    MeVector3Copy(out, c->localOrtho[i]);
}

void setWorldAxes(MdtConstraint *c, const MeVector3 primary, const MeVector3 ortho) {
  for (int i = 0; i < 2; ++i) {
    toBodyFrame(c, i, primary, c->localAxis[i]);
    toBodyFrame(c, i, ortho, c->localOrtho[i]);
  }
}

void anyOrthogonal(const MeVector3 n, MeVector3 out) {
  MeVector3 q;
  MeVector3PlaneSpace(n, out, q);
}

void bodyOrigin(const MdtConstraint *c, int i, MeVector3 out) {
  if (c->body[i])
    bodyCom(c->body[i], out);
  else
    MeVector3Set(out, 0, 0, 0);
}

bool isPointJoint(const MdtConstraint *c) {
  switch (c->type->id) {
    case MdtConstraintTypeBSJoint:
    case MdtConstraintTypeHinge:
    case MdtConstraintTypeUniversal:
    case MdtConstraintTypeSkeletal:
      return true;
    default:
      return false;
  }
}

void pointVelocity(const MdtConstraint *c, int i, const MeVector3 p, MeVector3 out) {
  const MdtBody *b = c->body[i];
  if (!b) {
    MeVector3Set(out, 0, 0, 0);
    return;
  }
  MeVector3 r, wr, com;
  bodyCom(b, com);
  MeVector3Subtract(r, p, com);
  MeVector3Cross(wr, b->angularVelocity, r);
  MeVector3Add(out, b->velocity, wr);
}

void moveToBodies(MdtConstraint *c, MdtBody *b0, MdtBody *b1) {
  MdtBody *const to[2] = {b0, b1};
  for (int i = 0; i < 2; ++i) {
    if (c->body[i] == to[i]) continue;
    MeVector3 p, axis, ortho;
    attachmentPoint(c, i, p);
    attachmentAxis(c, i, axis);
    attachmentOrtho(c, i, ortho);
    c->body[i] = to[i];
    pointToBodyFrame(c, i, p, c->localPos[i]);
    toBodyFrame(c, i, axis, c->localAxis[i]);
    toBodyFrame(c, i, ortho, c->localOrtho[i]);
  }
}

void setWorldPosition(MdtConstraint *c, const MeVector3 p, const char *fn) {
  ME_REQUIRE_ARG(realFinite3(p[0], p[1], p[2]), fn, "position is not finite; ignored");
  for (int i = 0; i < 2; ++i) pointToBodyFrame(c, i, p, c->localPos[i]);
}

}  // namespace karma::mdt

using namespace karma::mdt;

namespace {

// Normalises a world axis; false (with a warning) for zero or non-finite.
bool unitAxis(MeVector3 v, const char *fn, const char *what) {
  if (!MeVector3AllFinite(v)) {
    MeWarning(0, "%s: %s is not finite; ignored", fn, what);
    return false;
  }
  const MeReal n = MeVector3Magnitude(v);
  if (!(n > (MeReal)1e-6)) {
    MeWarning(0, "%s: %s has zero length; ignored", fn, what);
    return false;
  }
  MeVector3Scale(v, 1 / n);
  return true;
}

// Both axes unit and orthogonal within a small tolerance (then made exact).
bool orthoAxes(MeVector3 p, MeVector3 o, const char *fn) {
  if (!unitAxis(p, fn, "the primary axis") || !unitAxis(o, fn, "the secondary axis")) return false;
  const MeReal d = MeVector3Dot(p, o);
  if (std::fabs(d) > (MeReal)1e-3) {
    MeWarning(0, "%s: the axes are not orthogonal (cosine %g); ignored", fn, (double)d);
    return false;
  }
  MeVector3MultiplyAdd(o, -d, p);
  MeVector3Normalize(o);
  return true;
}

bool indexOk(unsigned i, const char *fn) {
  if (i > 1) {
    MeWarning(0, "%s: body index %u is not 0 or 1; ignored", fn, i);
    return false;
  }
  return true;
}

}  // namespace

extern "C" {

void MEAPI MdtConstraintSetPosition(const MdtConstraintID c, const MeReal x, const MeReal y, const MeReal z) {
  static const char *fn = "MdtConstraintSetPosition";
  if (!liveConstraint(c, fn)) return;
  const MeVector3 p = {x, y, z};
  setWorldPosition(c, p, fn);
}

void MEAPI MdtConstraintGetPosition(const MdtConstraintID c, MeVector3 position) {
  ME_REQUIRE_ARG(c != nullptr && position != nullptr, "MdtConstraintGetPosition", "NULL argument");
  if (!liveConstraint(c, "MdtConstraintGetPosition")) return;
  attachmentPoint(c, 0, position);
}

void MEAPI MdtConstraintBodySetPosition(const MdtConstraintID c, const unsigned int i, const MeReal x, const MeReal y,
                                        const MeReal z) {
  static const char *fn = "MdtConstraintBodySetPosition";
  if (!liveConstraint(c, fn)) return;
  ME_REQUIRE_ARG(realFinite3(x, y, z), fn, "position is not finite; ignored");
  if (!indexOk(i, fn)) return;
  const MeVector3 p = {x, y, z};
  pointToBodyFrame(c, (int)i, p, c->localPos[i]);
}

void MEAPI MdtConstraintBodyGetPosition(const MdtConstraintID c, const unsigned int i, MeVector3 position) {
  static const char *fn = "MdtConstraintBodyGetPosition";
  ME_REQUIRE_ARG(c != nullptr && position != nullptr, fn, "NULL argument");
  if (!liveConstraint(c, fn)) return;
  if (!indexOk(i, fn)) return;
  attachmentPoint(c, (int)i, position);
}

void MEAPI MdtConstraintSetAxis(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz) {
  static const char *fn = "MdtConstraintSetAxis";
  if (!liveConstraint(c, fn)) return;
  MeVector3 p = {px, py, pz}, o;
  if (!unitAxis(p, fn, "the axis")) return;
  // Keep the current secondary axis if it is still usable, else any.
  attachmentOrtho(c, 0, o);
  MeVector3MultiplyAdd(o, -MeVector3Dot(o, p), p);
  if (MeVector3Magnitude(o) < (MeReal)1e-3)
    anyOrthogonal(p, o);
  else
    MeVector3Normalize(o);
  setWorldAxes(c, p, o);
}

void MEAPI MdtConstraintSetAxes(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz,
                                const MeReal ox, const MeReal oy, const MeReal oz) {
  static const char *fn = "MdtConstraintSetAxes";
  if (!liveConstraint(c, fn)) return;
  MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
  if (!orthoAxes(p, o, fn)) return;
  setWorldAxes(c, p, o);
}

void MEAPI MdtConstraintBodySetAxes(const MdtConstraintID c, const unsigned int i, const MeReal px, const MeReal py,
                                    const MeReal pz, const MeReal ox, const MeReal oy, const MeReal oz) {
  static const char *fn = "MdtConstraintBodySetAxes";
  if (!liveConstraint(c, fn)) return;
  if (!indexOk(i, fn)) return;
  MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
  if (!orthoAxes(p, o, fn)) return;
  toBodyFrame(c, (int)i, p, c->localAxis[i]);
  toBodyFrame(c, (int)i, o, c->localOrtho[i]);
}

void MEAPI MdtConstraintGetAxis(const MdtConstraintID c, MeVector3 axis) {
  ME_REQUIRE_ARG(c != nullptr && axis != nullptr, "MdtConstraintGetAxis", "NULL argument");
  if (!liveConstraint(c, "MdtConstraintGetAxis")) return;
  attachmentAxis(c, 0, axis);
}

void MEAPI MdtConstraintGetAxes(const MdtConstraintID c, MeVector3 primary, MeVector3 ortho) {
  ME_REQUIRE_ARG(c != nullptr && primary != nullptr && ortho != nullptr, "MdtConstraintGetAxes", "NULL argument");
  if (!liveConstraint(c, "MdtConstraintGetAxes")) return;
  attachmentAxis(c, 0, primary);
  attachmentOrtho(c, 0, ortho);
}

void MEAPI MdtConstraintBodyGetAxes(const MdtConstraintID c, const unsigned int i, MeVector3 primary, MeVector3 ortho) {
  static const char *fn = "MdtConstraintBodyGetAxes";
  ME_REQUIRE_ARG(c != nullptr && primary != nullptr && ortho != nullptr, fn, "NULL argument");
  if (!liveConstraint(c, fn)) return;
  if (!indexOk(i, fn)) return;
  attachmentAxis(c, (int)i, primary);
  attachmentOrtho(c, (int)i, ortho);
}

}  // extern "C"
