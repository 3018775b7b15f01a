// world.cpp: creating and destroying worlds, counting bodies, and the step.
#include <algorithm>
#include <climits>
#include <cstddef>
#include <new>

#include "MeMemory.h"
#include "MeMessage.h"
#include "active_sets.h"
#include "kernels.h"
#include "step.h"

using namespace karma::mdt;

namespace {

// Partitions of more rows than this are solved iteratively by default
// (MdtWorldSetKeaIterativeRows): the exact active-set method pivots one row
// at a time, so a partition that must change many rows of its active set
// (columns of boxes landing on each other) can cost it thousands of linear
// solves in one step. Above the partitions of the anchor scenes at rest
// (pile1000's columns: about 120 rows).
constexpr int kDefaultIterativeRows = 300;

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
  p.keaMethod = MdtKeaMethodActiveSet;
  p.keaMaxIterations = 0;
  p.keaTolerance = 0;
  p.geometricStiffness = 1;
  p.keaIterativeRows = kDefaultIterativeRows;
  p.jointProjection = 0;
  p.keaAcceptWarmStart = 1;
}

}  // namespace

extern "C" {

MdtWorldID MEAPI MdtWorldCreate(const unsigned int maxBodies, const unsigned int maxConstraints,
                                const MeReal lengthScale, const MeReal massScale) {
  static const char *fn = "MdtWorldCreate";
  ME_REQUIRE_ARG_RET(maxBodies <= (unsigned int)(INT_MAX / 2), nullptr, fn, "maxBodies %u is too large", maxBodies);
  ME_REQUIRE_ARG_RET(maxConstraints <= (unsigned int)(INT_MAX / 2), nullptr, fn, "maxConstraints %u is too large",
                     maxConstraints);
  ME_REQUIRE_ARG_RET(realFinite(lengthScale) && lengthScale > 0, nullptr, fn,
                     "lengthScale must be positive and finite, got %g", (double)lengthScale);
  ME_REQUIRE_ARG_RET(realFinite(massScale) && massScale > 0, nullptr, fn,
                     "massScale must be positive and finite, got %g", (double)massScale);

  auto *w = static_cast<MdtWorld *>(MeMemoryAPI.createZeroed(sizeof(MdtWorld)));
  auto *p = static_cast<MdtWorldPrivate *>(MeMemoryAPI.createZeroed(sizeof(MdtWorldPrivate)));
  bool ok = w && p;
  const unsigned slot = largestConstraintSize();
  bool bodiesOk = false, constraintsOk = false;
  if (ok) {
    ok = bodiesOk = MePoolInit(&p->bodies, (int)maxBodies, (int)sizeof(MdtBody), (int)alignof(MdtBody));
  }
  if (ok) {
    ok = constraintsOk = MePoolInit(&p->constraints, (int)maxConstraints, (int)slot, kConstraintSlotAlignment);
  }
  if (ok) {
    p->scratch = new (std::nothrow) StepScratch();
    p->active = new (std::nothrow) ActiveSets();
    ok = p->scratch != nullptr && p->active != nullptr;
  }
  if (!ok) {
    if (constraintsOk) MePoolDestroy(&p->constraints);
    if (bodiesOk) MePoolDestroy(&p->bodies);
    if (p) {
      delete p->scratch;
      delete p->active;
      MeMemoryAPI.destroy(p);
    }
    if (w) MeMemoryAPI.destroy(w);
    MeWarning(0, "MdtWorldCreate: out of memory for a world of %u bodies", maxBodies);
    return nullptr;
  }
  MePoolSetName(&p->bodies, "MdtWorld bodies");
  MePoolSetName(&p->constraints, "MdtWorld constraints");
  p->constraintSlotSize = slot;
  p->maxBodies = maxBodies;
  p->maxConstraints = maxConstraints;
  p->lengthScale = lengthScale;
  p->massScale = massScale;
  p->kernels = &karma::platform::DefaultKernels();
  w->priv = p;
  setDefaultParams(w->params, lengthScale, massScale);
  rememberCheckedParams(w);
  registerWorldDiagnostics(w);
  return w;
}

void MEAPI MdtWorldDestroy(const MdtWorldID world) {
  if (!world) return;
  unregisterWorldDiagnostics(world);
  MdtWorldPrivate *p = world->priv;
  releaseConstraintPools(p);  // constraints own nothing outside their slot
  MePoolDestroy(&p->bodies);  // every body goes with the pool
  delete p->scratch;
  delete p->active;
  MeMemoryAPI.destroy(p);
  MeMemoryAPI.destroy(world);
}

unsigned int MEAPI MdtWorldGetEnabledBodyCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetEnabledBodyCount", "world is NULL");
  return world->priv->enabledCount;
}

