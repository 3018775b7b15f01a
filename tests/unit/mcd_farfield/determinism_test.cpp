// Determinism: two runs of the same scene give identical event sequences
// (kind, the proxies' insertion serials, record index), whatever the
// addresses of the user data; the order follows insertion serials only.
#include "farfield_test_util.h"

#include <gtest/gtest.h>

#include <memory>
#include <tuple>

namespace karma::mcd::test {
namespace {

using Trace = std::vector<std::tuple<int, std::uint64_t, int>>;

Trace RunScene(unsigned seed, int padding) {
  // Different heap layouts between runs: padding allocations.
  std::vector<std::unique_ptr<char[]>> pad;
  for (int i = 0; i < padding; ++i) pad.emplace_back(new char[static_cast<std::size_t>(64 * (i + 1))]);
  BoxWorld world(150, 14, seed);
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 150, 150 * 150);
  for (int i = 0; i < 100; ++i) InsertBox(*space, world.Box(i));
  space->EndChanges();
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  Trace trace;
  for (int step = 0; step < 150; ++step) {
    const Events ev = Collect(*space, 16);
    for (const PairRecord *r : ev.goodbyes) trace.emplace_back(0, r->SerialPair(), r->index);
    for (const PairRecord *r : ev.hellos) trace.emplace_back(1, r->SerialPair(), r->index);
    for (const PairRecord *r : ev.stayings) trace.emplace_back(2, r->SerialPair(), r->index);
    space->BeginChanges();
    world.Move();
    if (step % 10 == 5) {
      MovingBox &b = world.Box(world.Int(0, 149));
      if (b.id == kNoProxy) {
        InsertBox(*space, b);
      } else {
        space->Remove(b.id);
        b.id = kNoProxy;
      }
    }
    if (step % 7 == 3) {
      MovingBox &b = world.Box(world.Int(0, 99));
      if (b.id != kNoProxy) space->IsFrozen(b.id) ? space->Unfreeze(b.id) : space->Freeze(b.id);
    }
    space->UpdateAll();
    space->EndChanges();
  }
  AxisSortSpace::Destroy(space);
  return trace;
}

TEST(FarfieldDeterminism, TwoRunsGiveIdenticalPairSequences) {
  const Trace first = RunScene(42u, 0);
  const Trace second = RunScene(42u, 37);
  EXPECT_GT(first.size(), 1000u);
  EXPECT_EQ(first, second);
  EXPECT_NE(first, RunScene(43u, 0)) << "a different scene gives a different trace";
}

}  // namespace
}  // namespace karma::mcd::test
