// Validity tables, disabled pairs, culling tables, freezing and the
// frozen-pair policy, the AABB function, bad input.
#include "space_test_support.h"

using namespace space_test;

TEST(McdSpaceModes, WrongModeCallsWarnAndDoNothing) {
  WarningCapture w;
  Balls b({0, 1});
  EXPECT_EQ(McdSpaceIsChanging(b.space), 1);  // a new space is inside a block
  McdModelPairContainer *c = McdModelPairContainerCreate(4);
  McdSpacePairIterator it{};
  EXPECT_EQ(McdSpaceGetPairs(b.space, &it, c), 0);
  EXPECT_TRUE(w.lastMentions("McdSpaceGetPairs"));
  McdSpaceBeginChanges(b.space);
  EXPECT_TRUE(w.lastMentions("McdSpaceBeginChanges"));
  McdSpaceSetAABBFn(b.space, nullptr);
  EXPECT_TRUE(w.lastMentions("McdSpaceSetAABBFn"));

  McdSpaceUpdateAll(b.space);
  McdSpaceEndChanges(b.space);
  EXPECT_EQ(McdSpaceIsChanging(b.space), 0);
  w.clear();
  McdModelID extra = b.add(10, false);
  EXPECT_EQ(McdSpaceInsertModel(b.space, extra), 0);
  EXPECT_TRUE(w.lastMentions("McdSpaceInsertModel"));
  EXPECT_EQ(McdModelGetSpace(extra), nullptr);
  EXPECT_EQ(McdSpaceRemoveModel(b.models[0]), 0);  // removing outside a block
  EXPECT_TRUE(w.lastMentions("McdSpaceRemoveModel"));
  EXPECT_EQ(McdModelGetSpace(b.models[0]), b.space);
  McdSpaceUpdateModel(b.models[0]);
  EXPECT_TRUE(w.lastMentions("McdSpaceUpdateModel"));
  EXPECT_EQ(McdSpaceDisablePair(b.models[0], b.models[1]), 0);
  EXPECT_TRUE(w.lastMentions("McdSpaceDisablePair"));
  McdSpaceEndChanges(b.space);
  EXPECT_TRUE(w.lastMentions("McdSpaceEndChanges"));
  const size_t before = w.count();
  // Valid anywhere: no warnings.
  EXPECT_EQ(McdSpaceFreezeModel(extra), 0);  // (not in a space: warns)
  EXPECT_EQ(w.count(), before + 1);
  EXPECT_EQ(McdSpacePairIsEnabled(b.models[0], b.models[1]), 1);
  EXPECT_EQ(McdSpaceGetModelCount(b.space), 2);
  EXPECT_EQ(McdSpaceFreezeModel(b.models[0]), 1);
  EXPECT_EQ(McdSpaceModelIsFrozen(b.models[0]), 1);
  EXPECT_EQ(McdSpaceUnfreezeModel(b.models[0]), 1);
  EXPECT_EQ(w.count(), before + 1);
  // The pair events are still readable after all those ignored calls.
  McdSpacePairIteratorBegin(b.space, &it);
  McdModelPairContainerReset(c);
  EXPECT_EQ(McdSpaceGetPairs(b.space, &it, c), 0);
  EXPECT_EQ(c->helloEnd - c->helloFirst, 1);
  McdModelPairContainerDestroy(c);
  McdSpaceBeginChanges(b.space);
}

TEST(McdSpaceModes, ModelInTwoSpacesIsRefused) {
  WarningCapture w;
  Balls b({0});
  McdSpaceID other = McdSpaceAxisSortCreate(b.fw, McdXAxis | McdZAxis, 4, 4);
  EXPECT_EQ(McdSpaceInsertModel(other, b.models[0]), 0);
  EXPECT_TRUE(w.lastMentions("one space only"));
  EXPECT_EQ(McdSpaceInsertModel(b.space, b.models[0]), 0);
  EXPECT_EQ(McdModelGetSpace(b.models[0]), b.space);
  EXPECT_EQ(McdSpaceGetModelCount(other), 0);
  McdSpaceDestroy(other);
}

TEST(McdSpaceModes, BadInput) {
  WarningCapture w;
  Framework fw;
  EXPECT_EQ(McdSpaceAxisSortCreate(nullptr, McdAllAxes, 4, 4), nullptr);
  EXPECT_EQ(McdSpaceAxisSortCreate(fw, 0, 4, 4), nullptr);
  EXPECT_EQ(McdSpaceAxisSortCreate(fw, 8, 4, 4), nullptr);
  EXPECT_EQ(McdSpaceAxisSortCreate(fw, McdAllAxes, 0, 4), nullptr);
  EXPECT_EQ(McdSpaceAxisSortCreate(fw, McdAllAxes, 4, -1), nullptr);
  EXPECT_EQ(w.count(), 5u);
  EXPECT_EQ(McdSpaceInsertModel(nullptr, nullptr), 0);
  EXPECT_EQ(McdSpaceRemoveModel(nullptr), 0);
  McdSpaceUpdateModel(nullptr);
  McdSpaceUpdateAll(nullptr);
  EXPECT_EQ(McdSpaceGetModelCount(nullptr), 0);
  EXPECT_EQ(McdSpaceModelIsFrozen(nullptr), 0);
  EXPECT_EQ(McdCullingTableCreate(0), nullptr);
  McdSpaceDestroy(nullptr);
  EXPECT_GE(w.count(), 11u);
}

