// constraint.cpp: allocation, life cycle and type checks of constraints, and
// the row sink.
#include <algorithm>
#include <cstring>
#include <new>
#include <type_traits>

#include "MdtContact.h"
#include "MeMessage.h"
#include "active_sets.h"

namespace karma::mdt {

namespace {

// A new row but for its softness: zero, unbounded, role Joint. Rows are
// copied from it rather than value-initialised in place, which GCC does
// with `rep stos`, three times slower than the copy for a row
// (docs/NOTES.md, "String instructions in hot loops").
constexpr Row blankRow() {
  Row r{};
  r.lo = -MEINFINITY;
  r.hi = MEINFINITY;
  r.friction = -1;
  r.role = RowRole::Joint;
  return r;
}
// Constant-initialised: a world stepped during another file's static
// initialisation still copies the blank row, not zeros.
constexpr Row kBlankRow = blankRow();
static_assert(std::is_trivially_copyable_v<Row>, "rows are copied with memcpy");

}  // namespace

Row &RowSink::add(const StepContext &ctx) {
  Row *r = &spare_;
  if (count_ < capacity_) {
    r = &rows_[count_++];
  } else {
    overflow_ = true;  // a type wrote more rows than it declared: a bug
  }
  std::memcpy(static_cast<void *>(r), &kBlankRow, sizeof(Row));
  r->softness = ctx.epsilon;
  return *r;
}

extern const ConstraintType kDestroyedConstraintType = {
    MdtConstraintTypeCount, "destroyed constraint", 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr};

bool liveConstraint(const MdtConstraint *c, const char *fn) {
  if (!c) {
    MeArgumentWarning(fn, "constraint is NULL");
    return false;
  }
  if (c->type == &kDestroyedConstraintType) {
    MeArgumentWarning(fn, "constraint %p has been destroyed (a stale handle); ignored", (const void *)c);
    return false;
  }
  return true;
}

void resetBase(MdtConstraint *c) {
  c->body[0] = c->body[1] = nullptr;
  for (int i = 0; i < 2; ++i) {
    MeVector3Set(c->localPos[i], 0, 0, 0);
    MeVector3Set(c->localAxis[i], 1, 0, 0);
    MeVector3Set(c->localOrtho[i], 0, 1, 0);
  }
  clearForces(c);
  c->warmRows = 0;
}

void clearForces(MdtConstraint *c) {
  for (int i = 0; i < 2; ++i) {
    MeVector3Set(c->force[i], 0, 0, 0);
    MeVector3Set(c->torque[i], 0, 0, 0);
  }
}

MdtConstraint *createConstraint(MdtWorldID world, const ConstraintType &type) {
  MdtWorldPrivate *p = world->priv;
  void *slot = takeConstraintSlot(p);
  if (!slot) return nullptr;  // out of memory (warned)
  std::memset(slot, 0, p->constraintSlotSize);
  auto *c = static_cast<MdtConstraint *>(slot);
  c->type = &type;
  c->world = world;
  c->serial = p->nextConstraintSerial++;
  resetBase(c);
  type.reset(c);
  return c;
}

void attachDefault(MdtConstraint *c) {
  // Both points at body 0's origin, the world's x and y as the axes.
  const MeVector3 x = {1, 0, 0}, y = {0, 1, 0};
  MeVector3 p = {0, 0, 0};
  if (c->body[0]) MeVector3Copy(p, c->body[0]->position);
  for (int i = 0; i < 2; ++i) pointToBodyFrame(c, i, p, c->localPos[i]);
  setWorldAxes(c, x, y);
}

MdtConstraint *castTo(MdtConstraint *c, const ConstraintType &type) { return (c && c->type == &type) ? c : nullptr; }

bool checkType(const MdtConstraint *c, const ConstraintType &type, const char *fn) {
  if (!c) {
    MeWarning(0, "%s: constraint is NULL; ignored", fn);
    return false;
  }
  if (c->type != &type) {
    if (!liveConstraint(c, fn)) return false;
    MeWarning(0, "%s: the constraint is of type %s where %s was expected; ignored", fn, c->type->name, type.name);
    return false;
  }
  return true;
}

}  // namespace karma::mdt

using namespace karma::mdt;

namespace {

bool bodyValid(unsigned i, const char *fn) {
  if (i > 1) {
    MeWarning(0, "%s: body index %u is not 0 or 1; ignored", fn, i);
    return false;
  }
  return true;
}

}  // namespace

