// The world's body-enable callback (what Mst's world handlers use) and the
// bridge accessors of bridge/mdt_bridge.h.
#include "mdt_test_support.h"

#include "mdt_bridge.h"

#include <utility>
#include <vector>

using namespace mdt_test;

namespace {
std::vector<std::pair<MdtBodyID, MeBool>> gEvents;
void MEAPI Record(MdtBodyID b, MeBool enabled, void *data) {
  EXPECT_EQ(data, &gEvents);
  gEvents.emplace_back(b, enabled);
}
}  // namespace

TEST(BodyEnableCallback, CalledOnEveryChangeByProgramWakingAndAutoDisable) {
  World w;
  gEvents.clear();
  MdtWorldSetBodyEnableCallback(w, Record, &gEvents);
  void *data = nullptr;
  EXPECT_EQ(MdtWorldGetBodyEnableCallback(w, &data), Record);
  EXPECT_EQ(data, &gEvents);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
  EXPECT_TRUE(gEvents.empty());  // created disabled: no change
  MdtBodyEnable(a);
  MdtBodyEnable(a);  // no change, no call
  ASSERT_EQ(gEvents.size(), 1u);
  EXPECT_EQ(gEvents[0], std::make_pair(a, (MeBool)TRUE));
  // A joint from the enabled a to the disabled b wakes b in the step.
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointEnable(j);
  MdtWorldStep(w, (MeReal)0.01);
  ASSERT_EQ(gEvents.size(), 2u);
  EXPECT_EQ(gEvents[1], std::make_pair(b, (MeBool)TRUE));
  // At rest without gravity: auto-disable puts both to sleep.
  for (int i = 0; i < 100 && MdtBodyIsEnabled(a); ++i) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_FALSE(MdtBodyIsEnabled(a));
  ASSERT_EQ(gEvents.size(), 4u);
  EXPECT_EQ(gEvents[2].second, FALSE);
  EXPECT_EQ(gEvents[3].second, FALSE);
  MdtWorldSetBodyEnableCallback(w, nullptr, nullptr);
  MdtBodyEnable(a);
  EXPECT_EQ(gEvents.size(), 4u);
}

TEST(BodyEnableCallback, BridgeAccessors) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetLinearVelocity(b, 1, 2, 3);
  MdtBodySetAngularVelocity(b, 4, 5, 6);
  MeReal *v = MdtBodyGetLinearVelocityPtr(b), *av = MdtBodyGetAngularVelocityPtr(b);
  EXPECT_EQ(v[2], 3);
  EXPECT_EQ(av[0], 4);
  MdtBodySetLinearVelocity(b, 7, 8, 9);
  EXPECT_EQ(v[0], 7);  // the same storage
  EXPECT_EQ(MdtBodyGetCollisionModel(b), nullptr);
  int model = 0;
  MdtBodySetCollisionModel(b, &model);
  EXPECT_EQ(MdtBodyGetCollisionModel(b), &model);
  WarningCapture wc;
  EXPECT_EQ(MdtBodyGetLinearVelocityPtr(nullptr), nullptr);
  MdtWorldSetBodyEnableCallback(nullptr, nullptr, nullptr);
  EXPECT_EQ(wc.count(), 2u);
}
