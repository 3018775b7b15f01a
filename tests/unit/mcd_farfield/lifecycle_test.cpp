// The pair life cycle on small hand-made cases: hello, staying, goodbye and
// nothing, with the record's identity; removals; overlaps that begin and end
// inside one change block; batch insertion and Build.
#include "lifecycle_checker.h"

#include <gtest/gtest.h>

namespace karma::mcd::test {
namespace {

struct TwoBoxes : ::testing::Test {
  void SetUp() override {
    space = AxisSortSpace::Create(kAllAxes, 8, 8);
    ASSERT_NE(space, nullptr);
    MeReal min[3], max[3];
    SetBox(min, max, 0, 0, 0, 1, 1, 1);
    a = space->Insert(&userA, min, max);
    SetBox(min, max, 5, 0, 0, 6, 1, 1);
    b = space->Insert(&userB, min, max);
    space->EndChanges();
  }
  void TearDown() override { AxisSortSpace::Destroy(space); }
  // Moves b so that its x interval starts at x (unit box) and steps.
  Events MoveB(MeReal x) {
    space->BeginChanges();
    MeReal min[3], max[3];
    SetBox(min, max, x, 0, 0, x + 1, 1, 1);
    space->Update(b, min, max);
    space->EndChanges();
    return Collect(*space);
  }
  AxisSortSpace *space = nullptr;
  int userA = 0, userB = 0;
  ProxyId a = kNoProxy, b = kNoProxy;
};

// The guide's two-spheres walk-through: apart, hello, staying, staying,
// goodbye, then nothing; one record throughout.
TEST_F(TwoBoxes, HelloStayingGoodbyeSequence) {
  Events ev = Collect(*space);
  EXPECT_TRUE(ev.hellos.empty() && ev.stayings.empty() && ev.goodbyes.empty());

  ev = MoveB(MeReal(0.5));
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_TRUE(ev.stayings.empty() && ev.goodbyes.empty());
  const PairRecord *pair = ev.hellos[0];
  EXPECT_EQ(pair->state, PairState::Hello);
  EXPECT_EQ(pair->proxyA, a);  // inserted first
  EXPECT_EQ(pair->proxyB, b);
  EXPECT_EQ(pair->userA, &userA);
  EXPECT_EQ(pair->userB, &userB);

  for (MeReal x : {MeReal(0.7), MeReal(1.0)}) {  // 1.0: touching still counts
    ev = MoveB(x);
    ASSERT_EQ(ev.stayings.size(), 1u);
    EXPECT_EQ(ev.stayings[0], pair) << "the same record from hello to goodbye";
    EXPECT_EQ(pair->state, PairState::Staying);
    EXPECT_TRUE(ev.hellos.empty() && ev.goodbyes.empty());
  }

  ev = MoveB(MeReal(1.01));
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0], pair);
  EXPECT_EQ(pair->state, PairState::Goodbye);
  EXPECT_TRUE(ev.hellos.empty() && ev.stayings.empty());

  ev = MoveB(MeReal(3));
  EXPECT_TRUE(ev.hellos.empty() && ev.stayings.empty() && ev.goodbyes.empty());
  EXPECT_EQ(space->Stats().recordsInUse, 0) << "the record went back to the pool after its goodbye";
}

// Goodbye and the next block's hello never share a record while the goodbye
// is visible; the record comes back only after BeginChanges.
TEST_F(TwoBoxes, RecordRecycledOnlyAfterGoodbyeReported) {
  MoveB(MeReal(0.5));
  EXPECT_EQ(space->Stats().recordsInUse, 1);
  Events ev = MoveB(4);
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(space->Stats().recordsInUse, 1) << "the goodbye still holds its record";
  space->BeginChanges();
  EXPECT_EQ(space->Stats().recordsInUse, 0);
  space->EndChanges();
}

TEST_F(TwoBoxes, RemovingAProxySaysGoodbyeWithItsUserPointer) {
  const PairRecord *pair = MoveB(MeReal(0.5)).hellos.at(0);
  space->BeginChanges();
  EXPECT_TRUE(space->Remove(b));
  EXPECT_EQ(space->ProxyCount(), 1);
  space->EndChanges();
  // The guide's GetTransitions use: just the goodbyes of the removal.
  Events ev = Collect(*space, 8, true);
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0], pair);
  EXPECT_EQ(pair->userB, &userB);
  EXPECT_FALSE(space->IsProxy(b) && space->ProxyUser(b) == &userB);
  space->BeginChanges();
  space->EndChanges();
  ev = Collect(*space);
  EXPECT_TRUE(ev.goodbyes.empty() && ev.hellos.empty() && ev.stayings.empty());
}

// Sorting happens at UpdateAll/Build and at EndChanges; an overlap that
// appears and disappears inside one block is never reported.
TEST_F(TwoBoxes, OverlapWithinOneBlockIsNotReported) {
  space->BeginChanges();
  MeReal min[3], max[3];
  SetBox(min, max, MeReal(0.5), 0, 0, MeReal(1.5), 1, 1);
  space->Update(b, min, max);
  space->Build();  // sorted now: the pair overlaps internally
  EXPECT_EQ(space->Stats().overlaps, 1);
  SetBox(min, max, 5, 0, 0, 6, 1, 1);
  space->Update(b, min, max);
  space->EndChanges();
  const Events ev = Collect(*space);
  EXPECT_TRUE(ev.hellos.empty() && ev.stayings.empty() && ev.goodbyes.empty());
  EXPECT_EQ(space->Stats().overlaps, 0);
}

