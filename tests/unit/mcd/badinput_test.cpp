// badinput_test.cpp: degenerate sizes, NaN, NULL handles, wrong types,
// misuse of pairs and aggregates: a warning naming the function, a defined
// result, no crash.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

TEST(McdBadInput, DegenerateSizesGiveNull) {
  Framework fw;
  WarningCapture w;
  EXPECT_EQ(McdSphereCreate(fw, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("McdSphereCreate"));
  EXPECT_EQ(McdSphereCreate(fw, -1), nullptr);
  EXPECT_EQ(McdSphereCreate(fw, NAN), nullptr);
  EXPECT_EQ(McdSphereCreate(fw, INFINITY), nullptr);
  EXPECT_EQ(McdBoxCreate(fw, 1, 0, 1), nullptr);
  EXPECT_TRUE(w.lastMentions("McdBoxCreate"));
  EXPECT_EQ(McdBoxCreate(fw, 1, 1, NAN), nullptr);
  EXPECT_EQ(McdCylinderCreate(fw, 1, -2), nullptr);
  EXPECT_TRUE(w.lastMentions("McdCylinderCreate"));
  EXPECT_EQ(McdSphylCreate(fw, 0, 1), nullptr);
  EXPECT_EQ(McdSphylCreate(fw, 1, -1), nullptr);
  EXPECT_TRUE(w.lastMentions("McdSphylCreate"));
  EXPECT_EQ(McdAggregateCreate(fw, 0), nullptr);
  MeVector3 mn = {1, 0, 0}, mx = {0, 1, 1};
  auto cb = [](McdModelPair *, McdUserTriangle *, MeVector3, MeReal, int) -> int { return 0; };
  EXPECT_EQ(McdTriangleListCreate(fw, mn, mx, 4, cb), nullptr);
  EXPECT_TRUE(w.lastMentions("exceeds"));
  MeVector3 ok = {2, 2, 2};
  EXPECT_EQ(McdTriangleListCreate(fw, mn, ok, 0, cb), nullptr);
  EXPECT_EQ(McdTriangleListCreate(fw, mn, ok, 4, nullptr), nullptr);
  EXPECT_EQ(McdSphereCreate(nullptr, 1), nullptr);
  EXPECT_EQ(McdPlaneCreate(nullptr), nullptr);
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 0);
  // Setters refuse bad values and keep the old ones.
  McdGeometryID s = McdSphereCreate(fw, 1);
  McdSphereSetRadius(s, -3);
  EXPECT_EQ(McdSphereGetRadius(s), 1);
  McdGeometryID b = McdBoxCreate(fw, 1, 2, 3);
  McdBoxSetDimensions(b, 1, NAN, 3);
  MeReal dy;
  McdBoxGetDimensions(b, nullptr, &dy, nullptr);
  EXPECT_EQ(dy, 2);
}

TEST(McdBadInput, WrongGeometryTypeAndNulls) {
  Framework fw;
  WarningCapture w;
  McdGeometryID box = McdBoxCreate(fw, 1, 1, 1);
  EXPECT_EQ(McdSphereGetRadius(box), 0);
  EXPECT_TRUE(w.lastMentions("McdSphereGetRadius"));
  EXPECT_TRUE(w.lastMentions("Box"));
  EXPECT_EQ(McdCylinderGetHeight(nullptr), 0);
  EXPECT_EQ(McdConvexMeshGetVertexCount(box), 0);
  EXPECT_EQ(McdGeometryGetTypeId(nullptr), kMcdGeometryTypeNull);
  McdGeometryDestroy(nullptr);
  EXPECT_EQ(McdModelCreate(nullptr), nullptr);
  McdModelDestroy(nullptr);
  McdModelUpdate(nullptr);
  EXPECT_TRUE(w.lastMentions("McdModelUpdate"));
  EXPECT_EQ(McdModelGetGeometry(nullptr), nullptr);
  MeReal mass = 5;
  EXPECT_FALSE(McdGeometryGetMassProperties(box, 0, &mass, nullptr, nullptr));
  EXPECT_EQ(mass, 0);
  EXPECT_TRUE(w.lastMentions("density"));
  EXPECT_FALSE(McdGeometryGetMassProperties(box, NAN, &mass, nullptr, nullptr));
}

TEST(McdBadInput, ModelWithoutOrWithNanTransform) {
  Framework fw;
  WarningCapture w;
  McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
  McdModelUpdate(m);
  EXPECT_TRUE(w.lastMentions("no transform"));
  TM tm(1, 0, 0);
  McdModelSetTransformPtr(m, tm);
  McdModelUpdate(m);
  tm.m[3][1] = NAN;
  McdModelUpdate(m);
  EXPECT_TRUE(w.lastMentions("not finite"));
  MeVector3 mn, mx;
  McdModelGetAABB(m, mn, mx);  // the last good AABB
  EXPECT_EQ(mn[0], 0);
  EXPECT_EQ(mx[1], 1);
  McdModelSetSortKey(m, 40000);
  EXPECT_TRUE(w.lastMentions("sort key"));
  TM rel, link;
  McdModelSetRelativeTransformPtrs(m, rel, link, rel);
  EXPECT_TRUE(w.lastMentions("distinct"));
}

