// pair_test.cpp: pair containers (the guide's block layout, hello/goodbye
// each) and the triangle list query that nearfield tests call.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

struct Body {
  McdModelID model;
  TM tm;
  Body(McdGeometryID g, MeReal x, MeReal y, MeReal z) : model(McdModelCreate(g)), tm(x, y, z) {
    McdModelSetTransformPtr(model, tm);
    McdModelUpdate(model);
  }
  ~Body() { McdModelDestroy(model); }
  void update() { McdModelUpdate(model); }
};

TEST(McdPairs, ContainerLayoutAndHelloEach) {
  Framework fw;
  McdModelPairContainer *c = McdModelPairContainerCreate(8);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->size, 8);
  EXPECT_EQ(c->goodbyeFirst, 0);
  EXPECT_EQ(c->goodbyeEnd, 0);
  EXPECT_EQ(c->helloFirst, 4);
  EXPECT_EQ(c->helloEnd, 4);
  EXPECT_EQ(c->stayingFirst, 4);
  EXPECT_EQ(c->stayingEnd, 4);
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)0.5);
  // The guide's Q&A inserts a hello pair by hand like this.
  McdModelPair *pair = McdModelPairCreate(ball.model, ground.model);
  c->helloFirst = c->helloFirst - 1;
  c->array[c->helloFirst] = pair;
  McdHelloEach(c);
  EXPECT_EQ(pair->m_helloed, 1);
  McdContact contacts[4];
  McdIntersectResult r{};
  r.contacts = contacts;
  r.contactMaxCount = 4;
  for (int i = c->helloFirst; i < c->stayingEnd; ++i) EXPECT_EQ(McdIntersect(c->array[i], &r), 1);
  // Goodbye block.
  c->array[0] = pair;
  c->goodbyeEnd = 1;
  McdGoodbyeEach(c);
  EXPECT_EQ(pair->m_helloed, 0);
  McdModelPairContainerReset(c);
  EXPECT_EQ(c->goodbyeEnd, 0);
  EXPECT_EQ(c->helloFirst, 4);
  McdModelPairDestroy(pair);
  McdModelPairContainerDestroy(c);
}

int gTriangleCalls = 0;
MeVector3 gVerts[3] = {{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}};
MeVector3 gNormal = {0, 0, 1};
int MEAPI Greedy(McdModelPair *, McdUserTriangle *list, MeVector3, MeReal, int max) {
  ++gTriangleCalls;
  for (int i = 0; i < max; ++i) {
    list[i].vertices[0] = &gVerts[0];
    list[i].vertices[1] = &gVerts[1];
    list[i].vertices[2] = &gVerts[2];
    list[i].normal = &gNormal;
    list[i].flags = kMcdTriangleStandard;
  }
  return max + 3;  // claims more than it may
}

TEST(McdTriangleList, QueryClampsAnOverlongCallback) {
  Framework fw;
  MeVector3 mn = {-10, -10, -1}, mx = {10, 10, 0};
  McdGeometryID g = McdTriangleListCreate(fw, mn, mx, 2, Greedy);
  ASSERT_NE(g, nullptr);
  ((McdTriangleList *)g)->triangleMaxCount = 5;  // as the guide's QuadBike does
  EXPECT_EQ(McdTriangleListGetMaxTriangles(g), 5);
  WarningCapture w;
  McdUserTriangle *tris = nullptr;
  MeVector3 pos = {0, 0, 0};
  const int n = McdTriangleListGetTriangles(g, nullptr, pos, 1, &tris);
  EXPECT_EQ(n, 5);
  ASSERT_NE(tris, nullptr);
  EXPECT_EQ(tris[4].normal, &gNormal);
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("returned 8 triangles"));
  EXPECT_TRUE(w.lastMentions("triangleMaxCount is 5"));
  EXPECT_EQ(kMcdTriangleStandard, kMcdTriangleUseSmallestPenetration | kMcdTriangleTwoSided | kMcdTriangleUseEdge0 |
                                      kMcdTriangleUseEdge1 | kMcdTriangleUseEdge2);
}

}  // namespace
