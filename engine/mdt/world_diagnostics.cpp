// world_diagnostics.cpp: a world as a diagnostic source (MeDiagnostics.h),
// registered from MdtWorldCreate to MdtWorldDestroy, and
// MdtWorldGetDiagnostics.
//
// Energy drift is accumulated per body between reads: each read adds, for
// every live body also present at the previous read (same serial), its
// energy now minus its energy then. A body created since joins without
// contributing; a destroyed one leaves without contributing. The energy of
// a body is 1/2 m v.v + 1/2 w.I w - m g.x, with I in body axes and w turned
// into them (the transform's rows are the body axes).
#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "MeDiagnostics.h"
#include "MdtContact.h"
#include "MeMessage.h"
#include "mdt_internal.h"
#include "step.h"

namespace karma::mdt {

namespace {

struct EnergyLedger {
  std::unordered_map<std::uint64_t, double> last;  // serial -> energy at the last read
  double drift = 0;
};

// Never destroyed, like the source list (a world may outlive static destruction).
std::unordered_map<MdtWorldID, EnergyLedger> &ledgers() {
  static auto *map = new std::unordered_map<MdtWorldID, EnergyLedger>;
  return *map;
}

double bodyEnergy(const MdtBody *b, const MeVector3 g) {
  double wb[3];
  for (int i = 0; i < 3; ++i)
    wb[i] = double(b->tm[i][0]) * b->angularVelocity[0] + double(b->tm[i][1]) * b->angularVelocity[1] +
            double(b->tm[i][2]) * b->angularVelocity[2];
  double rotational = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotational += wb[i] * double(b->inertia[i][j]) * wb[j];
  double vv = 0, gx = 0;
  for (int i = 0; i < 3; ++i) {
    vv += double(b->velocity[i]) * b->velocity[i];
    gx += double(g[i]) * b->position[i];
  }
  const double m = b->mass;
  return 0.5 * m * vv + 0.5 * rotational - m * gx;
}

double energyDrift(MdtWorldID world) {
  EnergyLedger &ledger = ledgers()[world];
  std::unordered_map<std::uint64_t, double> now;
  MePool *pool = &world->priv->bodies;
  for (void *slot = MePoolGetNextUsed(pool, nullptr); slot; slot = MePoolGetNextUsed(pool, slot)) {
    const auto *b = static_cast<const MdtBody *>(slot);
    if (!b->alive) continue;
    const double e = bodyEnergy(b, world->params.gravity);
    now.emplace(b->serial, e);
    const auto before = ledger.last.find(b->serial);
    if (before != ledger.last.end()) ledger.drift += e - before->second;
  }
  ledger.last.swap(now);
  return ledger.drift;
}

// Simulated: enabled, or for a contact of a group, its group enabled.
bool active(const MdtConstraint *c) { return c->owner ? c->owner->enabled : c->enabled; }

void jointsAndContacts(MdtWorldID world, MeDiagnosticFigures &f) {
  double gap = 0, deepest = 0;
  MdtWorldPrivate *p = world->priv;
  for (void *slot = nextConstraintSlot(p, nullptr); slot; slot = nextConstraintSlot(p, slot)) {
    auto *c = static_cast<MdtConstraint *>(slot);
    if (!active(c) || !c->body[0]) continue;
    if (c->type->id == MdtConstraintTypeContact) {
      deepest = std::max(deepest, double(MdtContactGetPenetration(MdtConstraintDCastContact(c))));
    } else if (isPointJoint(c)) {
      MeVector3 a, b;
      MdtConstraintBodyGetPosition(c, 0, a);
      MdtConstraintBodyGetPosition(c, 1, b);
      gap = std::max(gap, double(MeVector3Distance(a, b)));
    }
  }
  f.jointError = (MeReal)gap;
  f.penetration = (MeReal)deepest;
}

void MEAPI readWorld(void *owner, MeDiagnosticFigures *figures) {
  auto world = static_cast<MdtWorldID>(owner);
  jointsAndContacts(world, *figures);
  figures->energyDrift = (MeReal)energyDrift(world);
  figures->residual = world->priv->scratch->stats.keaResidual;
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(world, &stats);
  figures->platform = stats.platform;
}

}  // namespace

void registerWorldDiagnostics(MdtWorldID world) { MeDiagnosticSourceRegister(world, readWorld); }

void unregisterWorldDiagnostics(MdtWorldID world) {
  MeDiagnosticSourceUnregister(world);
  ledgers().erase(world);
}

}  // namespace karma::mdt

extern "C" void MEAPI MdtWorldGetDiagnostics(const MdtWorldID world, MeDiagnosticFigures *figures) {
  ME_REQUIRE_ARG(world && figures, "MdtWorldGetDiagnostics", "world or figures is NULL");
  karma::mdt::readWorld(world, figures);
}