// A staying pair that stops and starts overlapping again inside one block
// stays, with its record.
TEST_F(TwoBoxes, GapWithinOneBlockKeepsThePair) {
  const PairRecord *pair = MoveB(MeReal(0.5)).hellos.at(0);
  space->BeginChanges();
  MeReal min[3], max[3];
  SetBox(min, max, 5, 0, 0, 6, 1, 1);
  space->Update(b, min, max);
  space->Build();
  SetBox(min, max, MeReal(0.6), 0, 0, MeReal(1.6), 1, 1);
  space->Update(b, min, max);
  space->EndChanges();
  const Events ev = Collect(*space);
  ASSERT_EQ(ev.stayings.size(), 1u);
  EXPECT_EQ(ev.stayings[0], pair);
  EXPECT_TRUE(ev.hellos.empty() && ev.goodbyes.empty());
}

TEST(FarfieldLifecycle, InsertAndRemoveInOneBlockLeaveNoTrace) {
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 4, 4);
  MeReal min[3], max[3];
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  const ProxyId a = space->Insert(nullptr, min, max);
  const ProxyId b = space->Insert(nullptr, min, max);
  EXPECT_TRUE(space->Remove(b));
  space->EndChanges();
  Events ev = Collect(*space);
  EXPECT_TRUE(ev.hellos.empty() && ev.goodbyes.empty());
  EXPECT_EQ(space->ProxyCount(), 1);
  EXPECT_EQ(space->NextProxy(kNoProxy), a);
  EXPECT_EQ(space->NextProxy(a), kNoProxy);
  AxisSortSpace::Destroy(space);
}

// A full space can remove and insert in one block (a removed proxy's slot
// waits for the next BeginChanges, the space has spare slots for that).
TEST(FarfieldLifecycle, FullSpaceRemovesAndInsertsInOneBlock) {
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 2, 4);
  MeReal min[3], max[3];
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  const ProxyId a = space->Insert(nullptr, min, max);
  const ProxyId b = space->Insert(nullptr, min, max);
  space->EndChanges();
  const PairRecord *pair = Collect(*space).hellos.at(0);
  space->BeginChanges();
  space->Remove(a);
  const ProxyId c = space->Insert(nullptr, min, max);
  EXPECT_NE(c, kNoProxy);
  EXPECT_NE(c, a);
  space->EndChanges();
  const Events ev = Collect(*space);
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0], pair);
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_NE(ev.hellos[0], pair) << "the goodbye's record is not reused while it is visible";
  EXPECT_EQ(ev.hellos[0]->proxyA, b);
  EXPECT_EQ(ev.hellos[0]->proxyB, c);
  AxisSortSpace::Destroy(space);
}

// Many insertions in one block (the batch merge and sweep) and Build.
TEST(FarfieldLifecycle, BatchInsertionAndBuild) {
  for (bool build : {false, true}) {
    BoxWorld world(300, 15, 9u);
    AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 300, 300 * 300);
    for (int i = 0; i < 150; ++i) InsertBox(*space, world.Box(i));
    if (build) space->Build();
    for (int i = 150; i < 300; ++i) InsertBox(*space, world.Box(i));
    space->EndChanges();
    const Events ev = Collect(*space);
    EXPECT_TRUE(ev.stayings.empty());
    EXPECT_EQ(ReportedKeys(ev), BruteForceReported(*space));
    EXPECT_TRUE(space->Validate());
    EXPECT_GT(ev.hellos.size(), 100u);
    AxisSortSpace::Destroy(space);
  }
}

// Boxes touching at zero, one ending at -0 and the other starting at +0,
// touch (-0 == +0), as in the brute force.
TEST(FarfieldLifecycle, NegativeZeroTouchesPositiveZero) {
  AxisSortSpace *space = AxisSortSpace::Create(kAxisX, 4, 8);
  MeReal min[3], max[3];
  SetBox(min, max, -1, 0, 0, -MeReal(0), 1, 1);
  space->Insert(nullptr, min, max);
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  space->Insert(nullptr, min, max);
  space->EndChanges();
  EXPECT_EQ(Collect(*space).hellos.size(), 1u);
  EXPECT_EQ(BruteForceReported(*space).size(), 1u);
  EXPECT_TRUE(space->Validate());
  AxisSortSpace::Destroy(space);
}

// Infinite AABBs (a plane) sort and pair like any other.
TEST(FarfieldLifecycle, InfiniteBoxes) {
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 4, 8);
  const MeReal inf = ME_REAL_MAX * 2;  // +infinity
  MeReal min[3], max[3];
  SetBox(min, max, -inf, -inf, -inf, inf, inf, 0);
  const ProxyId plane = space->Insert(nullptr, min, max);
  space->Freeze(plane);
  SetBox(min, max, 0, 0, MeReal(-0.5), 1, 1, MeReal(0.5));
  space->Insert(nullptr, min, max);
  SetBox(min, max, 0, 0, 2, 1, 1, 3);
  space->Insert(nullptr, min, max);
  space->EndChanges();
  const Events ev = Collect(*space);
  EXPECT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ReportedKeys(ev), BruteForceReported(*space));
  AxisSortSpace::Destroy(space);
}

}  // namespace
}  // namespace karma::mcd::test
