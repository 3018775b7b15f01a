/* accuracy_probe.cpp: MeViewerAccuracy.h, the accuracy figures of a
 * dynamics world for MeViewer's overlay. */
#include "MeViewerAccuracy.h"

#include <algorithm>
#include <vector>

struct RAccuracyProbe {
  RRender *rc = nullptr;
  MdtWorldID world = nullptr;
  std::vector<MdtConstraintID> joints;
};

namespace {

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
  MeDiagnosticFigures d;
  MdtWorldGetDiagnostics(p->world, &d);
  figures->jointError = d.jointError;
  figures->penetration = d.penetration;
  figures->energyDrift = d.energyDrift;
  figures->residual = d.residual;
  if (p->joints.empty()) return;
  /* Joints named by the program: their gaps alone count. */
  double gap = 0;
  for (MdtConstraintID c : p->joints) {
    MeVector3 a, b;
    MdtConstraintBodyGetPosition(c, 0, a);
    MdtConstraintBodyGetPosition(c, 1, b);
    gap = std::max(gap, double(MeVector3Distance(a, b)));
  }
  figures->jointError = MeReal(gap);
}

void MEAPI RAccuracyProbeDestroy(RAccuracyProbe *probe) {
  if (!probe) return;
  RRenderSetAccuracySource(probe->rc, nullptr, nullptr);
  delete probe;
}
