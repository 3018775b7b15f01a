// world.cpp: creating and destroying worlds, counting bodies, and the step.
#include <algorithm>
#include <climits>
#include <new>

#include "MeMemory.h"
#include "MeMessage.h"
#include "mdt_internal.h"

using namespace karma::mdt;

namespace {

void setDefaultParams(MdtWorldParams &p, MeReal l, MeReal m) {
  p.gravity[0] = p.gravity[1] = p.gravity[2] = 0;
  p.epsilon = (MeReal)0.01 / m;
  p.gamma = (MeReal)0.2;
  p.autoDisable = TRUE;
  p.velocityThreshold = (MeReal)0.02 * l;
  p.angularVelocityThreshold = (MeReal)0.001;
  p.accelerationThreshold = (MeReal)0.5 * l;
  p.angularAccelerationThreshold = (MeReal)0.002;
  p.aliveWindow = (MeReal)0.2;
  p.minSafeTime = (MeReal)0.001;
  p.maxMatrixSize = 0;
}

// Strict total order: sort key, then creation order (serials are unique).
bool stepsBefore(const MdtBody *a, const MdtBody *b) {
  if (a->sortKey != b->sortKey) return a->sortKey < b->sortKey;
  return a->serial < b->serial;
}

}  // namespace

extern "C" {

MdtWorldID MEAPI MdtWorldCreate(const unsigned int maxBodies, const unsigned int maxConstraints,
                                const MeReal lengthScale, const MeReal massScale) {
  static const char *fn = "MdtWorldCreate";
  ME_REQUIRE_ARG_RET(maxBodies <= (unsigned int)(INT_MAX / 2), nullptr, fn,
                     "maxBodies %u is too large", maxBodies);
  ME_REQUIRE_ARG_RET(realFinite(lengthScale) && lengthScale > 0, nullptr, fn,
                     "lengthScale must be positive and finite, got %g", (double)lengthScale);
  ME_REQUIRE_ARG_RET(realFinite(massScale) && massScale > 0, nullptr, fn,
                     "massScale must be positive and finite, got %g", (double)massScale);

  auto *w = static_cast<MdtWorld *>(MeMemoryAPI.createZeroed(sizeof(MdtWorld)));
  auto *p = static_cast<MdtWorldPrivate *>(MeMemoryAPI.createZeroed(sizeof(MdtWorldPrivate)));
  MdtBody **order = maxBodies > 0 ? static_cast<MdtBody **>(
                                        MeMemoryAPI.createZeroed(maxBodies * sizeof(MdtBody *)))
                                  : nullptr;
  bool ok = w && p && (maxBodies == 0 || order);
  if (ok) {
    ok = MePoolInit(&p->bodies, (int)maxBodies, (int)sizeof(MdtBody), (int)alignof(MdtBody));
  }
  if (!ok) {
    if (order) MeMemoryAPI.destroy(order);
    if (p) MeMemoryAPI.destroy(p);
    if (w) MeMemoryAPI.destroy(w);
    MeWarning(0, "MdtWorldCreate: out of memory for a world of %u bodies", maxBodies);
    return nullptr;
  }
  MePoolSetName(&p->bodies, "MdtWorld bodies");
  p->order = order;
  p->maxBodies = maxBodies;
  p->maxConstraints = maxConstraints;
  p->lengthScale = lengthScale;
  p->massScale = massScale;
  w->priv = p;
  setDefaultParams(w->params, lengthScale, massScale);
  return w;
}

void MEAPI MdtWorldDestroy(const MdtWorldID world) {
  if (!world) return;
  MdtWorldPrivate *p = world->priv;
  MePoolDestroy(&p->bodies);  // every body goes with the pool
  if (p->order) MeMemoryAPI.destroy(p->order);
  MeMemoryAPI.destroy(p);
  MeMemoryAPI.destroy(world);
}

unsigned int MEAPI MdtWorldGetEnabledBodyCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetEnabledBodyCount", "world is NULL");
  return world->priv->enabledCount;
}

unsigned int MEAPI MdtWorldGetBodyCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetBodyCount", "world is NULL");
  return (unsigned int)MePoolGetUsed(&world->priv->bodies);
}

unsigned int MEAPI MdtWorldGetMaxBodies(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetMaxBodies", "world is NULL");
  return world->priv->maxBodies;
}

// The step as it stands (no constraints yet): gather the enabled bodies,
// order them by (sort key, creation order), integrate each one.
// TODO(dynamics): partitions, Kea constraint forces and auto-disable slot in
// between the gathering and the integration.
void MEAPI MdtWorldStep(const MdtWorldID world, const MeReal stepSize) {
  static const char *fn = "MdtWorldStep";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(stepSize) && stepSize > 0, fn,
                 "stepSize must be positive and finite, got %g", (double)stepSize);
  ME_REQUIRE_ARG(MeVector3AllFinite(world->params.gravity), fn, "gravity is not finite");
  MdtWorldPrivate *p = world->priv;
  unsigned int n = 0;
  for (void *s = MePoolGetNextUsed(&p->bodies, nullptr); s;
       s = MePoolGetNextUsed(&p->bodies, s)) {
    auto *b = static_cast<MdtBody *>(s);
    if (b->enabled) p->order[n++] = b;
  }
  std::sort(p->order, p->order + n, stepsBefore);
  for (unsigned int i = 0; i < n; ++i) integrateBody(p->order[i], world->params.gravity, stepSize);
}

}  // extern "C"
