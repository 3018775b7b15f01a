// interaction_test.cpp: the interaction table and the dispatcher: hello /
// intersect / goodbye, both argument orders with flipped normals, the
// built-in sphere-sphere, sphere-plane and box-plane tests, unregistered
// pairs, user interactions, pair containers and triangle list queries.
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

struct Query {
  McdModelPair *pair;
  McdContact contacts[16];
  McdIntersectResult r{};
  int touch = 0;
  Query(McdModelID a, McdModelID b, int max = 16) {
    pair = McdModelPairCreate(a, b);
    McdHello(pair);
    r.contacts = contacts;
    r.contactMaxCount = max;
    touch = McdIntersect(pair, &r);
  }
  ~Query() {
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
  }
};

TEST(McdInteraction, SphereRestingInPlaneOneContactWithDepth) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body ball(McdSphereCreate(fw, 1), 2, 3, (MeReal)0.9);  // 0.1 into the plane
  Query t(ball.model, ground.model);
  ASSERT_EQ(t.touch, 1);
  ASSERT_EQ(t.r.contactCount, 1);
  EXPECT_EQ(t.r.touch, 1);
  EXPECT_EQ(t.r.pair, t.pair);
  EXPECT_EQ(t.r.model1, ball.model);
  const McdContact &c = t.contacts[0];
  EXPECT_NEAR(c.separation, -0.1, tol(1));
  EXPECT_EQ(c.normal[2], 1);  // from the plane (model2) towards the ball (model1)
  EXPECT_NEAR(c.position[0], 2, tol(2));
  EXPECT_NEAR(c.position[1], 3, tol(3));
  EXPECT_NEAR(c.position[2], -0.05, tol(1));  // midway between z = -0.1 and 0
  EXPECT_EQ(t.r.normal[2], 1);
  // Lifted clear: no contact.
  MeMatrix4TMSetPosition(ball.tm.m, 0, 0, (MeReal)1.5);
  ball.update();
  Query apart(ball.model, ground.model);
  EXPECT_EQ(apart.touch, 0);
  EXPECT_EQ(apart.r.contactCount, 0);
}

TEST(McdInteraction, ReversedOrderFlipsNormalsAndElements) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)0.75);
  Query forward(ball.model, ground.model), reverse(ground.model, ball.model);
  ASSERT_EQ(reverse.touch, 1);
  ASSERT_EQ(reverse.r.contactCount, 1);
  EXPECT_EQ(reverse.r.model1, ground.model);  // the caller's order is kept
  EXPECT_EQ(reverse.pair->model1, ground.model);
  EXPECT_EQ(reverse.contacts[0].normal[2], -1);
  EXPECT_EQ(reverse.r.normal[2], -1);
  EXPECT_EQ(reverse.contacts[0].separation, forward.contacts[0].separation);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(reverse.contacts[0].position[k], forward.contacts[0].position[k]);
  // The table: one explicit entry and its mirror.
  const McdInteractions *sp = McdFrameworkGetInteraction(fw, kMcdGeometryTypeSphere, kMcdGeometryTypePlane);
  const McdInteractions *ps = McdFrameworkGetInteraction(fw, kMcdGeometryTypePlane, kMcdGeometryTypeSphere);
  ASSERT_NE(sp, nullptr);
  ASSERT_NE(ps, nullptr);
  EXPECT_EQ(sp->swap, 0);
  EXPECT_EQ(ps->swap, 1);
  EXPECT_EQ(sp->intersectFn, ps->intersectFn);
}

TEST(McdInteraction, SphereSphereBothOrders) {
  Framework fw;
  McdGeometryID big = McdSphereCreate(fw, 2), small = McdSphereCreate(fw, 1);
  Body a(big, 0, 0, 0), b(small, (MeReal)2.5, 0, 0);
  Query ab(a.model, b.model), ba(b.model, a.model);
  ASSERT_EQ(ab.r.contactCount, 1);
  ASSERT_EQ(ba.r.contactCount, 1);
  EXPECT_NEAR(ab.contacts[0].separation, -0.5, tol(2));
  EXPECT_EQ(ab.contacts[0].normal[0], -1);                // from b towards a
  EXPECT_EQ(ba.contacts[0].normal[0], 1);                 // from a towards b
  EXPECT_NEAR(ab.contacts[0].position[0], 1.75, tol(2));  // midway between x = 1.5 and 2
  EXPECT_EQ(ab.contacts[0].dims, (MeI16)(2 | (2 << 8)));
  Body far(small, 10, 0, 0);
  Query none(a.model, far.model);
  EXPECT_EQ(none.touch, 0);
  EXPECT_FALSE(McdNearby(none.pair));
  EXPECT_TRUE(McdNearby(ab.pair));
}

