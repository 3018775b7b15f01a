// MstUniverseStep pads each model's space box by the contact tolerance and
// by how far its body can move in the step (engine/mst/step_bounds.cpp), so
// models within the tolerance get a pair and a contact in the same step, and
// a fast body is paired with what it is about to reach before it gets there.
// Each model also inherits its body's sort key.
#include "mst_test_support.h"

#include <cmath>
#include <vector>

using namespace mst_test;

namespace {

// What the bridge's McdIntersect calls saw in one step (default material).
struct IntersectLog {
  int pairs = 0;     // calls with at least one contact
  int contacts = 0;  // their contacts
};
IntersectLog g_log;

MeBool MEAPI LogIntersect(McdIntersectResult *r) {
  ++g_log.pairs;
  g_log.contacts += r->contactCount;
  return 1;
}

// The pairs the space reported in the last step: the step leaves the space
// inside a change block; closing it with no change reports every pair of
// the step as staying (no hellos, no goodbyes), then it is reopened.
std::vector<McdModelPair *> PairsOfLastStep(McdSpaceID space) {
  std::vector<McdModelPair *> out;
  McdSpaceEndChanges(space);
  McdModelPairContainer *c = McdModelPairContainerCreate(64);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(space, &it);
  int more;
  do {
    McdModelPairContainerReset(c);
    more = McdSpaceGetPairs(space, &it, c);
    EXPECT_EQ(c->goodbyeEnd - c->goodbyeFirst, 0);
    EXPECT_EQ(c->helloEnd - c->helloFirst, 0);
    for (int i = c->stayingFirst; i < c->stayingEnd; ++i) out.push_back(c->array[i]);
  } while (more);
  McdModelPairContainerDestroy(c);
  McdSpaceBeginChanges(space);
  return out;
}

bool Paired(McdSpaceID space, McdModelID a, McdModelID b) {
  for (McdModelPair *p : PairsOfLastStep(space))
    if ((p->model1 == a && p->model2 == b) || (p->model1 == b && p->model2 == a)) return true;
  return false;
}

// A 1 m fixed box centred at the origin and a 1 m box with a body resting
// `gap` above it, no gravity: the contacts of one universe step, and what
// McdIntersect says of the same two models directly.
struct GapResult {
  IntersectLog step;
  int groupContacts = -1;
  int direct = -1;
};

GapResult TwoBoxesAtGap(MeReal gap) {
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  MstBridgeSetIntersectCB(s.u->bridge, 0, 0, LogIntersect);
  MeMatrix4 lowerTM;
  MeMatrix4TMMakeIdentity(lowerTM);
  McdModelID lower = MstFixedModelCreate(s.u, McdBoxCreate(s.u->frame, 1, 1, 1), lowerTM);
  McdModelID upper = MstModelAndBodyCreate(s.u, McdBoxCreate(s.u->frame, 1, 1, 1), 1);
  MdtBodySetPosition(McdModelGetBody(upper), 0, 0, 1 + gap);
  g_log = {};
  s.step();
  GapResult out;
  out.step = g_log;
  for (McdModelPair *p : PairsOfLastStep(s.u->space)) {
    if (p->responseData) out.groupContacts = MdtContactGroupGetCount(static_cast<MdtContactGroupID>(p->responseData));
  }
  // The same models, directly (at the poses they had when the step
  // collided them: the upper box has not moved, it had no velocity).
  McdModelUpdate(upper);
  McdModelPair *pair = McdModelPairCreate(lower, upper);
  McdHello(pair);
  McdContact contacts[16];
  McdIntersectResult r{};
  r.contacts = contacts;
  r.contactMaxCount = 16;
  McdIntersect(pair, &r);
  out.direct = r.contactCount;
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  return out;
}

}  // namespace

TEST(MstSpeculativePairs, BoxesWithinTheToleranceTouchInTheFirstStep) {
  for (MeReal gap : {(MeReal)0, (MeReal)2e-6, (MeReal)5e-6}) {
    const GapResult r = TwoBoxesAtGap(gap);
    std::printf(
        "[ figures  ] gap %g m: step pairs with contacts %d, contacts %d, group contacts "
        "%d; McdIntersect directly: %d contacts\n",
        (double)gap, r.step.pairs, r.step.contacts, r.groupContacts, r.direct);
    EXPECT_EQ(r.step.pairs, 1) << "gap " << gap;
    EXPECT_EQ(r.step.contacts, 4) << "gap " << gap << ": a face-face touch";
    EXPECT_EQ(r.groupContacts, 4) << "gap " << gap;
    EXPECT_EQ(r.direct, r.step.contacts) << "gap " << gap << ": the step agrees with McdIntersect";
  }
}

TEST(MstSpeculativePairs, BeyondTheToleranceNoContact) {
  // 3 tolerances apart: the boxes may pair, the nearfield reports nothing.
  const GapResult r = TwoBoxesAtGap((MeReal)3e-5);
  EXPECT_EQ(r.step.contacts, 0);
  EXPECT_EQ(r.direct, 0);
}

