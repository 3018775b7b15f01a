// Random moving boxes over many steps: the space's reported pairs equal the
// brute-force overlap set every step, for every combination of sorted axes,
// with and without insertions, removals, freezes, disabled pairs and culling.
#include "lifecycle_checker.h"

#include <gtest/gtest.h>

namespace karma::mcd::test {
namespace {

// Moves every box, updates the space through its AABB function and checks
// the step's events against the brute force and the life-cycle rules.
void RunMotion(int axes, int count, int steps, unsigned seed) {
  BoxWorld world(count, 20, seed);
  AxisSortSpace *space = AxisSortSpace::Create(axes, count, count * count / 2 + 1);
  ASSERT_NE(space, nullptr);
  for (MovingBox &b : world.Boxes()) ASSERT_NE(InsertBox(*space, b), kNoProxy);
  space->EndChanges();
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  LifecycleChecker checker;
  long long reportedTotal = 0;
  for (int step = 0; step < steps; ++step) {
    const Events ev = Collect(*space, 37);
    checker.Step(ev);
    ASSERT_EQ(ReportedKeys(ev), BruteForceReported(*space)) << "axes " << axes << " step " << step;
    ASSERT_TRUE(space->Validate());
    reportedTotal += static_cast<long long>(ev.hellos.size() + ev.stayings.size());
    space->BeginChanges();
    world.Move();
    space->UpdateAll();
    space->EndChanges();
  }
  EXPECT_GT(reportedTotal, steps) << "the scene should have overlaps";
  EXPECT_GT(checker.Hellos(), 0);
  EXPECT_GT(checker.Goodbyes(), 0);
  AxisSortSpace::Destroy(space);
}

TEST(FarfieldRandomMotion, ThreeAxes) { RunMotion(kAllAxes, 200, 300, 1u); }
TEST(FarfieldRandomMotion, TwoAxes) {
  RunMotion(kAxisX | kAxisY, 150, 200, 2u);
  RunMotion(kAxisX | kAxisZ, 150, 200, 3u);
  RunMotion(kAxisY | kAxisZ, 150, 200, 4u);
}
TEST(FarfieldRandomMotion, OneAxis) {
  RunMotion(kAxisX, 100, 200, 5u);
  RunMotion(kAxisY, 100, 200, 6u);
  RunMotion(kAxisZ, 100, 200, 7u);
}

// Fast boxes (many swaps per step) still agree with the brute force.
TEST(FarfieldRandomMotion, FastMotion) {
  BoxWorld world(120, 10, 11u, MeReal(3));
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 120, 120 * 120);
  for (MovingBox &b : world.Boxes()) InsertBox(*space, b);
  space->EndChanges();
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  LifecycleChecker checker;
  for (int step = 0; step < 100; ++step) {
    checker.Step(Collect(*space));
    space->BeginChanges();
    world.Move();
    space->UpdateAll();
    space->EndChanges();
    ASSERT_EQ(ReportedKeys(Collect(*space)), BruteForceReported(*space)) << step;
    ASSERT_TRUE(space->Validate());
  }
  AxisSortSpace::Destroy(space);
}

// Everything at once over a long run: insertions, removals, re-insertions,
// freezes, disabled pairs, culling parameters; random container sizes. Every
// step equals the brute force, and after removing every proxy each hello has
// had exactly one goodbye.
void Soak(int axes, unsigned seed, int steps) {
  const int count = 160;
  BoxWorld world(count, 16, seed);
  CullingTable *table = CullingTableCreate(4);
  CullingTableSet(table, 0, 1, 1);
  CullingTableSet(table, 2, 2, 1);
  AxisSortSpace *space = AxisSortSpace::Create(axes, count, count * count);
  for (int i = 0; i < count / 2; ++i) InsertBox(*space, world.Box(i));
  space->EndChanges();
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  LifecycleChecker checker;
  auto randomLive = [&]() -> MovingBox * {
    for (int tries = 0; tries < 20; ++tries) {
      MovingBox &b = world.Box(world.Int(0, count - 1));
      if (b.id != kNoProxy) return &b;
    }
    return nullptr;
  };
  for (int step = 0; step < steps; ++step) {
    const Events ev = Collect(*space, world.Int(1, 50));
    checker.Step(ev);
    ASSERT_EQ(ReportedKeys(ev), BruteForceReported(*space)) << "step " << step;
    ASSERT_TRUE(space->Validate());
    space->BeginChanges();
    world.Move();
    const int ops = world.Int(0, 6);
    for (int op = 0; op < ops; ++op) {
      const int kind = world.Int(0, 7);
      if (kind <= 1) {  // insert a box that is out
        MovingBox &b = world.Box(world.Int(0, count - 1));
        if (b.id == kNoProxy) InsertBox(*space, b);
      } else if (kind == 2) {
        if (MovingBox *b = randomLive()) {
          ASSERT_TRUE(space->Remove(b->id));
          b->id = kNoProxy;
        }
      } else if (kind == 3) {
        if (MovingBox *b = randomLive()) space->Freeze(b->id);
      } else if (kind == 4) {
        if (MovingBox *b = randomLive()) space->Unfreeze(b->id);
      } else if (kind == 5) {
        MovingBox *a = randomLive(), *b = randomLive();
        if (a && b && a != b) space->DisablePair(a->id, b->id);
      } else if (kind == 6) {
        MovingBox *a = randomLive(), *b = randomLive();
        if (a && b && a != b) space->EnablePair(a->id, b->id);
      } else {
        if (MovingBox *b = randomLive()) {
          space->SetCulling(b->id, world.Int(0, 3) ? table : nullptr, world.Int(0, 3), world.Int(0, 1));
        }
      }
    }
    space->UpdateAll();
    space->EndChanges();
  }
  checker.Step(Collect(*space));
  space->BeginChanges();
  for (MovingBox &b : world.Boxes()) {
    if (b.id != kNoProxy) space->Remove(b.id);
  }
  space->EndChanges();
  const Events last = Collect(*space);
  EXPECT_TRUE(last.hellos.empty());
  EXPECT_TRUE(last.stayings.empty());
  checker.Step(last);
  EXPECT_EQ(checker.Alive(), 0u);
  EXPECT_EQ(checker.Hellos(), checker.Goodbyes());
  EXPECT_GT(checker.Hellos(), 100);
  EXPECT_EQ(space->ProxyCount(), 0);
  space->BeginChanges();
  EXPECT_EQ(space->Stats().recordsInUse, 0);
  EXPECT_EQ(space->Stats().overlaps, 0);
  AxisSortSpace::Destroy(space);
  CullingTableDestroy(table);
}

TEST(FarfieldRandomMotion, SoakAllOperationsThreeAxes) { Soak(kAllAxes, 21u, 600); }
TEST(FarfieldRandomMotion, SoakAllOperationsTwoAxes) { Soak(kAxisX | kAxisZ, 22u, 300); }
TEST(FarfieldRandomMotion, SoakAllOperationsOneAxis) { Soak(kAxisY, 23u, 200); }

}  // namespace
}  // namespace karma::mcd::test

