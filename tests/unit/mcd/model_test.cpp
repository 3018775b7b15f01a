// model_test.cpp: models: reference counting of geometries, transform
// pointers, relative transforms, the update callback, material, user data,
// body and velocity storage, the model pool.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

TEST(McdModel, GeometriesAreReferenceCounted) {
  Framework fw;
  WarningCapture w;
  McdGeometryID box = McdBoxCreate(fw, 1, 1, 1);
  EXPECT_EQ(McdGeometryGetReferenceCount(box), 0);
  McdModelID a = McdModelCreate(box), b = McdModelCreate(box);
  EXPECT_EQ(McdGeometryGetReferenceCount(box), 2);
  EXPECT_EQ(McdModelGetGeometry(a), box);
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 2);
  McdGeometryDestroy(box);  // still used: warns, nothing happens
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("McdGeometryDestroy"));
  EXPECT_TRUE(w.lastMentions("2 model"));
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 1);
  McdModelDestroy(a);
  EXPECT_EQ(McdGeometryGetReferenceCount(box), 1);
  McdModelDestroy(b);
  McdGeometryDestroy(box);
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 0);
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 0);
  EXPECT_EQ(w.count(), 1u);
}

TEST(McdModel, TransformPointerIsKeptNotCopied) {
  Framework fw;
  McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
  EXPECT_EQ(McdModelGetTransformPtr(m), nullptr);  // the guide: NULL until set
  TM tm(0, 0, 0);
  McdModelSetTransformPtr(m, tm);
  EXPECT_EQ(McdModelGetTransformPtr(m), (MeMatrix4Ptr)tm.m);
  EXPECT_EQ(McdGeometryInstanceGetTransformPtr(McdModelGetGeometryInstance(m)), (MeMatrix4Ptr)tm.m);
  MeVector3 mn, mx;
  McdModelUpdate(m);
  McdModelGetAABB(m, mn, mx);
  EXPECT_EQ(mx[0], 1);
  MeMatrix4TMSetPosition(tm.m, 5, 0, 0);  // moving the matrix moves the model...
  McdModelGetAABB(m, mn, mx);
  EXPECT_EQ(mx[0], 1);  // ...once it is updated
  McdModelUpdate(m);
  McdModelGetAABB(m, mn, mx);
  EXPECT_EQ(mn[0], 4);
  EXPECT_EQ(mx[0], 6);
}

TEST(McdModel, RelativeTransformComposesWithTheLink) {
  Framework fw;
  McdModelID m = McdModelCreate(McdBoxCreate(fw, 2, 2, 2));
  TM rel(1, 0, 0), link(0, 0, 10), global;
  const MeVector3 z = {0, 0, 1};
  link.rotate(z, ME_PI / 2);  // the link's x axis is world y
  McdModelSetRelativeTransformPtrs(m, rel, link, global);
  EXPECT_EQ(McdModelGetTransformPtr(m), (MeMatrix4Ptr)global.m);
  EXPECT_EQ(McdModelGetRelativeTransformPtr(m), (MeMatrix4Ptr)rel.m);
  McdModelUpdate(m);
  // The offset (1, 0, 0) in the link frame is world (0, 1, 0).
  EXPECT_NEAR(global.m[3][0], 0, tol(1));
  EXPECT_NEAR(global.m[3][1], 1, tol(1));
  EXPECT_NEAR(global.m[3][2], 10, tol(10));
  MeVector3 mn, mx;
  McdModelGetAABB(m, mn, mx);
  EXPECT_NEAR(mn[1], 0, tol(1));
  EXPECT_NEAR(mx[1], 2, tol(1));
  // Setting a plain transform pointer drops the relative transform.
  TM plain(0, 0, 0);
  McdModelSetTransformPtr(m, plain);
  EXPECT_EQ(McdModelGetRelativeTransformPtr(m), nullptr);
}

int gCalls = 0;
MeReal gSeenMax = 0;
void MEAPI CountUpdate(McdModelID m) {
  ++gCalls;
  MeVector3 mn, mx;
  McdModelGetAABB(m, mn, mx);  // the callback sees the fresh AABB
  gSeenMax = mx[2];
}

TEST(McdModel, UpdateCallbackRunsAfterTheAabb) {
  Framework fw;
  McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
  TM tm(0, 0, 3);
  McdModelSetTransformPtr(m, tm);
  gCalls = 0;
  McdModelSetUpdateCallback(m, CountUpdate);
  EXPECT_EQ(McdModelGetUpdateCallback(m), &CountUpdate);
  McdModelUpdate(m);
  McdModelUpdate(m);
  EXPECT_EQ(gCalls, 2);
  EXPECT_EQ(gSeenMax, 4);
  McdModelSetUpdateCallback(m, nullptr);
  McdModelUpdate(m);
  EXPECT_EQ(gCalls, 2);
}