TEST(McdSpaceFilters, DisableSaysGoodbyeEnableSaysHelloAgain) {
  Balls b({0, 1});
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *first = e.hello[0];
  EXPECT_EQ(McdSpaceDisablePair(b.models[1], b.models[0]), 1);
  EXPECT_EQ(McdSpacePairIsEnabled(b.models[0], b.models[1]), 0);
  e = Step(b.space);
  ASSERT_EQ(e.goodbye.size(), 1u);
  EXPECT_EQ(e.goodbye[0], first);
  e = Step(b.space);
  EXPECT_TRUE(e.hello.empty() && e.staying.empty() && e.goodbye.empty());
  EXPECT_EQ(McdSpaceEnablePair(b.models[0], b.models[1]), 1);
  e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 1u);
}

TEST(McdSpaceFilters, CullingTableActsAsDisabledPairs) {
  Balls b({}, 100);
  McdCullingTable *t = McdCullingTableCreate(4);
  EXPECT_EQ(McdCullingTableSet(t, 0, 1, 1), t);
  McdModelID a = b.add(0, false), c = b.add(1, false), d = b.add(2, false);
  EXPECT_EQ(McdSpaceInsertModelWithCulling(b.space, a, t, 0, 7), 1);
  EXPECT_EQ(McdSpaceInsertModelWithCulling(b.space, c, t, 1, 7), 1);
  EXPECT_EQ(McdSpaceInsertModelWithCulling(b.space, d, t, 1, 8), 1);  // other culling ID
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 2u);  // a-d (touching) and c-d; a-c culled
  EXPECT_EQ(McdSpacePairIsEnabled(a, c), 0);
  EXPECT_EQ(McdSpacePairIsEnabled(c, d), 1);
  McdSpaceSetModelCullingParameters(b.space, c, nullptr, 0, 0);  // uncull
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 1u);
  EXPECT_EQ(e.staying.size(), 2u);
  McdSpaceDestroy(b.space);
  b.space = nullptr;
  McdCullingTableDestroy(t);
}

TEST(McdSpaceFreeze, FrozenModelsKeepTheirPairAndAreNotUpdated) {
  Balls b({0, 1});
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *pair = e.hello[0];
  McdSpaceFreezeModel(b.models[0]);
  McdSpaceFreezeModel(b.models[1]);
  b.move(1, 50);  // frozen: UpdateAll leaves its AABB where it was
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.staying.size(), 1u);  // the keep-frozen-pairs policy
  EXPECT_EQ(e.staying[0], pair);
  MeVector3 mn, mx;
  McdModelGetAABB(b.models[1], mn, mx);
  EXPECT_FLOAT_EQ(mn[0], 0);

  McdSpaceSetKeepFrozenPairs(b.space, 0);  // the guide's plain rule
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.goodbye.size(), 1u);
  EXPECT_EQ(e.goodbye[0], pair);
  // Two frozen models never start a pair, whatever the policy.
  McdSpaceSetKeepFrozenPairs(b.space, 1);
  McdModelID c = b.add(0.5f);
  McdSpaceUpdateModel(c);
  McdSpaceFreezeModel(c);
  e = Step(b.space);
  EXPECT_TRUE(e.hello.empty());
  // Unfreezing brings the pairs back (model 1 is still at its old box).
  McdSpaceUnfreezeModel(b.models[0]);
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 2u);
}

TEST(McdSpaceFreeze, UpdatingAFrozenModelWarns) {
  WarningCapture w;
  Balls b({0});
  McdSpaceFreezeModel(b.models[0]);
  McdSpaceUpdateModel(b.models[0]);
  EXPECT_TRUE(w.lastMentions("frozen"));
}

namespace {
void MEAPI FatBox(McdModelID m, MeVector3 mn, MeVector3 mx) {
  McdModelGetAABB(m, mn, mx);
  for (int k = 0; k < 3; ++k) {
    mn[k] -= 1;
    mx[k] += 1;
  }
}
}  // namespace

TEST(McdSpaceFilters, AabbFunctionWidensTheBoxes) {
  Balls b({0, 3.5f});
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space, 8, false, true);
  EXPECT_TRUE(e.hello.empty());
  McdSpaceSetAABBFn(b.space, FatBox);
  McdSpaceBeginChanges(b.space);
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  EXPECT_EQ(e.hello.size(), 1u);
}