TEST(McdInteraction, BoxRestingFlatOnPlaneHasFourContacts) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body box(McdBoxCreate(fw, 2, 1, 3), 0, 0, (MeReal)1.49);  // 0.01 deep
  Query t(box.model, ground.model);
  ASSERT_EQ(t.touch, 1);
  ASSERT_EQ(t.r.contactCount, 4);
  for (int i = 0; i < 4; ++i) {
    const McdContact &c = t.contacts[i];
    EXPECT_NEAR(c.separation, -0.01, tol(2, 256));
    EXPECT_EQ(c.normal[2], 1);
    EXPECT_NEAR(std::fabs(c.position[0]), 1, tol(1));
    EXPECT_NEAR(std::fabs(c.position[1]), 0.5, tol(1));
    EXPECT_EQ(c.dims, (MeI16)(0 | (2 << 8)));  // box vertex on plane face
  }
  // Exactly touching (separation 0) still counts.
  MeMatrix4TMSetPosition(box.tm.m, 0, 0, (MeReal)1.5);
  box.update();
  Query touching(box.model, ground.model);
  EXPECT_EQ(touching.r.contactCount, 4);
  // Reversed: four contacts, normals down.
  Query reverse(ground.model, box.model);
  ASSERT_EQ(reverse.r.contactCount, 4);
  EXPECT_EQ(reverse.contacts[2].normal[2], -1);
  EXPECT_EQ(reverse.contacts[2].dims, (MeI16)(2 | (0 << 8)));
  // Tilted onto an edge: two contacts; a small buffer keeps the deepest.
  const MeVector3 y = {0, 1, 0};
  box.tm.rotate(y, (MeReal)0.3);
  MeMatrix4TMSetPosition(box.tm.m, 0, 0, (MeReal)1.7);  // lowest edge 0.03 deep
  box.update();
  Query tilted(box.model, ground.model), one(box.model, ground.model, 1);
  EXPECT_EQ(tilted.r.contactCount, 2);
  ASSERT_EQ(one.r.contactCount, 1);
  EXPECT_EQ(one.contacts[0].separation, std::fmin(tilted.contacts[0].separation, tilted.contacts[1].separation));
}

TEST(McdInteraction, UnregisteredPairsAreIgnored) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body can(McdCylinderCreate(fw, 1, 2), 0, 0, 0);  // deep in the plane, but no test
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypePlane, nullptr);
  WarningCapture w;
  Query t(can.model, ground.model);
  EXPECT_EQ(t.touch, 0);
  EXPECT_EQ(t.r.contactCount, 0);
  EXPECT_EQ(w.count(), 0u);
  EXPECT_EQ(McdFrameworkGetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypePlane), nullptr);
  // A framework with types but no interactions ignores everything.
  Framework bare(8, 8, 1, false);
  McdSphereBoxPlaneRegisterTypes(bare);
  Body g2(McdPlaneCreate(bare), 0, 0, 0), b2(McdSphereCreate(bare, 1), 0, 0, 0);
  Query none(b2.model, g2.model);
  EXPECT_EQ(none.touch, 0);
  McdSphereBoxPlaneRegisterInteractions(bare);
  Query now(b2.model, g2.model);
  EXPECT_EQ(now.touch, 1);
}

TEST(McdInteraction, APairKeepsTheInteractionItWasGreetedWithWhenTheEntryIsCleared) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)0.9);  // 0.1 into the plane
  Query t(ball.model, ground.model);  // greeted with the sphere-plane test
  ASSERT_EQ(t.touch, 1);
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeSphere, kMcdGeometryTypePlane, nullptr);
  McdFrameworkSetInteraction(fw, kMcdGeometryTypePlane, kMcdGeometryTypeSphere, nullptr);
  ASSERT_EQ(McdFrameworkGetInteraction(fw, kMcdGeometryTypeSphere, kMcdGeometryTypePlane), nullptr);
  t.r.contactCount = 0;
  EXPECT_EQ(McdIntersect(t.pair, &t.r), 1);  // still the test it was greeted with
  ASSERT_EQ(t.r.contactCount, 1);
  EXPECT_NEAR(t.contacts[0].separation, -0.1, tol(1));
  Query later(ball.model, ground.model);  // greeted after the change: no test
  EXPECT_EQ(later.touch, 0);
  EXPECT_EQ(later.r.contactCount, 0);
}

