// body_lifecycle.cpp: creating, destroying, enabling and disabling bodies.
//
// Handles are pointers into the world's body pool, so a destroyed body's
// slot is eventually handed out again. To keep stale handles detectable as
// long as possible, a destroyed body is retired rather than returned to the
// pool: it keeps its slot, marked dead (`alive`), in a queue, and
// MdtBodyCreate reuses the oldest retired slot only once the pool has no
// other free slot. While retired, the calls here refuse the handle with a
// warning. A collision model still joined to the body is detached by the
// bridge's body-destroy callback (MstSetWorldHandlers), so it cannot drive
// the slot's next body.
#include "MeMessage.h"
#include "active_sets.h"

namespace karma::mdt {

void updateTransform(MdtBody *b) { MeQuaternionToTM(b->tm, b->q, b->position); }

void initBody(MdtBody *b, MdtWorldID world) {
  const MdtWorldPrivate *p = world->priv;
  const MeReal m = p->massScale;
  const MeReal l = p->lengthScale;
  const MeReal i = (MeReal)0.4 * m * l * l;
  MdtBody zero{};
  *b = zero;
  b->world = world;
  MeQuaternionMakeIdentity(b->q);
  b->mass = m;
  b->invMass = (MeReal)1 / m;
  MeMatrix3MakeIdentity(b->inertiaCom);
  for (int k = 0; k < 3; ++k) b->inertiaCom[k][k] = i;
  MeMatrix4TMMakeIdentity(b->comTM);
  updateInertia(b);
  MeVector3Set(b->fastSpinAxis, 0, 1, 0);
  b->fastSpinEnabled = FALSE;
  b->enabled = FALSE;
  b->userData = nullptr;
  b->sortKey = 0;
  b->awakeSlot = -1;
  updateTransform(b);
}

void retireBody(MdtWorldPrivate *p, MdtBody *b) {
  b->nextRetired = nullptr;
  if (p->retiredTail)
    p->retiredTail->nextRetired = b;
  else
    p->retiredHead = b;
  p->retiredTail = b;
  ++p->retiredCount;
}

// A free slot: from the pool while it has one, else the oldest retired body.
MdtBody *takeSlot(MdtWorldPrivate *p) {
  if (MePoolGetUnused(&p->bodies) == 0 && p->retiredHead) {
    MdtBody *b = p->retiredHead;
    p->retiredHead = b->nextRetired;
    if (!p->retiredHead) p->retiredTail = nullptr;
    --p->retiredCount;
    return b;
  }
  return static_cast<MdtBody *>(MePoolGetStruct(&p->bodies));
}

bool liveBody(const MdtBody *b, const char *fn) {
  if (!b) {
    MeArgumentWarning(fn, "body is NULL");
    return false;
  }
  if (!b->alive) {
    MeArgumentWarning(fn, "body %p has been destroyed (a stale handle); ignored", (const void *)b);
    return false;
  }
  return true;
}

}  // namespace karma::mdt

using namespace karma::mdt;

extern "C" {

MdtBodyID MEAPI MdtBodyCreate(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, nullptr, "MdtBodyCreate", "world is NULL");
  MdtWorldPrivate *p = world->priv;
  MdtBody *b = takeSlot(p);
  if (!b) return nullptr;  // the pool has warned once
  initBody(b, world);
  b->alive = TRUE;
  b->serial = p->nextSerial++;
  return b;
}

void MEAPI MdtBodyDestroy(const MdtBodyID body) {
  if (!body) return;
  if (!liveBody(body, "MdtBodyDestroy")) return;  // destroyed twice
  MdtWorldPrivate *p = body->world->priv;
  // A collision model still joined to the body would go on driving the
  // body that takes this slot next: the bridge detaches it first.
  if (body->collisionModel && p->bodyDestroyCB) p->bodyDestroyCB(body, body->collisionModel);
  // Constraints still attached would point at a dead body: disable them and
  // leave them without bodies (the program may set new ones or destroy them),
  // their attachments where they were in the world and no force of the
  // bodies they had.
  for (void *s = nextConstraintSlot(p, nullptr); s; s = nextConstraintSlot(p, s)) {
    auto *c = static_cast<MdtConstraint *>(s);
    if (c->linked[0] == body || c->linked[1] == body) unlinkConstraint(c);
    if (c->body[0] != body && c->body[1] != body) continue;
    unlinkConstraint(c);
    if (c->enabled) MeWarning(0, "MdtBodyDestroy: an enabled %s still used this body; it was disabled", c->type->name);
    c->enabled = FALSE;
    moveToBodies(c, nullptr, nullptr);
    clearForces(c);
  }
  if (body->enabled) {
    --p->enabledCount;
    removeAwake(p, body);
  }
  body->enabled = FALSE;
  body->alive = FALSE;
  body->drivenListed = FALSE;
  body->collisionModel = nullptr;
  retireBody(p, body);
}

void MEAPI MdtBodyEnable(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyEnable")) return;
  if (body->enabled) return;
  body->enabled = TRUE;
  body->idleTime = 0;
  body->awakeTime = 0;
  body->awakeSteps = 0;
  MdtWorldPrivate *p = body->world->priv;
  ++p->enabledCount;
  addAwake(p, body);
  if (p->bodyEnableCB) p->bodyEnableCB(body, TRUE, p->bodyEnableData);
}

void MEAPI MdtBodyDisable(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyDisable")) return;
  if (!body->enabled) return;
  body->enabled = FALSE;
  MdtWorldPrivate *p = body->world->priv;
  --p->enabledCount;
  removeAwake(p, body);
  noteDriven(body);  // the program may have added forces before disabling it
  if (p->bodyEnableCB) p->bodyEnableCB(body, FALSE, p->bodyEnableData);
}

MeBool MEAPI MdtBodyIsEnabled(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyIsEnabled")) return FALSE;
  return body->enabled ? TRUE : FALSE;
}

MdtWorldID MEAPI MdtBodyGetWorld(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetWorld")) return nullptr;
  return body->world;
}

void MEAPI MdtBodySetUserData(const MdtBodyID body, void *data) {
  if (!liveBody(body, "MdtBodySetUserData")) return;
  body->userData = data;
}

void *MEAPI MdtBodyGetUserData(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetUserData")) return nullptr;
  return body->userData;
}

void MEAPI MdtBodySetSortKey(const MdtBodyID body, const MeI32 key) {
  if (!liveBody(body, "MdtBodySetSortKey")) return;
  body->sortKey = key;
}

MeI32 MEAPI MdtBodyGetSortKey(const MdtBodyID body) {
  if (!liveBody(body, "MdtBodyGetSortKey")) return 0;
  return body->sortKey;
}

}  // extern "C"
