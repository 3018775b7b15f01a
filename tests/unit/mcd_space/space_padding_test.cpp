// A space's box of a model is its AABB grown by the framework's contact
// tolerance plus the model's bounds padding (McdModelSetBoundsPadding), so
// models within the tolerance of each other always pair.
#include "space_test_support.h"

#include <limits>

using namespace space_test;

namespace {

// Unit balls 0 and 1 at centre distance 2 + gap: reported after a step?
bool PairedAtGap(MeReal gap, MeReal padding0 = 0, MeReal padding1 = 0) {
  Balls b({0, 2 + gap}, 100, 32, false);
  McdModelSetBoundsPadding(b.models[0], padding0);
  McdModelSetBoundsPadding(b.models[1], padding1);
  for (McdModelID m : b.models) McdSpaceInsertModel(b.space, m);
  return Step(b.space).hello.size() == 1;
}

void MEAPI OwnAabb(McdModelID m, MeVector3 mn, MeVector3 mx) { McdModelGetAABB(m, mn, mx); }

}  // namespace

TEST(McdSpacePadding, ModelsWithinTheContactTolerancePair) {
  Framework fw;
  const MeReal tol = McdFrameworkGetContactTolerance(fw);
  ASSERT_GT(tol, 0);
  EXPECT_TRUE(PairedAtGap(0));
  EXPECT_TRUE(PairedAtGap(tol / 5));
  EXPECT_TRUE(PairedAtGap(tol));
  EXPECT_TRUE(PairedAtGap((MeReal)1.8 * tol)) << "each box grows by the tolerance";
  EXPECT_FALSE(PairedAtGap((MeReal)2.5 * tol));
}

TEST(McdSpacePadding, PaddingGrowsTheBoxOnEverySide) {
  // Gap 1: the two paddings must cover it (less the two tolerances).
  EXPECT_FALSE(PairedAtGap(1, (MeReal)0.4, (MeReal)0.4));
  EXPECT_TRUE(PairedAtGap(1, (MeReal)0.5, (MeReal)0.5));
  EXPECT_TRUE(PairedAtGap(1, 1, 0));
  EXPECT_TRUE(PairedAtGap(1, 0, 1));
  EXPECT_FALSE(PairedAtGap(1, (MeReal)0.99, 0));
}

TEST(McdSpacePadding, TakesEffectAtTheNextUpdateAndCanShrinkAgain) {
  Balls b({0, 3});  // gap 1
  EXPECT_TRUE(Step(b.space).hello.empty());
  McdModelSetBoundsPadding(b.models[0], (MeReal)1.5);
  EXPECT_TRUE(Step(b.space).hello.empty()) << "not before the model is updated";
  McdSpaceUpdateModel(b.models[0]);
  const Events grown = Step(b.space);
  ASSERT_EQ(grown.hello.size(), 1u);
  McdModelSetBoundsPadding(b.models[0], 0);
  McdSpaceUpdateAll(b.space);
  EXPECT_EQ(Step(b.space).goodbye.size(), 1u);
  EXPECT_EQ(McdModelGetBoundsPadding(b.models[0]), 0);
}

TEST(McdSpacePadding, TheAabbFunctionsBoxIsPaddedToo) {
  Balls b({0, 3});
  McdSpaceEndChanges(b.space);
  McdSpaceSetAABBFn(b.space, OwnAabb);
  McdSpaceBeginChanges(b.space);
  McdModelSetBoundsPadding(b.models[1], (MeReal)1.01);
  McdSpaceUpdateAll(b.space);
  EXPECT_EQ(Step(b.space).hello.size(), 1u);
}

TEST(McdSpacePadding, BadPaddingWarnsAndKeepsTheOldOne) {
  WarningCapture w;
  Balls b({0});
  McdModelSetBoundsPadding(b.models[0], (MeReal)0.25);
  McdModelSetBoundsPadding(b.models[0], -1);
  EXPECT_TRUE(w.lastMentions("McdModelSetBoundsPadding"));
  McdModelSetBoundsPadding(b.models[0], std::numeric_limits<MeReal>::infinity());
  EXPECT_TRUE(w.lastMentions("McdModelSetBoundsPadding"));
  EXPECT_EQ(McdModelGetBoundsPadding(b.models[0]), (MeReal)0.25);
}
