// accuracy_overlay.cpp: the program behind golden.meviewer.accuracy: a box
// dropped 5 cm onto the ground and a chain of three balls released level
// from a pivot, stepped by Mst at 1/60 s, with the performance bar and
// MeViewer's accuracy overlay fed by the probe of MeViewerAccuracy.h. The
// bar's clock is a counter (every reading 2 ms after the last), so the
// frames are the same on every run of a build precision. Writes an empty
// trajectory (one frame, no bodies), as meviewer_scene does: the frames are
// what the golden pins.
#include "MeViewerAccuracy.h"
#include "Mst.h"

#include <karma/golden/KarmaTrajectory.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

RRender *rc = nullptr;
MstUniverseID universe = nullptr;
RAccuracyProbe *probe = nullptr;
MeMatrix4 groundTM;

double MEAPI StepClock(void *) {
  static double now = 0;
  return now += 2;
}

void MEAPI Tick(RRender *, void *) { MstUniverseStep(universe, (MeReal)1 / 60); }

void MEAPI_CDECL Cleanup() {
  RAccuracyProbeDestroy(probe);
  RRenderContextDestroy(rc);
  MstUniverseDestroy(universe);
}

void Build() {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  universe = MstUniverseCreate(&sizes);
  MdtWorldID world = MstUniverseGetWorld(universe);
  McdFrameworkID framework = MstUniverseGetFramework(universe);
  MdtWorldSetGravity(world, 0, (MeReal)-9.81, 0);
  MdtWorldSetAutoDisable(world, 0);
  // The plane's normal is its z: turn it onto y.
  const MeMatrix4 tm = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MeMatrix4Copy(groundTM, tm);
  MstFixedModelCreate(universe, McdPlaneCreate(framework), groundTM);
  probe = RAccuracyProbeCreate(rc, world);

  const float red[4] = {0.9f, 0.3f, 0.2f, 1}, blue[4] = {0.3f, 0.5f, 0.95f, 1}, green[4] = {0.3f, 0.7f, 0.35f, 1};
  McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(framework, 1, 1, 1), 100);
  MdtBodySetPosition(McdModelGetBody(box), -1.5, (MeReal)0.55, 0);
  RGraphicBoxCreate(rc, 1, 1, 1, red, MdtBodyGetTransformPtr(McdModelGetBody(box)));

  McdGeometryID ball = McdSphereCreate(framework, (MeReal)0.25);
  MdtBodyID previous = nullptr;
  for (int i = 0; i < 3; ++i) {
    McdModelID m = MstModelAndBodyCreate(universe, ball, 50);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, (MeReal)(0.6 * (i + 1)), 2.5, 0);
    RGraphicSphereCreate(rc, (MeReal)0.25, blue, MdtBodyGetTransformPtr(b));
    MdtBSJointID j = MdtBSJointCreate(world);
    MdtBSJointSetBodies(j, b, previous);  // the first hangs from the world
    MdtBSJointSetPosition(j, (MeReal)(0.6 * i), 2.5, 0);
    MdtBSJointEnable(j);
    RAccuracyProbeAddJoint(probe, MdtBSJointQuaConstraint(j));
    previous = b;
  }
  RGraphicGroundPlaneCreate(rc, 12, 6, green, 0);
  const AcmeVector3 lookAt = {0, 1, 0};
  RCameraSetLookAt(rc, lookAt);
  RCameraSetView(rc, 7, (MeReal)0.3, (MeReal)0.3);
  MeProfileSetClock(StepClock, nullptr);
  RPerformanceBarCreate(rc);
}

}  // namespace

int main(int argc, const char *argv[]) {
  MeCommandLineOptions *opts = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(opts, nullptr, 1);
  const char *trajectoryPath = MeCommandLineOptionsGetString(opts, "-trajectory", 1);
  const std::string path = trajectoryPath ? trajectoryPath : "";
  MeCommandLineOptionsDestroy(opts);
  if (!rc) return 1;
  Build();
  /* The context read -platform: the world runs on that backend. */
  const std::string backend = MdtWorldGetPlatformName(MstUniverseGetWorld(universe));
  KarmaTrajectoryInfo info = {"meviewer", "accuracy", backend.c_str(), "one still frame", (MeReal)1 / 60, 0};
  KarmaTrajectoryWriter *w = KarmaTrajectoryWriterCreate(path.empty() ? nullptr : path.c_str(), &info);
  const bool ok = w && KarmaTrajectoryWriterBeginFrame(w, 0, 0) && KarmaTrajectoryWriterEndFrame(w);
  if (!KarmaTrajectoryWriterDestroy(w) || !ok) {
    std::fprintf(stderr, "accuracy_overlay: cannot write the trajectory %s\n", path.c_str());
    return 1;
  }
  std::atexit(Cleanup);
  RRun(rc, Tick, nullptr);
}
