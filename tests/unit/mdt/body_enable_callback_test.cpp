// The world's body-enable callback (what Mst's world handlers use) and the
// bridge accessors of bridge/mdt_bridge.h.
#include "mdt_test_support.h"

#include "mdt_bridge.h"

#include <cmath>
#include <cstring>
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

namespace {
// Two turned bodies and a contact group between them (the bridge's setting).
struct Pair {
  World w;
  MdtBodyID a, b;
  MdtContactGroupID g;
  Pair() : a(MdtBodyCreate(w)), b(MdtBodyCreate(w)), g(MdtContactGroupCreate(w)) {
    MdtBodySetPosition(a, (MeReal)0.3, (MeReal)1.1, -(MeReal)0.2);
    MdtBodySetPosition(b, -(MeReal)0.4, (MeReal)0.2, (MeReal)0.7);
    MdtBodySetQuaternion(a, (MeReal)0.8, (MeReal)0.2, (MeReal)0.4, (MeReal)0.4);
    MdtBodySetQuaternion(b, (MeReal)0.6, -(MeReal)0.5, (MeReal)0.5, (MeReal)0.374);
    MdtContactGroupSetBodies(g, a, b);
  }
};

// Every state MdtContactSetFromCollision writes, read through the public API.
void ExpectSameContact(MdtContactID x, MdtContactID y) {
  for (unsigned i = 0; i < 2; ++i) {
    MeVector3 px, py;
    MdtConstraintBodyGetPosition(MdtContactQuaConstraint(x), i, px);
    MdtConstraintBodyGetPosition(MdtContactQuaConstraint(y), i, py);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(px[k], py[k]);
  }
  MeVector3 nx, ny;
  MdtContactGetNormal(x, nx);
  MdtContactGetNormal(y, ny);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(nx[k], ny[k]);
  EXPECT_EQ(MdtContactGetPenetration(x), MdtContactGetPenetration(y));
  EXPECT_EQ(std::memcmp(MdtContactGetParams(x), MdtContactGetParams(y), sizeof(MdtContactParams)), 0);
  EXPECT_EQ(MdtContactGetFeature(x), MdtContactGetFeature(y));
}
}  // namespace

TEST(BridgeContacts, SetFromCollisionEqualsTheFiveSettersBitForBit) {
  Pair p;
  MdtContactParams params;
  MdtContactParamsReset(&params);
  MdtContactParamsSetType(&params, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(&params, (MeReal)0.4);
  const MeVector3 at = {(MeReal)0.123, (MeReal)0.777, -(MeReal)0.31}, n = {(MeReal)0.1, (MeReal)0.99, -(MeReal)0.05};
  MdtContactID byHand = MdtContactGroupCreateContact(p.g), bulk = MdtContactGroupCreateContact(p.g);
  MdtContactSetPosition(byHand, at[0], at[1], at[2]);
  MdtContactSetNormal(byHand, n[0], n[1], n[2]);
  MdtContactSetPenetration(byHand, (MeReal)0.0042);
  MdtContactSetParams(byHand, &params);
  MdtContactSetFeature(byHand, 77);
  MdtContactSetFromCollision(bulk, at, n, (MeReal)0.0042, &params, 77);
  ExpectSameContact(byHand, bulk);
}

TEST(BridgeContacts, SetFromCollisionIgnoresEachBadFieldAsItsSetterDoes) {
  Pair p;
  WarningCapture cap;
  MdtContactParams params;
  MdtContactParamsReset(&params);
  const MeReal nan = std::nan("");
  const MeVector3 at = {nan, 0, 0}, zero = {0, 0, 0};
  MdtContactID byHand = MdtContactGroupCreateContact(p.g), bulk = MdtContactGroupCreateContact(p.g);
  MdtContactSetPosition(byHand, at[0], at[1], at[2]);
  MdtContactSetNormal(byHand, 0, 0, 0);
  MdtContactSetPenetration(byHand, nan);
  MdtContactSetFeature(byHand, 5);
  EXPECT_EQ(cap.count(), 3u);
  MdtContactSetFromCollision(bulk, at, zero, nan, nullptr, 5);
  EXPECT_EQ(cap.count(), 7u);  // position, normal, penetration, params
  ExpectSameContact(byHand, bulk);
  MdtContactSetFromCollision(nullptr, at, zero, 0, &params, 5);
  EXPECT_EQ(cap.count(), 8u);
}

TEST(BridgeContacts, GroupGetContactsListsTheGroupInOrderWithFeatures) {
  Pair p;
  MdtContactID made[3];
  for (int i = 0; i < 3; ++i) {
    made[i] = MdtContactGroupCreateContact(p.g);
    MdtContactSetFeature(made[i], (MeU32)(10 + i));
  }
  MdtContactID got[4] = {};
  MeU32 features[4] = {};
  ASSERT_EQ(MdtContactGroupGetContacts(p.g, got, features, 4), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(got[i], made[i]);
    EXPECT_EQ(features[i], (MeU32)(10 + i));
  }
  EXPECT_EQ(MdtContactGroupGetContacts(p.g, got, features, 2), 2);  // at most max
  WarningCapture cap;
  EXPECT_EQ(MdtContactGroupGetContacts(nullptr, got, features, 4), 0);
  EXPECT_EQ(cap.count(), 1u);
}
