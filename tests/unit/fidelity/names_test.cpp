// names_test.cpp: the names the guide uses that the headers lacked (issue
// 19, item 2). Each older name must do what its current name does; the
// request pointer must cap McdIntersect's contacts; DebugDrawOptions must
// default to 0 (Appendix A).
#include <gtest/gtest.h>

#include "Mcd.h"
#include "Mdt.h"
#include "MeViewer.h"
#include "support/warning_capture.h"

using karma_test::WarningCapture;

namespace {

// A framework with the primitives, two unit spheres 1.5 apart (overlapping
// boxes) in one space, after one change block.
struct TwoSpheres {
  McdFrameworkID fw = McdInit(0, 8, 16, 1);
  McdSpaceID space = nullptr;
  McdGeometryID ball = nullptr;
  MeMatrix4 tm[2];
  McdModelID m[2] = {nullptr, nullptr};
  TwoSpheres() {
    McdPrimitivesRegisterTypes(fw);
    McdPrimitivesRegisterInteractions(fw);
    space = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 4);
    ball = McdSphereCreate(fw, 1);
    for (int i = 0; i < 2; ++i) {
      MeMatrix4TMMakeIdentity(tm[i]);
      MeMatrix4TMSetPosition(tm[i], (MeReal)1.5 * (MeReal)i, 0, 0);
      m[i] = McdModelCreate(ball);
      McdModelSetTransformPtr(m[i], tm[i]);
      McdSpaceInsertModel(space, m[i]);
    }
    McdSpaceUpdate(space);  // the older name of McdSpaceUpdateAll
    McdSpaceEndChanges(space);
  }
  ~TwoSpheres() {
    McdSpaceDestroy(space);
    for (McdModelID x : m) McdModelDestroy(x);
    McdGeometryDestroy(ball);
    McdTerm(fw);
  }
  // Goodbye, hello and staying counts of the change block just ended.
  void counts(int *goodbye, int *hello, int *staying) {
    McdModelPairContainer *c = McdModelPairContainerCreate(8);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    McdSpaceGetPairs(space, &it, c);
    *goodbye = c->goodbyeEnd - c->goodbyeFirst;
    *hello = c->helloEnd - c->helloFirst;
    *staying = c->stayingEnd - c->stayingFirst;
    McdModelPairContainerDestroy(c);
  }
};

}  // namespace

TEST(GuideNames, McdSpaceUpdateReportsTheOverlapAsMcdSpaceUpdateAllDoes) {
  TwoSpheres s;
  int g, h, st;
  s.counts(&g, &h, &st);
  EXPECT_EQ(h, 1);
  // Moved apart: McdSpaceUpdateAllModels (= McdSpaceUpdateModels) sees it.
  McdSpaceBeginChanges(s.space);
  MeMatrix4TMSetPosition(s.tm[1], 10, 0, 0);
  McdSpaceUpdateAllModels(s.space);
  McdSpaceEndChanges(s.space);
  s.counts(&g, &h, &st);
  EXPECT_EQ(g, 1);
  EXPECT_EQ(h + st, 0);
}

TEST(GuideNames, FreezeAndUnfreezeUnderTheOlderNames) {
  TwoSpheres s;
  EXPECT_FALSE(McdSpaceIsFrozen(s.m[0]));
  EXPECT_TRUE(McdSpaceFreezeModel(s.m[0]));
  EXPECT_TRUE(McdSpaceIsFrozen(s.m[0]));
  EXPECT_EQ(McdSpaceIsFrozen(s.m[0]), McdSpaceModelIsFrozen(s.m[0]));
  EXPECT_TRUE(McdUnfreezeInSpace(s.m[0]));
  EXPECT_FALSE(McdSpaceIsFrozen(s.m[0]));
  EXPECT_FALSE(McdSpaceModelIsFrozen(s.m[0]));
}

TEST(GuideNames, McdDisablePairTurnsTheStayingPairIntoAGoodbye) {
  TwoSpheres s;
  McdSpaceBeginChanges(s.space);
  EXPECT_TRUE(McdSpacePairIsEnabled(s.m[0], s.m[1]));
  EXPECT_TRUE(McdDisablePair(s.m[0], s.m[1]));
  EXPECT_FALSE(McdSpacePairIsEnabled(s.m[0], s.m[1]));
  McdSpaceEndChanges(s.space);
  int g, h, st;
  s.counts(&g, &h, &st);
  EXPECT_EQ(g, 1);  // the guide: "that pair will appear as a goodbye pair"
  EXPECT_EQ(h + st, 0);
}

