// The pair life cycle through the public McdSpace API: the guide's loop,
// pair identity from hello to goodbye, removal and GetTransitions, overflow.
#include "space_test_support.h"

#include <set>

using namespace space_test;

TEST(McdSpaceLifecycle, HelloStayingGoodbyeKeepOnePairObject) {
  Balls b({0, 5});
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  EXPECT_TRUE(e.hello.empty() && e.staying.empty() && e.goodbye.empty());

  b.move(1, 1.5);  // overlapping now
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *pair = e.hello[0];
  EXPECT_EQ(pair->model1, b.models[0]);  // inserted first
  EXPECT_EQ(pair->model2, b.models[1]);
  EXPECT_EQ(pair->userData, nullptr);
  EXPECT_EQ(pair->responseData, nullptr);

  for (int k = 0; k < 3; ++k) {
    b.move(1, (MeReal)(1.4 - 0.1 * k));
    McdSpaceUpdateAll(b.space);
    e = Step(b.space);
    ASSERT_EQ(e.staying.size(), 1u);
    EXPECT_EQ(e.staying[0], pair);
    EXPECT_TRUE(e.hello.empty());
  }
  b.move(1, 3);  // apart
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.goodbye.size(), 1u);
  EXPECT_EQ(e.goodbye[0], pair);
  EXPECT_EQ(e.goodbye[0]->model1, b.models[0]);
  e = Step(b.space);
  EXPECT_TRUE(e.goodbye.empty() && e.hello.empty() && e.staying.empty());
}

TEST(McdSpaceLifecycle, GuideLoopWithHelloAndIntersect) {
  Balls b({0, (MeReal)1.9});
  McdSpaceUpdateAll(b.space);
  McdSpaceEndChanges(b.space);
  McdModelPairContainer *pairs = McdModelPairContainerCreate(8);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(b.space, &it);
  int touching = 0, overflow;
  do {
    McdModelPairContainerReset(pairs);
    overflow = McdSpaceGetPairs(b.space, &it, pairs);
    McdGoodbyeEach(pairs);
    McdHelloEach(pairs);
    for (int i = pairs->helloFirst; i < pairs->stayingEnd; ++i) {
      McdContact contacts[4];
      McdIntersectResult r{};
      r.contacts = contacts;
      r.contactMaxCount = 4;
      if (McdIntersect(pairs->array[i], &r)) {
        ++touching;
        EXPECT_NEAR((double)contacts[0].separation, -0.1, 1e-5);
      }
    }
  } while (overflow);
  McdSpaceBeginChanges(b.space);
  EXPECT_EQ(touching, 1);
  McdModelPairContainerDestroy(pairs);
}

TEST(McdSpaceLifecycle, RemovedModelsPairsBecomeGoodbyesInTransitions) {
  Balls b({0, 1, 2});  // pairs 0-1, 1-2, 0-2 (touching at 2)
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 3u);
  std::set<McdModelPair *> withMiddle;
  for (McdModelPair *p : e.hello)
    if (p->model1 == b.models[1] || p->model2 == b.models[1]) withMiddle.insert(p);
  ASSERT_EQ(withMiddle.size(), 2u);

  EXPECT_EQ(McdSpaceRemoveModel(b.models[1]), 1);
  EXPECT_EQ(McdModelGetSpace(b.models[1]), nullptr);
  EXPECT_EQ(McdSpaceGetModelCount(b.space), 2);
  e = Step(b.space, 64, /*transitions=*/true, /*stayOutside=*/true);
  EXPECT_TRUE(e.staying.empty());  // transitions only: the 0-2 pair is left out
  EXPECT_TRUE(e.hello.empty());
  EXPECT_EQ(std::set<McdModelPair *>(e.goodbye.begin(), e.goodbye.end()), withMiddle);
  for (McdModelPair *p : e.goodbye)  // the removed model is still readable
    EXPECT_TRUE(p->model1 == b.models[1] || p->model2 == b.models[1]);
  // The same events, all of them, through GetPairs: the 0-2 pair stays.
  McdModelPairContainer *c = McdModelPairContainerCreate(8);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(b.space, &it);
  EXPECT_EQ(McdSpaceGetPairs(b.space, &it, c), 0);
  EXPECT_EQ(c->goodbyeEnd - c->goodbyeFirst, 2);
  EXPECT_EQ(c->stayingEnd - c->stayingFirst, 1);
  McdModelPairContainerDestroy(c);
  McdSpaceBeginChanges(b.space);
  // The removed model can go into a space again.
  EXPECT_EQ(McdSpaceInsertModel(b.space, b.models[1]), 1);
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 2u);
}

TEST(McdSpaceLifecycle, OverflowDeliversEveryPairInChunks) {
  Balls b({0, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f});  // 15 pairs
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space, 4);
  EXPECT_EQ(e.hello.size(), 15u);
  EXPECT_EQ(e.calls, 4);  // 4 + 4 + 4 + 3
  std::set<McdModelPair *> all(e.hello.begin(), e.hello.end());
  EXPECT_EQ(all.size(), 15u);
  McdSpaceUpdateAll(b.space);
  e = Step(b.space, 4);
  EXPECT_EQ(std::set<McdModelPair *>(e.staying.begin(), e.staying.end()), all);
  // A chunk of one still makes progress.
  McdSpaceUpdateAll(b.space);
  e = Step(b.space, 1);
  EXPECT_EQ(e.staying.size(), 15u);
  EXPECT_EQ(e.calls, 15);
}

TEST(McdSpaceLifecycle, PairCountExceededGrowsAndWarnsOnce) {
  WarningCapture w;
  Balls b({0, 0.1f, 0.2f}, /*pairCount=*/2);
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 3u);  // every overlapping pair, not pairCount of them
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("McdSpaceEndChanges"));
  e = Step(b.space);
  EXPECT_EQ(e.staying.size(), 3u);
  EXPECT_EQ(w.count(), 1u);
}

TEST(McdSpaceLifecycle, ModelIteratorCountAndUserData) {
  Balls b({0, 3, 6});
  EXPECT_EQ(McdSpaceGetModelCount(b.space), 3);
  McdSpaceModelIterator it;
  McdSpaceModelIteratorBegin(b.space, &it);
  std::set<McdModelID> seen;
  McdModelID m;
  while (McdSpaceGetModel(b.space, &it, &m)) seen.insert(m);
  EXPECT_EQ(seen, std::set<McdModelID>(b.models.begin(), b.models.end()));
  EXPECT_EQ(m, nullptr);
  int data = 7;
  McdSpaceSetUserData(b.space, &data);
  EXPECT_EQ(McdSpaceGetUserData(b.space), &data);
  EXPECT_EQ(McdSpaceGetFramework(b.space), b.fw.id);
}