namespace karma::mcd::test {
namespace {

// Boxes on an integer grid moving by whole units: touching faces (equal
// endpoint values) happen all the time, and touching counts as overlapping
// in the space as in the brute force.
TEST(FarfieldRandomMotion, GridMotionWithTouchingBoxes) {
  for (int axes : {kAllAxes, kAxisX | kAxisY, kAxisZ}) {
    BoxWorld world(80, 8, 31u);
    for (MovingBox &b : world.Boxes()) {
      for (int k = 0; k < 3; ++k) {
        b.pos[k] = MeReal(world.Int(0, 8));
        b.vel[k] = MeReal(world.Int(-1, 1));
        b.half[k] = MeReal(world.Int(1, 2)) * MeReal(0.5);
      }
    }
    AxisSortSpace *space = AxisSortSpace::Create(axes, 80, 80 * 80);
    for (MovingBox &b : world.Boxes()) InsertBox(*space, b);
    space->EndChanges();
    space->SetAabbFn(&MovingBoxAabb, nullptr);
    LifecycleChecker checker;
    for (int step = 0; step < 150; ++step) {
      const Events ev = Collect(*space);
      checker.Step(ev);
      ASSERT_EQ(ReportedKeys(ev), BruteForceReported(*space)) << "axes " << axes << " step " << step;
      ASSERT_TRUE(space->Validate());
      space->BeginChanges();
      world.Move();
      space->UpdateAll();
      space->EndChanges();
    }
    AxisSortSpace::Destroy(space);
  }
}

}  // namespace
}  // namespace karma::mcd::test
