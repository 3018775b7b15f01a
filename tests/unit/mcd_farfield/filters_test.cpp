// Freezing, disabled pairs and culling tables: which overlapping pairs are
// reported, and the goodbyes and hellos when that changes.
#include "lifecycle_checker.h"

#include <gtest/gtest.h>

namespace karma::mcd::test {
namespace {

// Three unit boxes on top of each other, all overlapping.
struct Stack : ::testing::Test {
  void SetUp() override {
    space = AxisSortSpace::Create(kAllAxes, 8, 8);
    for (int i = 0; i < 3; ++i) {
      MeReal min[3], max[3];
      SetBox(min, max, 0, 0, MeReal(i) * MeReal(0.9), 1, 1, MeReal(i) * MeReal(0.9) + 1);
      id[i] = space->Insert(&user[i], min, max);
    }
  }
  void TearDown() override { AxisSortSpace::Destroy(space); }
  // Ends the block, checks and copies the events (goodbye records are
  // recycled by the BeginChanges that follows), begins the next block.
  struct Copied {
    std::vector<PairRecord> goodbyes, hellos, stayings;
  };
  Copied Step() {
    space->EndChanges();
    const Events ev = Collect(*space);
    checker.Step(ev);
    Copied c;
    for (const PairRecord *r : ev.goodbyes) c.goodbyes.push_back(*r);
    for (const PairRecord *r : ev.hellos) c.hellos.push_back(*r);
    for (const PairRecord *r : ev.stayings) c.stayings.push_back(*r);
    space->BeginChanges();
    return c;
  }
  AxisSortSpace *space = nullptr;
  int user[3] = {};
  ProxyId id[3] = {};
  LifecycleChecker checker;
};

int CallsToAabbFn = 0;
void CountingAabb(void *, void *, MeReal min[3], MeReal max[3]) {
  ++CallsToAabbFn;
  SetBox(min, max, 100, 100, 100, 101, 101, 101);
}

TEST_F(Stack, FrozenPairsAreNotReported) {
  space->Freeze(id[0]);
  space->Freeze(id[1]);
  EXPECT_TRUE(space->IsFrozen(id[0]));
  EXPECT_FALSE(space->IsFrozen(id[2]));
  Copied ev = Step();
  // 0-1 both frozen: not reported; 1-2 (frozen, unfrozen) is.
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ev.hellos[0].proxyA, id[1]);
  EXPECT_EQ(ev.hellos[0].proxyB, id[2]);

  space->Unfreeze(id[0]);  // 0-1 now says hello
  ev = Step();
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ev.hellos[0].proxyA, id[0]);
  EXPECT_EQ(ev.stayings.size(), 1u);

  space->Freeze(id[0]);  // both frozen again: goodbye
  ev = Step();
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0].proxyA, id[0]);
  EXPECT_EQ(ev.goodbyes[0].proxyB, id[1]);
  EXPECT_EQ(ev.stayings.size(), 1u);
}

// The softer rule: pairs that exist when both proxies freeze stay, with
// their records; frozen proxies still start no pair; overlap ending still
// says goodbye.
TEST_F(Stack, KeepFrozenPairsKeepsExistingPairs) {
  space->SetKeepFrozenPairs(true);
  Copied ev = Step();
  ASSERT_EQ(ev.hellos.size(), 2u);
  const int record01 = ev.hellos[0].index;
  space->Freeze(id[0]);
  space->Freeze(id[1]);
  space->Freeze(id[2]);
  ev = Step();
  EXPECT_TRUE(ev.goodbyes.empty());
  ASSERT_EQ(ev.stayings.size(), 2u);
  EXPECT_EQ(ev.stayings[0].index, record01);
  // A new frozen-frozen overlap (2 moved onto 0 while unfrozen, then frozen
  // again before the block ended) is not reported.
  space->Unfreeze(id[2]);
  MeReal min[3], max[3];
  SetBox(min, max, 0, 0, MeReal(0.5), 1, 1, MeReal(1.5));
  space->Update(id[2], min, max);
  space->Freeze(id[2]);
  ev = Step();
  EXPECT_TRUE(ev.hellos.empty());
  EXPECT_EQ(ev.stayings.size(), 2u);  // 0-1 and 1-2 stay
  EXPECT_EQ(space->Stats().overlaps, 3);
  // Disabling still says goodbye, and turning the option off drops the rest.
  space->DisablePair(id[0], id[1]);
  ev = Step();
  EXPECT_EQ(ev.goodbyes.size(), 1u);
  space->SetKeepFrozenPairs(false);
  ev = Step();
  EXPECT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_TRUE(ev.stayings.empty());
}

