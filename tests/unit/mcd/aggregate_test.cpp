// aggregate_test.cpp: aggregate elements, child geometry instances from the
// framework's pool, child transform pointers and nesting.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

TEST(McdAggregate, ChildInstancesFollowTheElements) {
  Framework fw(8, 10);
  static TM seatTM(0, 0, 1), legTM[4] = {TM(1, 1, 0), TM(1, -1, 0), TM(-1, 1, 0), TM(-1, -1, 0)};
  McdGeometryID seat = McdBoxCreate(fw, (MeReal)2.2, (MeReal)2.2, (MeReal)0.1);
  McdGeometryID leg = McdCylinderCreate(fw, (MeReal)0.1, 2);
  McdGeometryID ag = McdAggregateCreate(fw, 5);
  EXPECT_EQ(McdAggregateAddElement(ag, seat, seatTM), 0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(McdAggregateAddElement(ag, leg, legTM[i]), i + 1);
  EXPECT_EQ(McdAggregateGetElementCount(ag), 5);
  EXPECT_EQ(McdAggregateGetElementTransformPtr(ag, 2), (MeMatrix4Ptr)legTM[1].m);  // a pointer
  EXPECT_EQ(McdAggregateGetElementGeometry(ag, 3), leg);

  McdModelID model = McdModelCreate(ag);
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(McdGeometryGetReferenceCount(ag), 1);
  McdGeometryInstanceID parent = McdModelGetGeometryInstance(model);
  ASSERT_EQ(McdGeometryInstanceGetChildCount(parent), 5);
  EXPECT_EQ(McdGeometryInstanceGetGeometry(McdGeometryInstanceGetChild(parent, 0)), seat);
  EXPECT_EQ(McdGeometryInstanceGetGeometry(McdGeometryInstanceGetChild(parent, 4)), leg);

  // The guide's rendering idiom: give children TM storage, update, read.
  static MeMatrix4 childTM[5];
  for (int i = 0; i < 5; ++i) McdGeometryInstanceSetTransformPtr(McdGeometryInstanceGetChild(parent, i), childTM[i]);
  TM body(10, 0, 0);
  const MeVector3 z = {0, 0, 1};
  body.rotate(z, ME_PI / 2);
  McdModelSetTransformPtr(model, body);
  McdModelUpdate(model);
  // Seat at body + (0,0,1); leg 1 at (1,1,0) turned 90 degrees: (-1, 1, 0).
  EXPECT_NEAR(childTM[0][3][0], 10, tol(10));
  EXPECT_NEAR(childTM[0][3][2], 1, tol(1));
  EXPECT_NEAR(childTM[1][3][0], 9, tol(10));
  EXPECT_NEAR(childTM[1][3][1], 1, tol(1));
  EXPECT_EQ(McdGeometryInstanceGetTransformPtr(McdGeometryInstanceGetChild(parent, 1)), (MeMatrix4Ptr)childTM[1]);
  // The child's AABB is cached too; the model's is the union.
  MeVector3 mn, mx;
  McdGeometryInstanceGetAABB(McdGeometryInstanceGetChild(parent, 1), mn, mx);
  EXPECT_NEAR(mn[2], -1, tol(1));
  McdModelGetAABB(model, mn, mx);
  EXPECT_NEAR(mn[2], -1, tol(1));
  EXPECT_NEAR(mx[2], (MeReal)1.05, tol(1));
  EXPECT_NEAR(mx[0], (MeReal)11.1, tol(11));

  // Five instances in use; destroying the model gives them back.
  McdModelID second = McdModelCreate(ag);
  ASSERT_NE(second, nullptr);
  WarningCapture w;
  EXPECT_EQ(McdModelCreate(ag), nullptr);  // 15 > 10 instances
  EXPECT_TRUE(w.lastMentions("instance"));
  McdModelDestroy(second);
  McdModelDestroy(model);
  EXPECT_EQ(McdGeometryGetReferenceCount(ag), 0);
  EXPECT_NE(McdModelCreate(ag), nullptr);
}

TEST(McdAggregate, ChildrenWithoutPointersStillHaveTransforms) {
  Framework fw;
  static TM offset(0, 2, 0);
  McdGeometryID ag = McdAggregateCreate(fw, 1);
  McdAggregateAddElement(ag, McdSphereCreate(fw, 1), offset);
  McdModelID m = McdModelCreate(ag);
  TM tm(1, 0, 0);
  McdModelSetTransformPtr(m, tm);
  McdModelUpdate(m);
  MeMatrix4Ptr child =
      McdGeometryInstanceGetTransformPtr(McdGeometryInstanceGetChild(McdModelGetGeometryInstance(m), 0));
  ASSERT_NE(child, nullptr);
  EXPECT_EQ(child[3][0], 1);
  EXPECT_EQ(child[3][1], 2);
  // Changing the relTM the aggregate points at moves the element.
  MeMatrix4TMSetPosition(offset.m, 0, 0, 3);
  McdModelUpdate(m);
  EXPECT_EQ(child[3][2], 3);
}

TEST(McdAggregate, NestedAggregates) {
  Framework fw;
  static TM a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
  McdGeometryID ball = McdSphereCreate(fw, (MeReal)0.5);
  McdGeometryID inner = McdAggregateCreate(fw, 2);
  McdAggregateAddElement(inner, ball, a);
  McdAggregateAddElement(inner, ball, b);
  McdGeometryID outer = McdAggregateCreate(fw, 2);
  McdAggregateAddElement(outer, inner, c);
  McdAggregateAddElement(outer, McdBoxCreate(fw, 1, 1, 1), a);
  WarningCapture w;
  EXPECT_EQ(McdAggregateAddElement(inner, ball, c), -1);  // closed once referenced
  EXPECT_TRUE(w.lastMentions("already used"));
  McdModelID m = McdModelCreate(outer);
  ASSERT_NE(m, nullptr);
  McdGeometryInstanceID top = McdModelGetGeometryInstance(m);
  McdGeometryInstanceID in = McdGeometryInstanceGetChild(top, 0);
  ASSERT_EQ(McdGeometryInstanceGetChildCount(in), 2);
  TM tm;
  McdModelSetTransformPtr(m, tm);
  McdModelUpdate(m);
  // inner at (0,0,1); its second ball at (0,1,0) more: (0, 1, 1).
  MeMatrix4Ptr t = McdGeometryInstanceGetTransformPtr(McdGeometryInstanceGetChild(in, 1));
  EXPECT_EQ(t[3][0], 0);
  EXPECT_EQ(t[3][1], 1);
  EXPECT_EQ(t[3][2], 1);
  MeReal mass;
  ASSERT_TRUE(McdGeometryGetMassProperties(outer, 1, &mass, nullptr, nullptr));
  EXPECT_NEAR(mass, 1 + 2 * 4.0 / 3 * ME_PI * 0.125, tol(2));
  McdModelDestroy(m);
  McdGeometryDestroy(inner);  // referenced by outer: refused
  EXPECT_TRUE(w.lastMentions("still used"));
  McdGeometryDestroy(outer);
  McdGeometryDestroy(inner);
  EXPECT_EQ(McdGeometryGetReferenceCount(ball), 0);
}

}  // namespace
