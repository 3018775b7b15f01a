/* accuracy_probe.cpp: MeViewerAccuracy.h, the accuracy figures of a
 * dynamics world for MeViewer's overlay. */
#include "MeViewerAccuracy.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

struct RAccuracyProbe {
  RRender *rc = nullptr;
  MdtWorldID world = nullptr;
  std::vector<MdtConstraintID> joints;
  std::vector<MdtBodyID> bodies; /* every body seen in a partition, first sighting order */
  std::unordered_set<MdtBodyID> seen;
  bool started = false;
  double startEnergy = 0;
};

namespace {

/* 1/2 m v.v + 1/2 w.I w - m g.x, with I the body-frame inertia and w
 * turned into the body frame (the transform's rows are the body axes). */
double BodyEnergy(MdtBodyID b, const MeVector3 g) {
  MeVector3 v, w, x;
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, w);
  MdtBodyGetPosition(b, x);
  MeMatrix4 tm;
  MdtBodyGetTransform(b, tm);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  double wb[3];
  for (int i = 0; i < 3; ++i) wb[i] = double(tm[i][0]) * w[0] + double(tm[i][1]) * w[1] + double(tm[i][2]) * w[2];
  double rotational = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotational += wb[i] * I[i][j] * wb[j];
  const double m = MdtBodyGetMass(b);
  const double vv = double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2];
  const double gx = double(g[0]) * x[0] + double(g[1]) * x[1] + double(g[2]) * x[2];
  return 0.5 * m * vv + 0.5 * rotational - m * gx;
}

/* Adds the bodies of the last step's partitions not seen before; returns
 * their energy now. */
double DiscoverBodies(RAccuracyProbe *p, const MeVector3 g) {
  double added = 0;
  const int partitions = MdtWorldGetPartitionCount(p->world);
  for (int k = 0; k < partitions; ++k)
    for (int i = 0; i < MdtWorldGetPartitionBodyCount(p->world, k); ++i) {
      MdtBodyID b = MdtWorldGetPartitionBody(p->world, k, i);
      if (b && p->seen.insert(b).second) {
        p->bodies.push_back(b);
        added += BodyEnergy(b, g);
      }
    }
  return added;
}

void MEAPI ProbeSource(RAccuracyFigures *figures, void *data) {
  RAccuracyProbeRead(static_cast<RAccuracyProbe *>(data), figures);
}

}  // namespace

RAccuracyProbe *MEAPI RAccuracyProbeCreate(RRender *rc, MdtWorldID world) {
  ME_REQUIRE_ARG_RET(rc && world, nullptr, "RAccuracyProbeCreate", "rc or world is NULL");
  RAccuracyProbe *p = new RAccuracyProbe;
  p->rc = rc;
  p->world = world;
  RRenderSetAccuracySource(rc, ProbeSource, p);
  return p;
}

void MEAPI RAccuracyProbeAddJoint(RAccuracyProbe *probe, MdtConstraintID joint) {
  ME_REQUIRE_ARG(probe && joint, "RAccuracyProbeAddJoint", "probe or joint is NULL");
  probe->joints.push_back(joint);
}

void MEAPI RAccuracyProbeRead(RAccuracyProbe *p, RAccuracyFigures *figures) {
  ME_REQUIRE_ARG(p && figures, "RAccuracyProbeRead", "probe or figures is NULL");
  MeVector3 g;
  MdtWorldGetGravity(p->world, g);
  const double joined = DiscoverBodies(p, g);
  double energy = 0, deepest = 0, gap = 0;
  for (MdtBodyID b : p->bodies) energy += BodyEnergy(b, g);
  /* A body first seen now joins at its present energy: no drift from it. */
  if (!p->started)
    p->startEnergy = energy, p->started = true;
  else
    p->startEnergy += joined;
  for (int k = 0; k < MdtWorldGetPartitionCount(p->world); ++k)
    for (int i = 0; i < MdtWorldGetPartitionBodyCount(p->world, k); ++i) {
      MdtBodyID b = MdtWorldGetPartitionBody(p->world, k, i);
      for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c))
        deepest = std::max(deepest, double(MdtContactGetPenetration(c)));
    }
  for (MdtConstraintID c : p->joints) {
    MeVector3 a, b;
    MdtConstraintBodyGetPosition(c, 0, a);
    MdtConstraintBodyGetPosition(c, 1, b);
    gap = std::max(gap, double(MeVector3Distance(a, b)));
  }
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(p->world, &stats);
  figures->jointError = MeReal(gap);
  figures->penetration = MeReal(deepest);
  figures->energyDrift = MeReal(energy - p->startEnergy);
  figures->residual = stats.keaResidual;
}

void MEAPI RAccuracyProbeDestroy(RAccuracyProbe *probe) {
  if (!probe) return;
  RRenderSetAccuracySource(probe->rc, nullptr, nullptr);
  delete probe;
}