TEST(MstSpeculativePairs, FastBallIsPairedWithTheWallTheStepBeforeReachingIt) {
  // A ball of radius 2.5 cm at 100 m/s along +x toward a 10 cm wall whose
  // face is at x = 2.5; h = 1/60 s, so 1.667 m per step, no gravity. Step
  // 1 starts 2.475 m from the face (not reachable: no pair); step 2
  // starts 0.808 m from it and would end past the wall: paired.
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  const MeReal h = (MeReal)1 / 60;
  MeMatrix4 wallTM;
  MeMatrix4TMMakeIdentity(wallTM);
  MeMatrix4TMSetPosition(wallTM, (MeReal)2.55, 0, 0);
  McdModelID wall = MstFixedModelCreate(s.u, McdBoxCreate(s.u->frame, (MeReal)0.1, 1, 1), wallTM);
  McdModelID ball = MstModelAndBodyCreate(s.u, McdSphereCreate(s.u->frame, (MeReal)0.025), 1);
  MdtBodyID body = McdModelGetBody(ball);
  MdtBodySetLinearVelocity(body, 100, 0, 0);
  MstUniverseStep(s.u, h);
  EXPECT_NEAR(McdModelGetBoundsPadding(ball), 100 * h, 1e-5) << "h |v|";
  EXPECT_EQ(McdModelGetBoundsPadding(wall), 0);
  EXPECT_FALSE(Paired(s.u->space, ball, wall)) << "step 1: the wall is out of reach";
  MeVector3 p;
  MdtBodyGetPosition(body, p);
  ASSERT_LT(p[0] + (MeReal)0.025, (MeReal)2.5) << "the ball has not reached the wall yet";
  ASSERT_GT(p[0] + 100 * h, (MeReal)2.6) << "and would pass it in the next step";
  MstUniverseStep(s.u, h);
  EXPECT_TRUE(Paired(s.u->space, ball, wall)) << "step 2: paired before reaching the wall";
}

TEST(MstSpeculativePairs, PaddingBoundsTheMotionAndIsCapped) {
  Scene s(false);  // gravity kG
  McdModelID ball = s.ball((MeReal)0.5, 0, 0, 10);
  MdtBodyID body = McdModelGetBody(ball);
  // At rest: gravity alone, h^2 |g|.
  s.step();
  EXPECT_NEAR(McdModelGetBoundsPadding(ball), kH * kH * kG, 1e-6);
  // Spinning: + h |w| r, r >= the ball's radius about its centre (its
  // AABB's half diagonal, sqrt(3) r).
  MdtBodySetLinearVelocity(body, 0, 0, 0);
  MdtBodySetAngularVelocity(body, 0, 0, 10);
  s.step();
  const MeReal spin = McdModelGetBoundsPadding(ball) - kH * kH * kG;
  EXPECT_GE(spin, kH * 10 * (MeReal)0.5);
  EXPECT_LE(spin, kH * 10 * (MeReal)0.5 * (MeReal)1.8);
  // Very fast: capped at twice max(radius, length scale 1).
  MdtBodySetAngularVelocity(body, 0, 0, 0);
  MdtBodySetLinearVelocity(body, 1e4, 0, 0);
  s.step();
  EXPECT_NEAR(McdModelGetBoundsPadding(ball), 2, 1e-5);
  // Asleep: tolerance only.
  MdtBodySetLinearVelocity(body, 0, 0, 0);
  MdtBodyDisable(body);
  s.step();
  EXPECT_EQ(McdModelGetBoundsPadding(ball), 0);
}

TEST(MstSpeculativePairs, ModelsInheritTheirBodysSortKeyUnlessTheirOwnIsSet) {
  Scene s;
  McdModelID a = s.ball((MeReal)0.5, 0, 0, (MeReal)0.5);
  McdModelID b = s.ball((MeReal)0.5, (MeReal)0.9, 0, (MeReal)0.5);
  MdtBodySetSortKey(McdModelGetBody(a), 20);
  MdtBodySetSortKey(McdModelGetBody(b), 10);
  McdModelSetSortKey(s.ground, 30);
  s.step();
  EXPECT_EQ(McdModelGetInheritedSortKey(a), 20);
  EXPECT_EQ(McdModelGetInheritedSortKey(b), 10);
  EXPECT_EQ(McdModelGetSortKey(a), 0) << "the model's own key is not written";
  // The pairs in key order: (b, a) [10, 20], (b, ground) [10, 30],
  // (a, ground) [20, 30].
  std::vector<std::pair<McdModelID, McdModelID>> order;
  for (McdModelPair *p : PairsOfLastStep(s.u->space)) order.emplace_back(p->model1, p->model2);
  EXPECT_EQ(order, (std::vector<std::pair<McdModelID, McdModelID>>{{b, a}, {b, s.ground}, {a, s.ground}}));
  // An own key wins: a now ranks first.
  McdModelSetSortKey(a, 1);
  s.step();
  order.clear();
  for (McdModelPair *p : PairsOfLastStep(s.u->space)) order.emplace_back(p->model1, p->model2);
  EXPECT_EQ(order, (std::vector<std::pair<McdModelID, McdModelID>>{{a, b}, {a, s.ground}, {b, s.ground}}));
}