int gHello = 0, gGoodbye = 0;
McdModelID gFirstSeen = nullptr;
void MEAPI UserHello(McdModelPair *p) {
  ++gHello;
  gFirstSeen = p->model1;
  p->m_cachedData = &gHello;
}
void MEAPI UserGoodbye(McdModelPair *p) {
  ++gGoodbye;
  EXPECT_EQ(p->m_cachedData, &gHello);
}
// Cylinder (model1) against box (model2): one made-up contact, normal +x.
int MEAPI UserIntersect(McdModelPair *p, McdIntersectResult *r) {
  EXPECT_EQ(McdGeometryGetTypeId(McdModelGetGeometry(p->model1)), kMcdGeometryTypeCylinder);
  EXPECT_EQ(r->model1, p->model1);
  McdContact &c = r->contacts[0];
  MeVector3Set(c.position, 1, 2, 3);
  MeVector3Set(c.normal, 1, 0, 0);
  c.separation = -1;
  c.dims = (MeI16)(1 | (2 << 8));
  c.element1.tag = 11;
  c.element2.tag = 22;
  r->contactCount = 1;
  MeVector3Set(r->normal, 1, 0, 0);
  r->touch = 1;
  return 1;
}

TEST(McdInteraction, UserInteractionIsMirroredAutomatically) {
  Framework fw(32, 64, 1, false);  // types only: the built-in box-cylinder would take (box, cylinder)
  McdPrimitivesRegisterTypes(fw);
  McdInteractions fns{};
  fns.helloFn = UserHello;
  fns.intersectFn = UserIntersect;
  fns.goodbyeFn = UserGoodbye;
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, &fns);
  Body can(McdCylinderCreate(fw, 1, 1), 0, 0, 0), box(McdBoxCreate(fw, 1, 1, 1), 0, 0, 0);
  gHello = gGoodbye = 0;
  {
    Query t(box.model, can.model);  // the other order
    EXPECT_EQ(gHello, 1);
    EXPECT_EQ(gFirstSeen, can.model);      // hello saw the interaction's order
    EXPECT_EQ(t.pair->model1, box.model);  // but the pair is the caller's again
    ASSERT_EQ(t.r.contactCount, 1);
    EXPECT_EQ(t.contacts[0].normal[0], -1);
    EXPECT_EQ(t.contacts[0].element1.tag, 22);
    EXPECT_EQ(t.contacts[0].element2.tag, 11);
    EXPECT_EQ(t.contacts[0].dims, (MeI16)(2 | (1 << 8)));
    EXPECT_EQ(t.r.normal[0], -1);
  }
  EXPECT_EQ(gGoodbye, 1);
  // Registering the other order explicitly replaces the mirror only.
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder, &fns);
  EXPECT_EQ(McdFrameworkGetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder)->swap, 0);
  // Removing an entry.
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder, nullptr);
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, nullptr);
  EXPECT_EQ(McdFrameworkGetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox), nullptr);
}

// A second user interaction for the cylinder-box entry, with its own data.
int gHelloB = 0, gGoodbyeB = 0;
void MEAPI UserHelloB(McdModelPair *p) {
  ++gHelloB;
  p->m_cachedData = &gHelloB;
}
void MEAPI UserGoodbyeB(McdModelPair *p) {
  ++gGoodbyeB;
  EXPECT_EQ(p->m_cachedData, &gHelloB);
}
int MEAPI UserIntersectB(McdModelPair *p, McdIntersectResult *r) {
  EXPECT_EQ(p->m_cachedData, &gHelloB);
  r->contactCount = 0;
  r->touch = 0;
  return 0;
}

