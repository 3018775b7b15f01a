// Few movers among many still proxies (issue 17): the space re-sorts only
// near the endpoints that moved and settles only the overlap entries their
// swaps touched, and GetActivePairs leaves out the stayings of two frozen
// proxies. Two spaces hold the same boxes: A is told of the movers only
// (Update), B of every unfrozen box each step (UpdateAll: every proxy moved,
// the full pass). Their events must be the same record for record every
// step, and A's must equal the brute force (which knows the default frozen
// rule only, so not with SetKeepFrozenPairs(true)).
#include "brute_force.h"
#include "farfield_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace karma::mcd::test {
namespace {

constexpr int kBoxes = 240, kMovers = 10;

// One event as the bridge meets it: (kind, serial pair, record index).
struct Call {
  char kind;  // 'G' goodbye, 'H' hello, 'C' a pair to collide
  std::uint64_t pair;
  int record;
  bool operator==(const Call &) const = default;
};

// The bridge's loop: per chunk, the transitions, then every hello and
// staying; with `active`, through GetActivePairs, else through GetPairs
// leaving out the stayings of two frozen proxies.
std::vector<Call> BridgeCalls(AxisSortSpace &space, int chunkSize, bool active) {
  std::vector<Call> calls;
  std::vector<const PairRecord *> storage(static_cast<std::size_t>(chunkSize));
  PairIterator it;
  space.PairIteratorBegin(&it);
  for (bool more = true; more;) {
    PairChunk chunk;
    chunk.array = storage.data();
    chunk.size = chunkSize;
    more = active ? space.GetActivePairs(&it, &chunk) : space.GetPairs(&it, &chunk);
    for (int i = chunk.goodbyeFirst; i < chunk.goodbyeEnd; ++i)
      calls.push_back({'G', chunk.array[i]->SerialPair(), chunk.array[i]->index});
    for (int i = chunk.helloFirst; i < chunk.helloEnd; ++i)
      calls.push_back({'H', chunk.array[i]->SerialPair(), chunk.array[i]->index});
    for (int i = chunk.helloFirst; i < chunk.stayingEnd; ++i) {
      const PairRecord *r = chunk.array[i];
      const bool frozenPair = space.IsFrozen(r->proxyA) && space.IsFrozen(r->proxyB);
      if (i >= chunk.helloEnd && frozenPair && !active) continue;
      calls.push_back({'C', r->SerialPair(), r->index});
    }
  }
  return calls;
}

std::vector<std::pair<std::uint64_t, int>> Records(const std::vector<const PairRecord *> &list) {
  std::vector<std::pair<std::uint64_t, int>> out;
  for (const PairRecord *r : list) out.push_back({r->SerialPair(), r->index});
  return out;
}

void ExpectSameEvents(const Events &a, const Events &b, int step) {
  EXPECT_EQ(Records(a.goodbyes), Records(b.goodbyes)) << "step " << step;
  EXPECT_EQ(Records(a.hellos), Records(b.hellos)) << "step " << step;
  EXPECT_EQ(Records(a.stayings), Records(b.stayings)) << "step " << step;
}

// Boxes on an integer grid (touching faces all the time); the first
// kMovers move by whole units, the rest stand still.
BoxWorld GridWorld(unsigned seed) {
  BoxWorld world(kBoxes, 24, seed);
  for (int i = 0; i < kBoxes; ++i) {
    MovingBox &b = world.Box(i);
    for (int k = 0; k < 3; ++k) {
      b.pos[k] = MeReal(world.Int(0, 24));
      b.vel[k] = i < kMovers ? MeReal(world.Int(-1, 1)) : MeReal(0);
      b.half[k] = MeReal(world.Int(1, 3)) * MeReal(0.5);
    }
  }
  return world;
}

void RunFewMovers(int axes, bool keepFrozenPairs) {
  {
    BoxWorld world = GridWorld(41u);
    AxisSortSpace *a = AxisSortSpace::Create(axes, kBoxes, kBoxes * kBoxes / 2);
    AxisSortSpace *b = AxisSortSpace::Create(axes, kBoxes, kBoxes * kBoxes / 2);
    ASSERT_TRUE(a && b);
    std::vector<ProxyId> idA(kBoxes), idB(kBoxes);
    for (int i = 0; i < kBoxes; ++i) {
      MeReal min[3], max[3];
      MovingBoxAabb(&world.Box(i), nullptr, min, max);
      idA[(size_t)i] = a->Insert(&world.Box(i), min, max);
      idB[(size_t)i] = b->Insert(&world.Box(i), min, max);
    }
    for (AxisSortSpace *s : {a, b}) {
      s->SetKeepFrozenPairs(keepFrozenPairs);
      s->EndChanges();
    }
    b->SetAabbFn(&MovingBoxAabb, nullptr);
    long long frozenStayings = 0;
    for (int step = 0; step < 200; ++step) {
      const Events ea = Collect(*a, 7), eb = Collect(*b, 7);
      ExpectSameEvents(ea, eb, step);
      if (!keepFrozenPairs) {
        ASSERT_EQ(ReportedKeys(ea), BruteForceReported(*a)) << "axes " << axes << " step " << step;
      }
      ASSERT_TRUE(a->Validate());
      const std::vector<Call> plain = BridgeCalls(*a, 5, false);
      EXPECT_EQ(BridgeCalls(*a, 5, true), plain) << "step " << step;
      for (const PairRecord *r : ea.stayings) frozenStayings += a->IsFrozen(r->proxyA) && a->IsFrozen(r->proxyB);
      a->BeginChanges();
      b->BeginChanges();
      world.Move();
      // Now and then a still box freezes or thaws (in both spaces).
      if (step % 5 == 0) {
        const int i = world.Int(kMovers, kBoxes - 1);
        const bool freeze = world.Int(0, 3) != 0;
        for (auto [s, id] : {std::pair{a, idA[(size_t)i]}, std::pair{b, idB[(size_t)i]}})
          freeze ? s->Freeze(id) : s->Unfreeze(id);
      }
      for (int i = 0; i < kMovers; ++i) {
        MeReal min[3], max[3];
        MovingBoxAabb(&world.Box(i), nullptr, min, max);
        a->Update(idA[(size_t)i], min, max);
      }
      b->UpdateAll();
      a->EndChanges();
      b->EndChanges();
    }
    if (keepFrozenPairs) {
      EXPECT_GT(frozenStayings, 0) << "the run should keep pairs of two frozen boxes";
    }
    AxisSortSpace::Destroy(a);
    AxisSortSpace::Destroy(b);
  }
}

TEST(FarfieldActiveSets, FewMoversGiveTheFullPassEventsAndTheBruteForce) {
  RunFewMovers(kAllAxes, false);
  RunFewMovers(kAxisX | kAxisZ, false);
  RunFewMovers(kAxisY, false);
}

TEST(FarfieldActiveSets, FewMoversKeepingFrozenPairsGiveTheFullPassEvents) {
  RunFewMovers(kAllAxes, true);
  RunFewMovers(kAxisX | kAxisY, true);
}

}  // namespace
}  // namespace karma::mcd::test