TEST(McdBadInput, AggregateMisuse) {
  Framework fw;
  WarningCapture w;
  static TM t, skew;
  McdGeometryID agg = McdAggregateCreate(fw, 1);
  EXPECT_EQ(McdAggregateAddElement(agg, agg, t), -1);
  EXPECT_TRUE(w.lastMentions("itself"));
  EXPECT_EQ(McdAggregateAddElement(agg, McdPlaneCreate(fw), t), -1);
  EXPECT_TRUE(w.lastMentions("Plane"));
  EXPECT_EQ(McdAggregateAddElement(agg, McdSphereCreate(fw, 1), nullptr), -1);
  skew.m[0][0] = 3;  // not a rotation
  EXPECT_EQ(McdAggregateAddElement(agg, McdSphereCreate(fw, 1), skew), -1);
  EXPECT_TRUE(w.lastMentions("rigid"));
  EXPECT_EQ(McdAggregateAddElement(agg, McdSphereCreate(fw, 1), t), 0);
  EXPECT_EQ(McdAggregateAddElement(agg, McdSphereCreate(fw, 1), t), -1);
  EXPECT_TRUE(w.lastMentions("full"));
  EXPECT_EQ(McdAggregateAddElement(McdBoxCreate(fw, 1, 1, 1), McdSphereCreate(fw, 1), t), -1);
  Framework other;
  EXPECT_EQ(McdAggregateAddElement(McdAggregateCreate(fw, 2), McdSphereCreate(other, 1), t), -1);
  EXPECT_TRUE(w.lastMentions("another framework"));
  McdModelID m = McdModelCreate(agg);
  EXPECT_EQ(McdGeometryInstanceGetChild(McdModelGetGeometryInstance(m), 1), nullptr);
  EXPECT_TRUE(w.lastMentions("McdGeometryInstanceGetChild"));
  EXPECT_EQ(McdGeometryInstanceGetChild(nullptr, 0), nullptr);
}

TEST(McdBadInput, PairsAndIntersectMisuse) {
  Framework fw;
  WarningCapture w;
  McdModelID a = McdModelCreate(McdSphereCreate(fw, 1));
  McdModelID b = McdModelCreate(McdSphereCreate(fw, 1));
  TM ta, tb;
  McdModelSetTransformPtr(a, ta);
  McdModelSetTransformPtr(b, tb);
  McdModelUpdate(a);
  McdModelUpdate(b);
  EXPECT_EQ(McdModelPairCreate(a, a), nullptr);
  EXPECT_EQ(McdModelPairCreate(a, nullptr), nullptr);
  McdModelPair *p = McdModelPairCreate(a, b);
  McdContact c[2];
  McdIntersectResult r{};
  r.contacts = c;
  r.contactMaxCount = 2;
  EXPECT_EQ(McdIntersect(p, &r), 0);  // no hello yet
  EXPECT_TRUE(w.lastMentions("McdHello"));
  McdHello(p);
  McdHello(p);  // twice: ignored
  EXPECT_EQ(McdIntersect(p, nullptr), 0);
  r.contacts = nullptr;
  EXPECT_EQ(McdIntersect(p, &r), 0);
  EXPECT_TRUE(w.lastMentions("contacts is NULL"));
  r.contacts = c;
  r.contactMaxCount = -1;
  EXPECT_EQ(McdIntersect(p, &r), 0);
  r.contactMaxCount = 0;  // room for none: touch reported, no contacts
  EXPECT_EQ(McdIntersect(p, &r), 1);
  EXPECT_EQ(r.contactCount, 0);
  McdModelPairReset(p, b, a);
  EXPECT_TRUE(w.lastMentions("between McdHello"));
  McdModelPairDestroy(p);  // says goodbye itself
  McdHello(nullptr);
  McdGoodbye(nullptr);
  EXPECT_FALSE(McdNearby(nullptr));
  EXPECT_EQ(McdModelPairContainerCreate(0), nullptr);
  McdModelPairContainerDestroy(nullptr);
  McdHelloEach(nullptr);
  // Models of different frameworks never collide.
  Framework other;
  McdModelID o = McdModelCreate(McdSphereCreate(other, 1));
  McdModelSetTransformPtr(o, ta);
  McdModelUpdate(o);
  McdModelPair *q = McdModelPairCreate(a, o);
  McdHello(q);
  EXPECT_TRUE(w.lastMentions("different frameworks"));
  r.contactMaxCount = 2;
  EXPECT_EQ(McdIntersect(q, &r), 0);
  McdModelPairDestroy(q);
}

}  // namespace
