// Sort keys in the farfield core ("Pair order" in axis_sort_space.h):
// random moving boxes with random keys, re-keyed now and then, still report
// exactly the brute force's pairs, each list in Order(), proxyA ranking
// first, and a pair's record unchanged unless its proxies swap ranks.
#include "lifecycle_checker.h"

#include <gtest/gtest.h>

#include <tuple>

namespace karma::mcd::test {
namespace {

TEST(FarfieldSortKeys, RandomKeysAndReKeyingKeepEveryInvariant) {
  const int count = 150;
  BoxWorld world(count, 16, 21u);
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, count, count * count / 2);
  std::mt19937 rng(5u);
  std::uniform_int_distribution<int> key(0, 40);  // many equal keys too
  for (MovingBox &b : world.Boxes()) {
    InsertBox(*space, b);
    space->SetKey(b.id, static_cast<std::uint32_t>(key(rng)));
  }
  space->EndChanges();
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  LifecycleChecker checker;
  for (int step = 0; step < 200; ++step) {
    const Events ev = Collect(*space, 29);
    checker.Step(ev);
    ASSERT_EQ(ReportedKeys(ev), BruteForceReported(*space)) << step;
    ASSERT_TRUE(space->Validate()) << step;
    for (const auto *list : {&ev.hellos, &ev.stayings}) {
      for (const PairRecord *r : *list) {
        const ProxyRank a = space->Rank(r->proxyA), b = space->Rank(r->proxyB);
        ASSERT_LT(a.Packed(), b.Packed()) << "proxyA ranks first";
        ASSERT_EQ(r->keyA, a.key);
        ASSERT_EQ(r->keyB, b.key);
      }
    }
    space->BeginChanges();
    world.Move();
    if (step % 5 == 2) {  // re-key a tenth of the boxes
      for (int i = 0; i < count / 10; ++i) {
        const MovingBox &b = world.Box(world.Int(0, count - 1));
        space->SetKey(b.id, static_cast<std::uint32_t>(key(rng)));
      }
    }
    space->UpdateAll();
    space->EndChanges();
  }
  EXPECT_GT(checker.Hellos(), 1000);
  AxisSortSpace::Destroy(space);
}

// The same boxes with the same distinct keys, inserted in two different
// orders: identical event sequences when written as keys.
TEST(FarfieldSortKeys, InsertionOrderDoesNotMatterWhenKeysDiffer) {
  auto run = [](bool reverse) {
    const int count = 80;
    BoxWorld world(count, 10, 8u);
    AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, count, count * count);
    for (int k = 0; k < count; ++k) {
      const int i = reverse ? count - 1 - k : k;
      InsertBox(*space, world.Box(i));
      space->SetKey(world.Box(i).id, static_cast<std::uint32_t>(1000 + 7 * i));
    }
    space->EndChanges();
    space->SetAabbFn(&MovingBoxAabb, nullptr);
    std::vector<std::tuple<int, std::uint32_t, std::uint32_t>> trace;
    for (int step = 0; step < 100; ++step) {
      const Events ev = Collect(*space, 16);
      for (const PairRecord *r : ev.goodbyes) trace.emplace_back(0, r->keyA, r->keyB);
      for (const PairRecord *r : ev.hellos) trace.emplace_back(1, r->keyA, r->keyB);
      for (const PairRecord *r : ev.stayings) trace.emplace_back(2, r->keyA, r->keyB);
      space->BeginChanges();
      world.Move();
      space->UpdateAll();
      space->EndChanges();
    }
    AxisSortSpace::Destroy(space);
    return trace;
  };
  const auto forward = run(false);
  EXPECT_GT(forward.size(), 500u);
  EXPECT_EQ(forward, run(true));
}

}  // namespace
}  // namespace karma::mcd::test
