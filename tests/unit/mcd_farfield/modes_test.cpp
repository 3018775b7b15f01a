// The change-block validity tables: every operation in the wrong mode warns
// once, naming its McdSpace function, and changes nothing. Bad input: clear
// warnings and defined results.
#include "farfield_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace karma::mcd::test {
namespace {

struct Modes : ::testing::Test {
  void SetUp() override {
    space = AxisSortSpace::Create(kAllAxes, 4, 8);
    MeReal min[3], max[3];
    SetBox(min, max, 0, 0, 0, 1, 1, 1);
    a = space->Insert(nullptr, min, max);
    b = space->Insert(nullptr, min, max);
  }
  void TearDown() override { AxisSortSpace::Destroy(space); }
  AxisSortSpace *space = nullptr;
  ProxyId a = kNoProxy, b = kNoProxy;
};

TEST_F(Modes, CreationStartsInsideAChangeBlock) { EXPECT_TRUE(space->IsChanging()); }

TEST_F(Modes, InsideOnlyCallsOutsideWarnAndDoNothing) {
  space->EndChanges();
  EXPECT_FALSE(space->IsChanging());
  const std::vector<std::uint64_t> before = ReportedKeys(Collect(*space));
  ASSERT_EQ(before.size(), 1u);
  CullingTable *t = CullingTableCreate(2);
  WarningCapture w;
  MeReal min[3], max[3];
  SetBox(min, max, 5, 5, 5, 6, 6, 6);
  EXPECT_EQ(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_EQ(w.CountContaining("McdSpaceInsertModel:"), 1);
  EXPECT_EQ(space->InsertWithCulling(nullptr, min, max, t, 0, 0), kNoProxy);
  EXPECT_EQ(w.CountContaining("McdSpaceInsertModelWithCulling"), 1);
  EXPECT_FALSE(space->Remove(a));
  EXPECT_EQ(w.CountContaining("McdSpaceRemoveModel"), 1);
  EXPECT_FALSE(space->Update(a, min, max));
  EXPECT_EQ(w.CountContaining("McdSpaceUpdateModel"), 1);
  space->UpdateAll();
  EXPECT_EQ(w.CountContaining("McdSpaceUpdateAll"), 1);
  EXPECT_FALSE(space->DisablePair(a, b));
  EXPECT_EQ(w.CountContaining("McdSpaceDisablePair"), 1);
  EXPECT_FALSE(space->EnablePair(a, b));
  EXPECT_EQ(w.CountContaining("McdSpaceEnablePair"), 1);
  EXPECT_FALSE(space->SetCulling(a, t, 0, 0));
  EXPECT_EQ(w.CountContaining("McdSpaceSetModelCullingParameters"), 1);
  space->EndChanges();
  EXPECT_EQ(w.CountContaining("McdSpaceEndChanges"), 1);
  EXPECT_EQ(w.Count(), 9);
  for (const std::string &m : w.Messages()) EXPECT_NE(m.find("inside a change block"), std::string::npos) << m;
  // Nothing changed.
  EXPECT_FALSE(space->IsChanging());
  EXPECT_EQ(space->ProxyCount(), 2);
  EXPECT_TRUE(space->PairIsEnabled(a, b));
  MeReal amin[3], amax[3];
  space->GetAabb(a, amin, amax);
  EXPECT_EQ(amin[0], 0);
  EXPECT_EQ(ReportedKeys(Collect(*space)), before);
  CullingTableDestroy(t);
}

TEST_F(Modes, OutsideOnlyCallsInsideWarnAndDoNothing) {
  WarningCapture w;
  PairIterator it;
  space->PairIteratorBegin(&it);  // anywhere
  const PairRecord *storage[4];
  PairChunk chunk;
  chunk.array = storage;
  chunk.size = 4;
  EXPECT_FALSE(space->GetPairs(&it, &chunk));
  EXPECT_EQ(chunk.stayingEnd, 0);
  EXPECT_EQ(w.CountContaining("McdSpaceGetPairs"), 1);
  EXPECT_FALSE(space->GetTransitions(&it, &chunk));
  EXPECT_EQ(w.CountContaining("McdSpaceGetTransitions"), 1);
  space->SetAabbFn(&MovingBoxAabb, nullptr);
  EXPECT_EQ(w.CountContaining("McdSpaceSetAABBFn"), 1);
  space->BeginChanges();
  EXPECT_EQ(w.CountContaining("McdSpaceBeginChanges"), 1);
  EXPECT_TRUE(space->RequireInside("McdSpaceGetLineSegFirstIntersection"));
  EXPECT_FALSE(space->RequireOutside("McdSpaceGetLineSegFirstIntersection"));
  EXPECT_EQ(w.CountContaining("McdSpaceGetLineSegFirstIntersection"), 1);
  EXPECT_EQ(w.Count(), 5);
  for (const std::string &m : w.Messages()) EXPECT_NE(m.find("outside a change block"), std::string::npos) << m;
  // SetAabbFn was ignored: UpdateAll calls no function.
  space->UpdateAll();
  MeReal min[3], max[3];
  space->GetAabb(a, min, max);
  EXPECT_EQ(max[0], 1);
  EXPECT_TRUE(space->IsChanging());
}

TEST_F(Modes, AnywhereCallsDoNotWarn) {
  WarningCapture w;
  for (int round = 0; round < 2; ++round) {
    EXPECT_TRUE(space->Freeze(a));
    EXPECT_TRUE(space->IsFrozen(a));
    EXPECT_TRUE(space->Unfreeze(a));
    EXPECT_TRUE(space->PairIsEnabled(a, b));
    EXPECT_EQ(space->ProxyCount(), 2);
    EXPECT_EQ(space->NextProxy(kNoProxy), a);
    int data = 0;
    space->SetUserData(&data);
    EXPECT_EQ(space->UserData(), &data);
    PairIterator it;
    space->PairIteratorBegin(&it);
    space->Build();
    if (round == 0) space->EndChanges();
  }
  EXPECT_EQ(w.Count(), 0);
}

TEST(FarfieldBadInput, CreationArguments) {
  WarningCapture w;
  EXPECT_EQ(AxisSortSpace::Create(kAllAxes, 0, 10), nullptr);
  EXPECT_EQ(AxisSortSpace::Create(kAllAxes, 10, 0), nullptr);
  EXPECT_EQ(w.CountContaining("McdSpaceAxisSortCreate"), 2);
  AxisSortSpace *s = AxisSortSpace::Create(0, 4, 4);  // no axes: all three
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->Axes(), kAllAxes);
  AxisSortSpace::Destroy(s);
  s = AxisSortSpace::Create(kAxisY | 8, 4, 4);  // stray bit dropped
  EXPECT_EQ(s->Axes(), kAxisY);
  AxisSortSpace::Destroy(s);
  EXPECT_EQ(w.CountContaining("McdSpaceAxisSortCreate"), 4);
}

TEST_F(Modes, BadAabbsAndHandles) {
  WarningCapture w;
  const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
  MeReal min[3], max[3];
  SetBox(min, max, 0, nan, 0, 1, 1, 1);
  EXPECT_EQ(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_FALSE(space->Update(a, min, max));
  SetBox(min, max, 2, 0, 0, 1, 1, 1);  // min > max
  EXPECT_EQ(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_EQ(space->Insert(nullptr, nullptr, max), kNoProxy);
  EXPECT_EQ(w.Count(), 4);
  space->GetAabb(a, min, max);
  EXPECT_EQ(min[1], 0);
  // Handles that are not proxies.
  EXPECT_FALSE(space->Remove(77));
  EXPECT_FALSE(space->Freeze(-1));
  EXPECT_FALSE(space->DisablePair(a, a));
  EXPECT_EQ(w.Count(), 7);
  // Full space.
  SetBox(min, max, 0, 0, 0, 1, 1, 1);
  EXPECT_NE(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_NE(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_EQ(space->Insert(nullptr, min, max), kNoProxy);
  EXPECT_EQ(w.CountContaining("full"), 1);
  EXPECT_EQ(space->ProxyCount(), 4);
  // A removed handle is no longer a proxy.
  EXPECT_TRUE(space->Remove(a));
  EXPECT_FALSE(space->Remove(a));
  EXPECT_EQ(w.Count(), 9);
}

}  // namespace
}  // namespace karma::mcd::test