extern "C" {

MdtConstraintType MEAPI MdtConstraintGetType(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintGetType")) return MdtConstraintTypeCount;
  return c->type->id;
}

const char *MEAPI MdtConstraintTypeName(const MdtConstraintType t) {
  const ConstraintType *const *all = allConstraintTypes();
  for (int i = 0; all[i]; ++i)
    if (all[i]->id == t) return all[i]->name;
  return "unknown";
}

void MEAPI MdtConstraintDestroy(const MdtConstraintID c) {
  if (!c || !liveConstraint(c, "MdtConstraintDestroy")) return;
  unlinkConstraint(c);
  // A group frees its contacts itself; a contact enabled alone before it
  // joined the group may still be linked.
  if (c->type->id == MdtConstraintTypeContactGroup) {
    MdtContactGroupID g = MdtConstraintDCastContactGroup(c);
    for (MdtContactID k = MdtContactGroupGetFirstContact(g); k; k = MdtContactGroupGetNextContact(g, k))
      unlinkConstraint(MdtContactQuaConstraint(k));
  }
  if (c->type->destroy) c->type->destroy(c);
  releaseConstraintSlot(c->world->priv, c);
}

void MEAPI MdtConstraintEnable(const MdtConstraintID c) {
  static const char *fn = "MdtConstraintEnable";
  if (!liveConstraint(c, fn)) return;
  ME_REQUIRE_ARG(c->owner == nullptr, fn, "this contact belongs to a contact group, which is enabled instead; ignored");
  if (c->type->id != MdtConstraintTypeContactGroup) {
    ME_REQUIRE_ARG(c->body[0] != nullptr, fn, "%s has no bodies; set them before enabling", c->type->name);
  }
  linkConstraint(c);
  c->enabled = TRUE;
}

void MEAPI MdtConstraintDisable(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintDisable")) return;
  c->enabled = FALSE;
}

MeBool MEAPI MdtConstraintIsEnabled(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintIsEnabled")) return FALSE;
  return c->enabled ? TRUE : FALSE;
}

void MEAPI MdtConstraintSetBodies(const MdtConstraintID c, const MdtBodyID body0, const MdtBodyID body1) {
  static const char *fn = "MdtConstraintSetBodies";
  if (!liveConstraint(c, fn)) return;
  ME_REQUIRE_ARG(c->owner == nullptr, fn, "this contact belongs to a contact group, whose bodies it has; ignored");
  ME_REQUIRE_ARG(!c->enabled, fn, "the %s is enabled; disable it before changing its bodies", c->type->name);
  ME_REQUIRE_ARG(body0 != nullptr, fn, "body0 is NULL (only body1 may be the world)");
  if (!liveBody(body0, fn) || (body1 && !liveBody(body1, fn))) return;
  ME_REQUIRE_ARG(body0 != body1, fn, "body0 and body1 are the same body");
  ME_REQUIRE_ARG(body0->world == c->world && (!body1 || body1->world == c->world), fn,
                 "a body belongs to another world");
  c->body[0] = body0;
  c->body[1] = body1;
  linkConstraint(c);
  attachDefault(c);
  if (c->type->attach) c->type->attach(c);
  c->warmRows = 0;
  clearForces(c);
}

MdtBodyID MEAPI MdtConstraintGetBody(const MdtConstraintID c, const unsigned int i) {
  if (!liveConstraint(c, "MdtConstraintGetBody")) return nullptr;
  if (!bodyValid(i, "MdtConstraintGetBody")) return nullptr;
  return c->body[i];
}

void MEAPI MdtConstraintGetForce(const MdtConstraintID c, const unsigned int i, MeVector3 f) {
  ME_REQUIRE_ARG(c != nullptr && f != nullptr, "MdtConstraintGetForce", "NULL argument");
  if (!liveConstraint(c, "MdtConstraintGetForce")) return;
  if (!bodyValid(i, "MdtConstraintGetForce")) return;
  MeVector3Copy(f, c->force[i]);
}

void MEAPI MdtConstraintGetTorque(const MdtConstraintID c, const unsigned int i, MeVector3 t) {
  ME_REQUIRE_ARG(c != nullptr && t != nullptr, "MdtConstraintGetTorque", "NULL argument");
  if (!liveConstraint(c, "MdtConstraintGetTorque")) return;
  if (!bodyValid(i, "MdtConstraintGetTorque")) return;
  MeVector3Copy(t, c->torque[i]);
}

MdtWorldID MEAPI MdtConstraintGetWorld(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintGetWorld")) return nullptr;
  return c->world;
}

void MEAPI MdtConstraintSetUserData(const MdtConstraintID c, void *data) {
  if (!liveConstraint(c, "MdtConstraintSetUserData")) return;
  c->userData = data;
}

void *MEAPI MdtConstraintGetUserData(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintGetUserData")) return nullptr;
  return c->userData;
}

void MEAPI MdtConstraintSetSortKey(const MdtConstraintID c, const MeI32 key) {
  if (!liveConstraint(c, "MdtConstraintSetSortKey")) return;
  c->sortKey = key;
}

MeI32 MEAPI MdtConstraintGetSortKey(const MdtConstraintID c) {
  if (!liveConstraint(c, "MdtConstraintGetSortKey")) return 0;
  return c->sortKey;
}

unsigned int MEAPI MdtWorldGetConstraintCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetConstraintCount", "world is NULL");
  return (unsigned int)usedConstraintSlots(world->priv);
}

unsigned int MEAPI MdtWorldGetMaxConstraints(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetMaxConstraints", "world is NULL");
  return world->priv->maxConstraints;
}

}  // extern "C"