TEST(McdModel, PropertiesBodyAndVelocities) {
  Framework fw;
  McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
  EXPECT_EQ(McdModelGetMaterial(m), 0);
  McdModelSetMaterial(m, 3);
  EXPECT_EQ(McdModelGetMaterial(m), 3);
  EXPECT_EQ(McdGeometryInstanceGetMaterial(McdModelGetGeometryInstance(m)), 3);
  int tag = 0;
  McdModelSetUserData(m, &tag);
  EXPECT_EQ(McdModelGetUserData(m), &tag);
  EXPECT_EQ(McdModelGetFramework(m), fw.id);
  EXPECT_EQ(McdModelGetBody(m), nullptr);
  MdtBodyID fake = reinterpret_cast<MdtBodyID>(&tag);  // Mcd only stores it
  McdModelStoreBody(m, fake);
  EXPECT_EQ(McdModelGetBody(m), fake);
  MeVector3 v = {1, 2, 3}, w = {4, 5, 6};
  EXPECT_EQ(McdModelGetLinearVelocityPtr(m), nullptr);
  McdModelSetLinearVelocityPtr(m, v);
  McdModelSetAngularVelocityPtr(m, w);
  EXPECT_EQ(McdModelGetLinearVelocityPtr(m), v);
  EXPECT_EQ(McdModelGetAngularVelocityPtr(m)[2], 6);
  McdModelSetSortKey(m, 7);
  EXPECT_EQ(McdModelGetSortKey(m), 7);
  EXPECT_EQ(McdModelGetSpace(m), nullptr);
  EXPECT_EQ(McdModelGetSpaceIndex(m), -1);
  McdModelSetSpaceData(m, &tag, 4);
  EXPECT_EQ(McdModelGetSpaceIndex(m), 4);
  McdModelSetSpaceData(m, nullptr, 0);
}

TEST(McdModel, PoolExhaustionWarnsAndReturnsNull) {
  Framework fw(2);
  WarningCapture w;
  McdGeometryID s = McdSphereCreate(fw, 1);
  McdModelID a = McdModelCreate(s), b = McdModelCreate(s);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(McdModelCreate(s), nullptr);
  EXPECT_EQ(w.count(), 1u);
  EXPECT_EQ(McdGeometryGetReferenceCount(s), 2);
  McdModelDestroy(a);
  EXPECT_NE(McdModelCreate(s), nullptr);
}

TEST(McdModel, DestroyAllAndTerm) {
  Framework fw;
  McdGeometryID s = McdSphereCreate(fw, 1);
  static TM t;
  McdGeometryID agg = McdAggregateCreate(fw, 2);
  McdAggregateAddElement(agg, s, t);
  McdModelCreate(s);
  McdModelCreate(agg);
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 2);
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 2);
  McdFrameworkDestroyAllModelsAndGeometries(fw);
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 0);
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 0);
  EXPECT_NE(McdSphereCreate(fw, 1), nullptr);  // still usable; McdTerm frees the rest
}

// A model in a space is named by the space's proxy and pairs: it cannot be
// destroyed until it leaves, nor its framework freed until the space goes.
TEST(McdModel, AModelInASpaceIsNotDestroyedNorItsFrameworkFreed) {
  McdFrameworkID fw = McdInit(0, 8, 8, 1);
  McdPrimitivesRegisterTypes(fw);
  McdPrimitivesRegisterInteractions(fw);
  McdGeometryID ball = McdSphereCreate(fw, 1);
  static TM t;
  McdModelID m = McdModelCreate(ball);
  McdModelSetTransformPtr(m, t);
  McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 8, 16);  // in a change block
  ASSERT_TRUE(McdSpaceInsertModel(space, m));
  {
    WarningCapture w;
    McdModelDestroy(m);
    EXPECT_EQ(w.count(), 1u);
    McdFrameworkDestroyAllModelsAndGeometries(fw);
    EXPECT_EQ(w.count(), 2u);
    McdTerm(fw);
    EXPECT_EQ(w.count(), 3u);
  }
  EXPECT_EQ(McdModelGetSpace(m), space);  // all three left it alone
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 1);
  EXPECT_EQ(McdGeometryGetReferenceCount(ball), 1);
  McdSpaceUpdateAll(space);
  McdSpaceEndChanges(space);
  McdSpaceBeginChanges(space);
  ASSERT_TRUE(McdSpaceRemoveModel(m));
  WarningCapture w;
  McdModelDestroy(m);
  EXPECT_EQ(McdFrameworkGetModelCount(fw), 0);
  McdSpaceDestroy(space);
  McdTerm(fw);  // frees everything: no space is left
  EXPECT_EQ(w.count(), 0u);
}

// Without an AABB function a space takes a model's own bounds, which a
// model never placed, or placed only at non-finite transforms, lacks.
TEST(McdModel, AModelWithoutBoundsIsNotInsertedIntoASpace) {
  Framework fw;
  McdGeometryID ball = McdSphereCreate(fw, 1);
  McdModelID none = McdModelCreate(ball), bad = McdModelCreate(ball), good = McdModelCreate(ball);
  static TM nan(std::nanf(""), 0, 0), origin;
  McdModelSetTransformPtr(bad, nan);
  McdModelSetTransformPtr(good, origin);
  McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 8, 16);
  {
    WarningCapture w;
    EXPECT_FALSE(McdSpaceInsertModel(space, none));
    EXPECT_FALSE(McdSpaceInsertModel(space, bad));  // McdModelUpdate warns too
    EXPECT_EQ(w.count(), 3u);
  }
  EXPECT_EQ(McdModelGetSpace(none), nullptr);
  EXPECT_EQ(McdModelGetSpace(bad), nullptr);
  EXPECT_TRUE(McdSpaceInsertModel(space, good));
  ASSERT_TRUE(McdSpaceRemoveModel(good));
  McdSpaceDestroy(space);
  for (McdModelID m : {none, bad, good}) McdModelDestroy(m);
}

}  // namespace