TEST_F(Stack, FreezeIsValidOutsideAChangeBlock) {
  WarningCapture warnings;
  Step();
  space->EndChanges();
  EXPECT_TRUE(space->Freeze(id[0]));
  EXPECT_TRUE(space->Freeze(id[1]));
  EXPECT_TRUE(space->Unfreeze(id[1]));
  EXPECT_TRUE(space->IsFrozen(id[0]));
  space->BeginChanges();
  EXPECT_EQ(warnings.Count(), 0);
}

TEST_F(Stack, FrozenProxyIsNotUpdatedByUpdateAll) {
  Step();
  space->EndChanges();
  space->SetAabbFn(&CountingAabb, nullptr);
  space->BeginChanges();
  space->Freeze(id[1]);
  CallsToAabbFn = 0;
  space->UpdateAll();
  EXPECT_EQ(CallsToAabbFn, 2);
  MeReal min[3], max[3];
  space->GetAabb(id[1], min, max);
  EXPECT_EQ(min[2], MeReal(0.9)) << "the frozen proxy keeps its last AABB";
  space->GetAabb(id[0], min, max);
  EXPECT_EQ(min[0], 100);
  const Copied ev = Step();
  // 0 and 2 moved away together (they overlap each other); 1 stayed.
  EXPECT_EQ(ev.goodbyes.size(), 2u);
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ev.hellos[0].proxyA, id[0]);
  EXPECT_EQ(ev.hellos[0].proxyB, id[2]);
  space->EndChanges();
  EXPECT_EQ(ReportedKeys(Collect(*space)), BruteForceReported(*space));
  space->BeginChanges();
}

TEST_F(Stack, UpdatingAFrozenProxyWarnsAndDoesNothing) {
  WarningCapture warnings;
  space->Freeze(id[0]);
  MeReal min[3], max[3];
  SetBox(min, max, 50, 50, 50, 51, 51, 51);
  EXPECT_FALSE(space->Update(id[0], min, max));
  EXPECT_EQ(warnings.CountContaining("McdSpaceUpdateModel"), 1);
  space->GetAabb(id[0], min, max);
  EXPECT_EQ(min[0], 0);
}

TEST_F(Stack, DisableGivesGoodbyeEnableGivesHello) {
  Copied ev = Step();
  ASSERT_EQ(ev.hellos.size(), 2u);  // 0-1 and 1-2 (0 and 2 are apart in z)
  EXPECT_TRUE(space->PairIsEnabled(id[0], id[1]));
  EXPECT_TRUE(space->DisablePair(id[1], id[0]));
  EXPECT_FALSE(space->PairIsEnabled(id[0], id[1]));
  ev = Step();
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0].proxyA, id[0]);
  EXPECT_EQ(ev.goodbyes[0].proxyB, id[1]);
  for (int i = 0; i < 3; ++i) {  // no more references to it
    ev = Step();
    EXPECT_TRUE(ev.goodbyes.empty() && ev.hellos.empty());
    EXPECT_EQ(ev.stayings.size(), 1u);
  }
  EXPECT_TRUE(space->EnablePair(id[0], id[1]));
  EXPECT_TRUE(space->PairIsEnabled(id[0], id[1]));
  ev = Step();
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ev.hellos[0].proxyA, id[0]);
  EXPECT_EQ(ev.hellos[0].proxyB, id[1]);
}

TEST_F(Stack, EnablingAPairApartGivesHelloOnlyWhenTheyMeet) {
  space->DisablePair(id[0], id[2]);
  Step();
  MeReal min[3], max[3];
  SetBox(min, max, 10, 0, 0, 11, 1, 1);
  space->Update(id[2], min, max);
  space->EnablePair(id[0], id[2]);
  Copied ev = Step();
  EXPECT_TRUE(ev.hellos.empty());
  SetBox(min, max, MeReal(0.5), 0, MeReal(0.5), MeReal(1.5), 1, MeReal(1.5));
  space->Update(id[2], min, max);
  ev = Step();
  EXPECT_EQ(ev.hellos.size(), 2u);  // 0-2 and 1-2
}

