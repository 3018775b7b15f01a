// Chunked pair retrieval: goodbyes first, then hellos and stayings sharing
// the rest; "overflow, call again"; the transitions-only variant; the
// pairCount limit and its once-per-step warning; stale iterators.
#include "lifecycle_checker.h"

#include <gtest/gtest.h>

namespace karma::mcd::test {
namespace {

// Twelve unit boxes in a row, neighbours overlapping: 11 pairs.
struct Row : ::testing::Test {
  void SetUp() override {
    space = AxisSortSpace::Create(kAllAxes, 16, 64);
    for (int i = 0; i < 12; ++i) {
      MeReal min[3], max[3];
      SetBox(min, max, MeReal(i) * MeReal(0.8), 0, 0, MeReal(i) * MeReal(0.8) + 1, 1, 1);
      id[i] = space->Insert(nullptr, min, max);
    }
    space->EndChanges();
  }
  void TearDown() override { AxisSortSpace::Destroy(space); }
  // Lifts boxes 0..4 to z = 10 at x = 0, 20, 0.5, 20.5, 40: goodbyes 0-1,
  // 1-2, 2-3, 3-4, 4-5; hellos 0-2, 1-3; stayings 5-6 ... 10-11.
  void Lift() {
    space->BeginChanges();
    const MeReal x[5] = {0, 20, MeReal(0.5), MeReal(20.5), 40};
    for (int i = 0; i < 5; ++i) {
      MeReal min[3], max[3];
      SetBox(min, max, x[i], 0, 10, x[i] + 1, 1, 11);
      space->Update(id[i], min, max);
    }
    space->EndChanges();
  }
  AxisSortSpace *space = nullptr;
  ProxyId id[12] = {};
};

TEST_F(Row, ChunksGiveGoodbyesFirstThenHellosAndStayings) {
  EXPECT_EQ(Collect(*space).hellos.size(), 11u);
  Lift();
  ASSERT_EQ(space->Goodbyes().size(), 5u);
  ASSERT_EQ(space->Hellos().size(), 2u);
  ASSERT_EQ(space->Stayings().size(), 6u);

  const PairRecord *storage[4];
  PairIterator it;
  space->PairIteratorBegin(&it);
  std::vector<const PairRecord *> g, h, s;
  std::vector<bool> more;
  bool sawHelloOrStaying = false;
  for (int call = 0; call < 10; ++call) {
    PairChunk chunk;
    chunk.array = storage;
    chunk.size = 4;
    more.push_back(space->GetPairs(&it, &chunk));
    EXPECT_LE(chunk.stayingEnd, 4);
    if (chunk.goodbyeEnd > 0) {
      EXPECT_FALSE(sawHelloOrStaying) << "a goodbye after hellos or stayings";
    }
    for (int i = 0; i < chunk.goodbyeEnd; ++i) g.push_back(storage[i]);
    for (int i = chunk.helloFirst; i < chunk.helloEnd; ++i) h.push_back(storage[i]);
    for (int i = chunk.helloEnd; i < chunk.stayingEnd; ++i) s.push_back(storage[i]);
    if (chunk.stayingEnd > chunk.helloFirst) sawHelloOrStaying = true;
    if (call == 0) {
      EXPECT_EQ(chunk.goodbyeEnd, 4);  // a full chunk of goodbyes
      EXPECT_EQ(chunk.stayingEnd, 4);
    }
    if (call == 1) {  // the last goodbye, then hellos and stayings share 3
      EXPECT_EQ(chunk.goodbyeEnd, 1);
      EXPECT_EQ(chunk.helloEnd - chunk.helloFirst, 2);
      EXPECT_EQ(chunk.stayingEnd - chunk.helloEnd, 1);
    }
    if (!more.back()) break;
  }
  // 13 events in chunks of 4: four calls, "call again" on the first three.
  EXPECT_EQ(more, (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(g, std::vector<const PairRecord *>(space->Goodbyes().begin(), space->Goodbyes().end()));
  EXPECT_EQ(h, std::vector<const PairRecord *>(space->Hellos().begin(), space->Hellos().end()));
  EXPECT_EQ(s, std::vector<const PairRecord *>(space->Stayings().begin(), space->Stayings().end()));
}

TEST_F(Row, ChunkOfOneStillProgresses) {
  Collect(*space);
  Lift();
  const Events ev = Collect(*space, 1);
  EXPECT_EQ(ev.calls, 13);
  EXPECT_EQ(ev.goodbyes.size(), 5u);
  EXPECT_EQ(ev.hellos.size(), 2u);
  EXPECT_EQ(ev.stayings.size(), 6u);
  const Events big = Collect(*space, 100);
  EXPECT_EQ(big.calls, 1);
  EXPECT_EQ(Keys(big.goodbyes), Keys(ev.goodbyes));
  EXPECT_EQ(Keys(big.hellos), Keys(ev.hellos));
  EXPECT_EQ(Keys(big.stayings), Keys(ev.stayings));
}

TEST_F(Row, TransitionsOnlyLeaveOutStayings) {
  Collect(*space);
  Lift();
  for (int size : {1, 3, 64}) {
    const Events ev = Collect(*space, size, true);
    EXPECT_EQ(ev.goodbyes.size(), 5u);
    EXPECT_EQ(ev.hellos.size(), 2u);
    EXPECT_TRUE(ev.stayings.empty());
  }
}

TEST_F(Row, StaleIteratorWarnsAndGivesNothing) {
  PairIterator old;
  space->PairIteratorBegin(&old);
  space->BeginChanges();
  space->EndChanges();
  WarningCapture warnings;
  const PairRecord *storage[8];
  PairChunk chunk;
  chunk.array = storage;
  chunk.size = 8;
  EXPECT_FALSE(space->GetPairs(&old, &chunk));
  EXPECT_EQ(chunk.stayingEnd, 0);
  EXPECT_EQ(warnings.CountContaining("McdSpaceGetPairs"), 1);
  chunk.size = 0;
  PairIterator fresh;
  space->PairIteratorBegin(&fresh);
  EXPECT_FALSE(space->GetPairs(&fresh, &chunk));
  EXPECT_EQ(warnings.Count(), 2);
}

// pairCount 5, twelve boxes on one spot (66 overlapping pairs): the pair
// records grow (issue 15: a full pool grows and says so once), every pair
// is reported, the records keep their addresses, and the growth is
// reported once however often it happens.
TEST(FarfieldPairCount, ExceedingPairCountGrowsTheRecordsAndWarnsOnce) {
  WarningCapture warnings;
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 12, 5);
  ProxyId id[12];
  MeReal min[3], max[3];
  for (int i = 0; i < 12; ++i) {
    SetBox(min, max, MeReal(10 * i), 0, 0, MeReal(10 * i + 1), 1, 1);
    id[i] = space->Insert(nullptr, min, max);
  }
  space->EndChanges();
  LifecycleChecker checker;
  Events ev = Collect(*space);
  checker.Step(ev);
  EXPECT_TRUE(ev.hellos.empty());
  // Boxes 0..3 onto one spot: 6 pairs, one more than pairCount.
  space->BeginChanges();
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  for (int i = 1; i < 4; ++i) space->Update(id[i], min, max);
  space->EndChanges();
  EXPECT_EQ(warnings.Count(), 1);
  EXPECT_EQ(warnings.CountContaining("McdSpaceEndChanges"), 1);
  EXPECT_EQ(warnings.CountContaining("pairCount (5)"), 1);
  ev = Collect(*space);
  checker.Step(ev);
  ASSERT_EQ(ev.hellos.size(), 6u);
  EXPECT_EQ(space->Stats().pairRecords, 21);  // 5 grown by 16
  const PairRecord *first = ev.hellos[0];
  const std::uint64_t firstPair = first->SerialPair();
  // All twelve on the spot: 66 pairs, the records grow again, no warning.
  space->BeginChanges();
  for (int i = 4; i < 12; ++i) space->Update(id[i], min, max);
  space->EndChanges();
  EXPECT_EQ(warnings.Count(), 1);
  ev = Collect(*space);
  checker.Step(ev);
  EXPECT_EQ(ev.hellos.size(), 60u);
  EXPECT_EQ(ev.stayings.size(), 6u);
  EXPECT_EQ(space->Stats().overlaps, 66);
  EXPECT_GE(space->Stats().pairRecords, 66);
  // The first record did not move and still holds its pair.
  EXPECT_EQ(first->SerialPair(), firstPair);
  EXPECT_EQ(first->state, PairState::Staying);
  EXPECT_TRUE(space->Validate());
  AxisSortSpace::Destroy(space);
}

}  // namespace
}  // namespace karma::mcd::test