TEST(McdInteraction, AnInteractionReplacedWhileAPairIsLiveServesThatPairToItsGoodbye) {
  Framework fw(32, 64, 1, false);
  McdPrimitivesRegisterTypes(fw);
  McdInteractions a{}, b{};
  a.helloFn = UserHello;
  a.intersectFn = UserIntersect;
  a.goodbyeFn = UserGoodbye;  // checks that the data is its own hello's
  b.helloFn = UserHelloB;
  b.intersectFn = UserIntersectB;
  b.goodbyeFn = UserGoodbyeB;
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, &a);
  Body can(McdCylinderCreate(fw, 1, 1), 0, 0, 0), box(McdBoxCreate(fw, 1, 1, 1), 0, 0, 0);
  gHello = gGoodbye = gHelloB = gGoodbyeB = 0;
  {
    Query first(can.model, box.model);  // greeted with a
    ASSERT_EQ(first.touch, 1);
    McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, &b);
    McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, &b);  // replaced twice
    {
      Query second(can.model, box.model);  // greeted with b
      EXPECT_EQ(second.touch, 0);
      EXPECT_EQ(gHelloB, 1);
    }
    EXPECT_EQ(gGoodbyeB, 1);
    EXPECT_EQ(McdIntersect(first.pair, &first.r), 1);  // a's test, on a's data
    EXPECT_EQ(gGoodbye, 0);
  }
  // The first pair's goodbye was a's, on a's data; b never saw that pair.
  EXPECT_EQ(gHello, 1);
  EXPECT_EQ(gGoodbye, 1);
  EXPECT_EQ(gGoodbyeB, 1);
  // A pair greeted with an entry outlives its removal too.
  Query last(can.model, box.model);  // greeted with b
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeCylinder, kMcdGeometryTypeBox, nullptr);
  EXPECT_EQ(McdIntersect(last.pair, &last.r), 0);  // b's test ran (it checks its data)
}

TEST(McdInteraction, GuideDirectTestWithCallocPair) {
  Framework fw;
  Body ground(McdPlaneCreate(fw), 0, 0, 0);
  Body ball(McdSphereCreate(fw, 1), 0, 0, (MeReal)0.5);
  // The guide's "Testing Collision Directly", verbatim in spirit.
  McdModelPair *pair = (McdModelPair *)calloc(1, sizeof *pair);
  pair->model1 = ball.model;
  pair->model2 = ground.model;
  McdHello(pair);
  ASSERT_TRUE(McdNearby(pair));
  McdIntersectResult result;
  result.pair = pair;
  result.contactMaxCount = 20;
  result.contacts = (McdContact *)calloc(20, sizeof(McdContact));
  EXPECT_TRUE(McdIntersect(pair, &result));
  EXPECT_EQ(result.maxContactCount, 20);  // the guide's other name
  EXPECT_EQ(result.contactCount, 1);
  free(result.contacts);
  McdGoodbye(pair);
  free(pair);
}

TEST(McdInteraction, RandomPosesGiveUnitNormalsAndMirroredResults) {
  Framework fw;
  McdGeometryID shapes[2] = {McdSphereCreate(fw, (MeReal)0.7), McdBoxCreate(fw, 1, 2, (MeReal)0.5)};
  TM groundTM;
  const MeVector3 x = {1, 0, 0};
  groundTM.rotate(x, -ME_PI / 2);  // the guide's y-up ground
  McdModelID ground = McdModelCreate(McdPlaneCreate(fw));
  McdModelSetTransformPtr(ground, groundTM);
  McdModelUpdate(ground);
  unsigned seed = 12345;
  auto uniform = [&](double lo, double hi) {
    seed = seed * 1664525u + 1013904223u;
    return (MeReal)(lo + (hi - lo) * (seed >> 8) / 16777216.0);
  };
  int touching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Body b(shapes[trial % 2], uniform(-5, 5), uniform(-1.5, 1.5), uniform(-5, 5));
    const MeVector3 axis = {uniform(-1, 1), uniform(-1, 1), uniform(0.1, 1)};
    b.tm.rotate(axis, uniform(0, 6.28));
    b.update();
    Query f(b.model, ground), r(ground, b.model);
    ASSERT_EQ(f.touch, r.touch);
    ASSERT_EQ(f.r.contactCount, r.r.contactCount);
    touching += f.touch;
    for (int i = 0; i < f.r.contactCount; ++i) {
      const McdContact &c = f.contacts[i], &d = r.contacts[i];
      EXPECT_NEAR(MeVector3Magnitude(c.normal), 1, tol(1));
      EXPECT_TRUE(std::isfinite(c.separation));
      EXPECT_LE(c.separation, McdFrameworkGetContactTolerance(fw));
      EXPECT_NEAR(c.normal[1], 1, tol(1));  // up, from the ground to the shape
      // The separation is the height of the deepest point over y = 0.
      EXPECT_NEAR(c.position[1], c.separation / 2, tol(4, 256));
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(d.normal[k], -c.normal[k]);
        EXPECT_EQ(d.position[k], c.position[k]);
      }
    }
  }
  EXPECT_GT(touching, 40);
  EXPECT_LT(touching, 180);
}

}  // namespace