TEST_F(Stack, RemovingAProxyForgetsItsDisabledPairs) {
  space->DisablePair(id[0], id[1]);
  Step();
  space->Remove(id[1]);
  Step();
  // A new proxy in the same place (maybe the same slot later) is enabled.
  MeReal min[3], max[3];
  SetBox(min, max, 0, 0, MeReal(0.9), 1, 1, MeReal(1.9));
  const ProxyId n = space->Insert(nullptr, min, max);
  EXPECT_TRUE(space->PairIsEnabled(id[0], n));
  const Copied ev = Step();
  EXPECT_EQ(ev.hellos.size(), 2u);
}

TEST(FarfieldCulling, TableIsSymmetricAndChecksIndices) {
  WarningCapture warnings;
  EXPECT_EQ(CullingTableCreate(0), nullptr);
  EXPECT_EQ(warnings.CountContaining("McdCullingTableCreate"), 1);
  CullingTable *t = CullingTableCreate(3);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(CullingTableSet(t, 0, 2, 1), t);
  EXPECT_TRUE(CullingTableGet(t, 0, 2));
  EXPECT_TRUE(CullingTableGet(t, 2, 0));
  EXPECT_FALSE(CullingTableGet(t, 0, 1));
  CullingTableSet(t, 2, 0, 0);
  EXPECT_FALSE(CullingTableGet(t, 0, 2));
  CullingTableSet(t, 3, 0, 1);
  EXPECT_EQ(warnings.CountContaining("McdCullingTableSet"), 1);
  CullingTableDestroy(t);
}

// Culled: both have parameters, same table, same ID, flag set.
TEST(FarfieldCulling, CulledPairsActAsDisabled) {
  CullingTable *t = CullingTableCreate(4);
  CullingTable *other = CullingTableCreate(4);
  CullingTableSet(t, 0, 1, 1);
  CullingTableSet(other, 0, 1, 1);
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, 8, 32);
  MeReal min[3], max[3];
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  const ProxyId a = space->InsertWithCulling(nullptr, min, max, t, 0, 7);
  const ProxyId b = space->InsertWithCulling(nullptr, min, max, t, 1, 7);      // culled with a
  const ProxyId c = space->InsertWithCulling(nullptr, min, max, t, 1, 8);      // other ID
  const ProxyId d = space->InsertWithCulling(nullptr, min, max, other, 1, 7);  // other table
  const ProxyId e = space->Insert(nullptr, min, max);                          // no parameters
  const ProxyId f = space->InsertWithCulling(nullptr, min, max, t, 2, 7);      // flag clear
  space->EndChanges();
  EXPECT_FALSE(space->PairIsEnabled(a, b));
  EXPECT_FALSE(space->PairIsEnabled(b, a));
  for (ProxyId x : {c, d, e, f}) EXPECT_TRUE(space->PairIsEnabled(a, x));
  Events ev = Collect(*space);
  EXPECT_EQ(ev.hellos.size(), 15u - 1u);  // 6 boxes, all overlap, a-b culled
  EXPECT_EQ(ReportedKeys(ev), BruteForceReported(*space));
  // Changing the parameters: b moves to ID 8 (pairs with a), c to ID 7 with
  // index 1 (culled with a now).
  space->BeginChanges();
  space->SetCulling(b, t, 1, 8);
  space->SetCulling(c, t, 1, 7);
  space->EndChanges();
  ev = Collect(*space);
  ASSERT_EQ(ev.hellos.size(), 1u);
  EXPECT_EQ(ev.hellos[0]->proxyA, a);
  EXPECT_EQ(ev.hellos[0]->proxyB, b);
  ASSERT_EQ(ev.goodbyes.size(), 1u);
  EXPECT_EQ(ev.goodbyes[0]->proxyA, a);
  EXPECT_EQ(ev.goodbyes[0]->proxyB, c);
  // Clearing c's parameters.
  space->BeginChanges();
  space->SetCulling(c, nullptr, 0, 0);
  space->EndChanges();
  EXPECT_EQ(Collect(*space).hellos.size(), 1u);
  {
    WarningCapture warnings;
    space->BeginChanges();
    EXPECT_FALSE(space->SetCulling(c, t, 4, 0));
    EXPECT_EQ(space->InsertWithCulling(nullptr, min, max, t, -1, 0), kNoProxy);
    EXPECT_EQ(warnings.Count(), 2);
    space->EndChanges();
  }
  AxisSortSpace::Destroy(space);
  CullingTableDestroy(t);
  CullingTableDestroy(other);
}

}  // namespace
}  // namespace karma::mcd::test
