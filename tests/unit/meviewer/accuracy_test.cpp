// accuracy_test.cpp: MeViewer's accuracy figures: the probe of
// MeViewerAccuracy.h against closed forms (a free fall's energy drift
// under the integrator, a joint pulled apart by a known distance, a box
// pressed into the ground), the -accuracy option, the overlay's text and
// -profile's table per quarter of the run; a program with no probe read
// through its worlds (MeDiagnostics.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "MeViewerAccuracy.h"
#include "Mst.h"
#include "viewer_internal.h"

namespace {

RRender *Context(const char *extra = nullptr) {
  const char *argv[] = {"prog", "-null", extra};
  MeCommandLineOptions *o = MeCommandLineOptionsCreate(extra ? 3 : 2, argv);
  RRender *rc = RRenderContextCreate(o, nullptr, 1);
  MeCommandLineOptionsDestroy(o);
  return rc;
}

TEST(MeViewerAccuracy, TheOptionIsRead) {
  RRender *with = Context("-accuracy"), *without = Context();
  ASSERT_TRUE(with && without);
  EXPECT_TRUE(RRenderAccuracyRequested(with));
  EXPECT_FALSE(RRenderAccuracyRequested(without));
  // Without -accuracy there is no overlay; with it and no source, the
  // overlay says that the program gives no figures.
  EXPECT_TRUE(karma::viewer::AccuracyOverlay(without).empty());
  const std::vector<RGraphic *> overlay = karma::viewer::AccuracyOverlay(with);
  EXPECT_EQ(overlay.size(), 3u);  // the panel and two lines
  for (RGraphic *g : overlay) RGraphicDestroy(g);
  RRenderContextDestroy(with);
  RRenderContextDestroy(without);
}

TEST(MeViewerAccuracy, FreeFallDriftsByTheIntegratorsClosedForm) {
  // One body in free fall: a step v' = v - g h, x' = x + v' h changes
  // kinetic + potential energy by -m g^2 h^2 / 2 (the probe's first frame
  // is after step 1, so n more steps move it by n times that).
  RRender *rc = Context();
  MdtWorldID world = MdtWorldCreate(1, 1, 1, 1);
  MdtWorldSetGravity(world, 0, -9.81, 0);
  MdtWorldSetAutoDisable(world, 0);
  MdtBodyID b = MdtBodyCreate(world);
  MdtBodySetMass(b, 2);
  MdtBodyEnable(b);
  RAccuracyProbe *probe = RAccuracyProbeCreate(rc, world);
  const MeReal h = (MeReal)1 / 100;
  RAccuracyFigures f{};
  MdtWorldStep(world, h);
  RAccuracyProbeRead(probe, &f);
  EXPECT_EQ(f.energyDrift, 0);
  for (int i = 0; i < 50; ++i) MdtWorldStep(world, h);
  RAccuracyProbeRead(probe, &f);
  const double expected = -50 * 2 * 9.81 * 9.81 * double(h) * double(h) / 2;
  EXPECT_NEAR(f.energyDrift, expected, 1e-3 * std::fabs(expected));
  EXPECT_EQ(f.jointError, 0);
  EXPECT_EQ(f.penetration, 0);
  RAccuracyProbeDestroy(probe);
  MdtWorldDestroy(world);
  RRenderContextDestroy(rc);
}

// A world with an enabled ball joint whose body 1 carries the joint's
// point `gap` along x from where body 0 carries it.
struct JointWorld {
  MdtWorldID world;
  MdtBSJointID joint;
};

JointWorld MakeJointWorld(MeReal gap) {
  MdtWorldID world = MdtWorldCreate(2, 1, 1, 1);
  MdtBodyID a = MdtBodyCreate(world), b = MdtBodyCreate(world);
  MdtBodySetPosition(b, 1, 0, 0);
  MdtBSJointID j = MdtBSJointCreate(world);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointSetPosition(j, (MeReal)0.5, 0, 0);
  MdtBSJointEnable(j);
  MdtBodySetPosition(b, 1 + gap, 0, 0);
  return {world, j};
}

TEST(MeViewerAccuracy, AJointPulledApartShowsItsGap) {
  RRender *rc = Context();
  const JointWorld jw = MakeJointWorld((MeReal)0.25);
  MdtWorldID world = jw.world;
  RAccuracyProbe *probe = RAccuracyProbeCreate(rc, world);
  RAccuracyProbeAddJoint(probe, MdtBSJointQuaConstraint(jw.joint));
  RAccuracyFigures f{};
  RAccuracyProbeRead(probe, &f);
  EXPECT_NEAR(f.jointError, 0.25, 1e-6);
  RAccuracyProbeDestroy(probe);
  MdtWorldDestroy(world);
  RRenderContextDestroy(rc);
}

TEST(MeViewerAccuracy, ABoxPressedIntoTheGroundShowsThePenetration) {
  // A 1 m cube whose centre starts 0.49 m up: 10 mm into the ground plane.
  // After one step at rest the deepest contact is close to 10 mm (the step
  // pushes it out by at most gamma of it).
  RRender *rc = Context();
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  MstUniverseID u = MstUniverseCreate(&sizes);
  MdtWorldSetGravity(MstUniverseGetWorld(u), 0, -9.81, 0);
  MeMatrix4 ground = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MstFixedModelCreate(u, McdPlaneCreate(MstUniverseGetFramework(u)), ground);
  McdModelID box = MstModelAndBodyCreate(u, McdBoxCreate(MstUniverseGetFramework(u), 1, 1, 1), 10);
  MdtBodySetPosition(McdModelGetBody(box), 0, (MeReal)0.49, 0);
  RAccuracyProbe *probe = RAccuracyProbeCreate(rc, MstUniverseGetWorld(u));
  MstUniverseStep(u, (MeReal)1 / 60);
  RAccuracyFigures f{};
  RAccuracyProbeRead(probe, &f);
  EXPECT_GT(f.penetration, 0.006);
  EXPECT_LT(f.penetration, 0.0101);
  MdtWorldStepStats stats;
  MdtWorldGetStepStats(MstUniverseGetWorld(u), &stats);
  EXPECT_EQ(f.residual, stats.keaResidual);
  RAccuracyProbeDestroy(probe);
  MstUniverseDestroy(u);
  RRenderContextDestroy(rc);
}

TEST(MeViewerAccuracy, AProgramWithoutAProbeIsReadThroughItsWorlds) {
  // No probe and no source: -accuracy reads every live world (MeDiagnostics.h),
  // the largest joint gap of the two worlds.
  RRender *rc = Context("-accuracy");
  ASSERT_TRUE(rc);
  const int before = MeDiagnosticSourceCount();
  MdtWorldID w1 = MakeJointWorld((MeReal)0.25).world, w2 = MakeJointWorld((MeReal)0.1).world;
  EXPECT_EQ(MeDiagnosticSourceCount(), before + 2);
  karma::viewer::SampleAccuracy(rc);
  const karma::viewer::AccuracyState &a = rc->m_pPrivate->accuracy;
  ASSERT_TRUE(a.have);
  EXPECT_NEAR(a.last.jointError, 0.25, 1e-6);
  EXPECT_EQ(a.last.penetration, 0);
  EXPECT_EQ(a.last.energyDrift, 0);  // the first read
  MdtWorldDestroy(w1);
  EXPECT_EQ(MeDiagnosticSourceCount(), before + 1);
  karma::viewer::SampleAccuracy(rc);
  EXPECT_NEAR(a.last.jointError, 0.1, 1e-6);
  MdtWorldDestroy(w2);
  EXPECT_EQ(MeDiagnosticSourceCount(), before);
  RRenderContextDestroy(rc);
}

TEST(MeViewerAccuracy, TheWorldsFiguresSkipJointsWhosePointsNeedNotMeet) {
  // A spring's two ends are apart by design: no joint error from it.
  MdtWorldID world = MdtWorldCreate(2, 1, 1, 1);
  MdtBodyID a = MdtBodyCreate(world), b = MdtBodyCreate(world);
  MdtBodySetPosition(b, 2, 0, 0);
  MdtSpringID s = MdtSpringCreate(world);
  MdtSpringSetBodies(s, a, b);
  MdtSpringEnable(s);
  MeDiagnosticFigures f;
  MdtWorldGetDiagnostics(world, &f);
  EXPECT_EQ(f.jointError, 0);
  MdtWorldDestroy(world);
}

TEST(MeViewerAccuracy, ProfileTableGivesEachQuartersLargestMagnitude) {
  karma::viewer::AccuracyState a;
  for (int i = 0; i < 8; ++i) {
    RAccuracyFigures f{};
    f.jointError = (MeReal)(0.001 * (i + 1));          // 1..8 mm
    f.penetration = (MeReal)(i == 2 ? 0.004 : 0.001);  // 4 mm in the 2nd quarter
    f.energyDrift = (MeReal)(i % 2 ? -2 * i : i);      // the larger magnitude wins, with its sign
    f.residual = 0;
    a.frames.push_back(f);
  }
  std::FILE *out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  karma::viewer::PrintAccuracyReport(a, out);
  std::rewind(out);
  std::string text;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, out)) text += buffer;
  std::fclose(out);
  EXPECT_NE(text.find("accuracy over 8 frames"), std::string::npos) << text;
  EXPECT_NE(text.find("joint error (mm)             2            4            6            8            8"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("penetration (mm)             1            4            1            1            1"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("energy drift (J)            -2           -6          -10          -14          -14"),
            std::string::npos)
      << text;
}

}  // namespace