namespace {

// A 2 x 2 x 2 box sunk 0.1 into a plane (normal z): four corner contacts.
struct BoxOnPlane {
  McdFrameworkID fw = McdInit(0, 4, 8, 1);
  McdGeometryID box = nullptr, plane = nullptr;
  MeMatrix4 boxTM, planeTM;
  McdModelID b = nullptr, p = nullptr;
  McdModelPairID pair = nullptr;
  McdContact contacts[10];
  BoxOnPlane() {
    McdPrimitivesRegisterTypes(fw);
    McdPrimitivesRegisterInteractions(fw);
    box = McdBoxCreate(fw, 2, 2, 2);
    plane = McdPlaneCreate(fw);
    MeMatrix4TMMakeIdentity(boxTM);
    MeMatrix4TMSetPosition(boxTM, 0, 0, (MeReal)0.9);
    MeMatrix4TMMakeIdentity(planeTM);
    b = McdModelCreate(box);
    p = McdModelCreate(plane);
    McdModelSetTransformPtr(b, boxTM);
    McdModelSetTransformPtr(p, planeTM);
    McdModelUpdate(b);
    McdModelUpdate(p);
    pair = McdModelPairCreate(b, p);
  }
  ~BoxOnPlane() {
    McdModelPairDestroy(pair);
    McdModelDestroy(b);
    McdModelDestroy(p);
    McdGeometryDestroy(box);
    McdGeometryDestroy(plane);
    McdTerm(fw);
  }
  int intersect() {
    McdIntersectResult r{};
    r.contacts = contacts;
    r.contactMaxCount = 10;
    McdIntersect(pair, &r);
    EXPECT_EQ(r.contactMaxCount, 10);  // the caller's cap is given back unchanged
    return r.contactCount;
  }
};

}  // namespace

TEST(GuideNames, TheRequestCapsTheContactsOfItsPair) {
  BoxOnPlane s;
  McdRequest request{2};
  EXPECT_EQ(McdModelPairGetRequestPtr(s.pair), nullptr);
  McdModelPairSetRequestPtr(s.pair, &request);
  EXPECT_EQ(McdModelPairGetRequestPtr(s.pair), &request);
  McdHello(s.pair);
  EXPECT_EQ(s.intersect(), 2);
  request.contactMaxCount = 0;  // no cap of its own
  EXPECT_EQ(s.intersect(), 4);
  // The guide: not allowed between McdHello and McdGoodbye.
  {
    WarningCapture cap;
    McdModelPairSetRequestPtr(s.pair, nullptr);
    EXPECT_EQ(cap.count(), 1u);
    EXPECT_TRUE(cap.lastMentions("McdModelPairSetRequestPtr"));
  }
  EXPECT_EQ(McdModelPairGetRequestPtr(s.pair), &request);
  McdGoodbye(s.pair);
  McdModelPairSetRequestPtr(s.pair, nullptr);
  EXPECT_EQ(McdModelPairGetRequestPtr(s.pair), nullptr);
}

TEST(GuideNames, TheBothAxesNamesAreTheAxesFunctions) {
  MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
  MdtHingeID h = MdtHingeCreate(w);
  MdtHingeSetBodies(h, a, b);
  MdtConstraintSetBothAxis(MdtHingeQuaConstraint(h), 0, 0, 2, 0, 3, 0);
  MeVector3 p, o, p1, o1;
  MdtConstraintGetAxes(MdtHingeQuaConstraint(h), p, o);
  EXPECT_NEAR(p[2], 1, 1e-6);  // normalised, as the guide says
  EXPECT_NEAR(o[1], 1, 1e-6);
  MdtConstraintGetBothAxes(MdtHingeQuaConstraint(h), p1, o1);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(p1[k], p[k]);
    EXPECT_EQ(o1[k], o[k]);
  }
  MdtConstraintBodyGetAxes(MdtHingeQuaConstraint(h), 1, p, o);
  MdtConstraintBodyGetBothAxes(MdtHingeQuaConstraint(h), 1, p1, o1);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(p1[k], p[k]);
    EXPECT_EQ(o1[k], o[k]);
  }
  MdtWorldDestroy(w);
}

TEST(GuideNames, DebugDrawOptionsDefaultsToZeroAndIsKept) {
  MdtWorldID w = MdtWorldCreate(1, 1, 1, 1);
  EXPECT_EQ(MdtWorldGetDebugDrawOptions(w), 0);  // Appendix A
  MdtWorldSetDebugDrawOptions(w, 5);
  EXPECT_EQ(MdtWorldGetDebugDrawOptions(w), 5);
  MdtWorldDestroy(w);
}

TEST(GuideNames, TextureOlderNames) {
  MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString("prog -null");
  RRender *rc = RRenderContextCreate(o, nullptr, 1);
  MeCommandLineOptionsDestroy(o);
  ASSERT_NE(rc, nullptr);
  char first[] = "first", second[] = "second";
  EXPECT_EQ(RCreateTextureID(rc, first), 0);
  EXPECT_EQ(RRenderTextureCreate(rc, second), 1);
  EXPECT_EQ(RCreateTextureID(rc, second), 1);  // a name seen before keeps its ID
  RGraphic *g = RGraphicCreateEmpty(3);
  EXPECT_EQ(RSetTexture(rc, g, first), 0);
  EXPECT_EQ(g->m_pObject->m_nTextureID, 0);
  RGraphicDestroy(g);
  RRenderContextDestroy(rc);
}