unsigned int MEAPI MdtWorldGetBodyCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetBodyCount", "world is NULL");
  // Destroyed bodies waiting for reuse still hold their pool slots.
  return (unsigned int)MePoolGetUsed(&world->priv->bodies) - world->priv->retiredCount;
}

unsigned int MEAPI MdtWorldGetMaxBodies(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0u, "MdtWorldGetMaxBodies", "world is NULL");
  return world->priv->maxBodies;
}

// The step: see step.h for the stages.
void MEAPI MdtWorldStep(const MdtWorldID world, const MeReal stepSize) {
  static const char *fn = "MdtWorldStep";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(stepSize) && stepSize > 0, fn, "stepSize must be positive and finite, got %g",
                 (double)stepSize);
  checkDirectParamWrites(world);
  ME_REQUIRE_ARG(MeVector3AllFinite(world->params.gravity), fn, "gravity is not finite");
  world->priv->lastStepSize = stepSize;
  StepScratch &s = *world->priv->scratch;
  s.stats = MdtWorldStepStats{};
  ++s.step;
  s.stats.platform = world->priv->kernels->name;
  s.arena.reset();
  const StepClock clock(s.budget);
  wakeDrivenBodies(world);
  buildPartitions(world, s);
  StepContext ctx;
  ctx.h = stepSize;
  ctx.invH = (MeReal)1 / stepSize;
  ctx.epsilon = world->params.epsilon;
  ctx.gamma = world->params.gamma;
  s.partitionRows.assign(s.partitions.size(), 0);
  s.freePartitions.clear();
  for (size_t i = 0; i < s.partitions.size(); ++i) {
    const Partition &part = s.partitions[i];
    s.stats.bodies += part.bodyCount;
    s.stats.constraints += part.constraintCount;
    if (part.constraintCount == 0) {
      s.freePartitions.push_back((int)i);  // one body, no rows: batched below
    } else if (stepPartition(world, s, (int)i, ctx)) {
      ++s.stats.sleeping;
    }
  }
  s.stats.sleeping += stepFreeBodies(world, s, ctx);
  s.stats.partitions = (int)s.partitions.size();
  s.solveWarnings.endStep(stepSize);
  clock.stop(s.stats);
}

MeReal MEAPI MdtWorldGetLastStepSize(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetLastStepSize", "world is NULL");
  return world->priv->lastStepSize;
}

void MEAPI MdtWorldGetStepStats(const MdtWorldID world, MdtWorldStepStats *stats) {
  ME_REQUIRE_ARG(world != nullptr && stats != nullptr, "MdtWorldGetStepStats", "NULL argument");
  *stats = world->priv->scratch->stats;
  if (!stats->platform) stats->platform = world->priv->kernels->name;  // no step yet
}

int MEAPI MdtWorldGetPartitionCount(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetPartitionCount", "world is NULL");
  return (int)world->priv->scratch->partitions.size();
}

namespace {
const Partition *partitionAt(MdtWorldID world, int i, const char *fn) {
  if (!world) {
    MeWarning(0, "%s: world is NULL", fn);
    return nullptr;
  }
  const StepScratch &s = *world->priv->scratch;
  if (i < 0 || i >= (int)s.partitions.size()) {
    MeWarning(0, "%s: partition %d does not exist (last step had %d)", fn, i, (int)s.partitions.size());
    return nullptr;
  }
  return &s.partitions[(size_t)i];
}
}  // namespace

int MEAPI MdtWorldGetPartitionBodyCount(const MdtWorldID world, const int partition) {
  const Partition *p = partitionAt(world, partition, "MdtWorldGetPartitionBodyCount");
  return p ? p->bodyCount : 0;
}

MdtBodyID MEAPI MdtWorldGetPartitionBody(const MdtWorldID world, const int partition, const int i) {
  const Partition *p = partitionAt(world, partition, "MdtWorldGetPartitionBody");
  if (!p) return nullptr;
  if (i < 0 || i >= p->bodyCount) {
    MeWarning(0, "MdtWorldGetPartitionBody: body %d of %d does not exist", i, p->bodyCount);
    return nullptr;
  }
  return world->priv->scratch->partBodies[(size_t)(p->bodyStart + i)];
}

int MEAPI MdtWorldGetPartitionRowCount(const MdtWorldID world, const int partition) {
  if (!partitionAt(world, partition, "MdtWorldGetPartitionRowCount")) return 0;
  return world->priv->scratch->partitionRows[(size_t)partition];
}

}  // extern "C"
