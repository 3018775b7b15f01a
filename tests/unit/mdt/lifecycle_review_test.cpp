// lifecycle_review_test.cpp: the life cycle of constraints and contacts
// around changes of bodies, destruction and the step's wake-up: a contact
// keeps its place in the world when its group's bodies change or it joins a
// group, a group keeps its own list, a destroyed constraint's handle is
// refused, a constraint given new bodies keeps no force of the old ones, and
// the enable callback may destroy the body it is told about while a step
// wakes an island.
#include <cmath>

#include "mdt_test_support.h"

using namespace mdt_test;

namespace {

constexpr double kTol = 1e-5;

void expectPosition(MdtConstraintID c, MeReal x, MeReal y, MeReal z) {
  MeVector3 p;
  MdtConstraintGetPosition(c, p);
  EXPECT_NEAR(p[0], x, kTol);
  EXPECT_NEAR(p[1], y, kTol);
  EXPECT_NEAR(p[2], z, kTol);
}

MdtContactID restingContact(MdtContactGroupID g) {
  MdtContactID k = MdtContactGroupCreateContact(g);
  MdtContactSetNormal(k, 0, 0, 1);
  MdtContactSetPenetration(k, 0);
  return k;
}

TEST(MdtContactGroup, ItsContactsKeepTheirWorldPositionWhenItIsGivenNewBodies) {
  World w;
  MdtBodyID a = MdtBodyCreate(w), c = MdtBodyCreate(w);
  MdtBodySetPosition(a, 0, 0, 0);
  MdtBodySetPosition(c, 10, 0, 0);
  const MeReal turn[4] = {(MeReal)0.5, (MeReal)0.5, (MeReal)0.5, (MeReal)0.5};  // a third of a turn about (1,1,1)
  MdtBodySetQuaternion(c, turn[0], turn[1], turn[2], turn[3]);
  MdtBodyEnable(c);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  MdtContactID kept = restingContact(g);
  MdtContactSetPosition(kept, 10, 1, (MeReal)-0.5);  // placed before the group moves to c
  MdtContactID placed = restingContact(g);

  MdtContactGroupSetBodies(g, c, nullptr);
  EXPECT_EQ(MdtContactGetBody(kept, 0), c);
  expectPosition(MdtContactQuaConstraint(kept), 10, 1, (MeReal)-0.5);
  MdtContactSetPosition(placed, 10, 0, (MeReal)-0.5);  // placed after

  MdtContactGroupEnable(g);
  MdtWorldStep(w, (MeReal)0.01);  // nothing moves: no gravity, no penetration
  expectPosition(MdtContactQuaConstraint(kept), 10, 1, (MeReal)-0.5);
  expectPosition(MdtContactQuaConstraint(placed), 10, 0, (MeReal)-0.5);
}

TEST(MdtContactGroup, AContactAppendedToAGroupKeepsItsWorldPosition) {
  World w;
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodySetPosition(a, 5, 0, 0);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  MdtContactID k = MdtContactCreate(w);
  MdtContactSetPosition(k, 5, 0, (MeReal)-0.5);
  MdtContactGroupAppendContact(g, k);
  EXPECT_EQ(MdtContactGetBody(k, 0), a);
  expectPosition(MdtContactQuaConstraint(k), 5, 0, (MeReal)-0.5);
}

TEST(MdtContactGroup, SetNextOnAContactOfAGroupIsRefusedAndTheGroupKeepsItsContacts) {
  World w;
  MdtBodyID a = MdtBodyCreate(w);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  MdtContactID k1 = MdtContactGroupCreateContact(g);
  MdtContactGroupCreateContact(g);
  WarningCapture warnings;
  MdtContactSetNext(k1, nullptr);
  EXPECT_TRUE(warnings.saw("MdtContactSetNext"));
  int walked = 0;
  for (MdtContactID k = MdtContactGroupGetFirstContact(g); k; k = MdtContactGroupGetNextContact(g, k)) ++walked;
  EXPECT_EQ(walked, 2);
  EXPECT_EQ(MdtContactGroupGetCount(g), 2);
  MdtContactGroupDestroy(g);
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 0u);  // the group took both contacts with it
}

TEST(MdtConstraint, AStaleHandleIsRefusedAndLeavesTheNextConstraintAlone) {
  World w;
  MdtBodyID a = MdtBodyCreate(w);
  MdtHingeID h = MdtHingeCreate(w);
  MdtHingeDestroy(h);
  MdtBSJointID j = MdtBSJointCreate(w);
  EXPECT_NE((void *)j, (void *)h);  // a just-released slot is not the next one handed out
  MdtBSJointSetBodies(j, a, nullptr);
  WarningCapture warnings;
  MdtHingeDestroy(h);
  EXPECT_TRUE(warnings.saw("MdtConstraintDestroy"));
  MdtHingeSetAxis(h, 0, 0, 1);  // a typed call
  EXPECT_TRUE(warnings.lastMentions("destroyed"));
  MdtConstraintEnable(MdtHingeQuaConstraint(h));  // a common one
  EXPECT_TRUE(warnings.lastMentions("destroyed"));
  EXPECT_EQ(warnings.count(), 3u);
  EXPECT_EQ(MdtConstraintDCastHinge(MdtHingeQuaConstraint(h)), nullptr);
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 1u);
  EXPECT_EQ(MdtBSJointGetBody(j, 0), a);
  EXPECT_EQ(warnings.count(), 3u);
}

TEST(MdtConstraint, ReleasedSlotsAreReusedBeforeTheWorldGrows) {
  World w(2, 1, 1, 4);
  WarningCapture warnings;
  for (int round = 0; round < 3; ++round) {
    MdtBSJointID j[4];
    for (MdtBSJointID &k : j) {
      k = MdtBSJointCreate(w);
      ASSERT_NE(k, nullptr);
    }
    EXPECT_EQ(MdtWorldGetConstraintCount(w), 4u);
    for (MdtBSJointID k : j) MdtBSJointDestroy(k);
    EXPECT_EQ(MdtWorldGetConstraintCount(w), 0u);
  }
  EXPECT_EQ(warnings.count(), 0u);  // never grown
}

// A joint holding a 1000 kg load, stepped until it carries it.
struct LoadedJoint {
  World w;
  MdtBodyID load = MdtBodyCreate(w);
  MdtBSJointID j = MdtBSJointCreate(w);
  LoadedJoint() {
    MdtWorldSetAutoDisable(w, 0);
    MdtBodySetMass(load, 1000);
    MdtBodySetPosition(load, 0, 0, -1);
    MdtBodyEnable(load);
    MdtBSJointSetBodies(j, load, nullptr);
    MdtBSJointSetPosition(j, 0, 0, 0);
    MdtBSJointEnable(j);
    MdtWorldSetGravity(w, 0, 0, -10);
    for (int i = 0; i < 5; ++i) MdtWorldStep(w, (MeReal)0.01);
  }
};

void expectNoForce(MdtBSJointID j) {
  for (unsigned i = 0; i < 2; ++i) {
    MeVector3 f, t;
    MdtBSJointGetForce(j, i, f);
    MdtBSJointGetTorque(j, i, t);
    EXPECT_EQ(MeVector3Magnitude(f), 0) << "body " << i;
    EXPECT_EQ(MeVector3Magnitude(t), 0) << "body " << i;
  }
}

TEST(MdtConstraint, AConstraintGivenNewBodiesKeepsNoForceOfTheOldOnes) {
  LoadedJoint s;
  MeVector3 f;
  MdtBSJointGetForce(s.j, 0, f);
  ASSERT_GT(f[2], 5000);  // it holds the load
  MdtBSJointDisable(s.j);
  MdtBodyID light = MdtBodyCreate(s.w);
  MdtBSJointSetBodies(s.j, light, nullptr);
  expectNoForce(s.j);
}

TEST(MdtConstraint, AConstraintLeftWithoutBodiesByMdtBodyDestroyKeepsNoForce) {
  LoadedJoint s;
  MeVector3 f;
  MdtBSJointGetForce(s.j, 0, f);
  ASSERT_GT(f[2], 5000);
  WarningCapture warnings;  // "an enabled BSJoint still used this body"
  MdtBodyDestroy(s.load);
  expectNoForce(s.j);
}

MdtBodyID gDestroyOnWake = nullptr;
void MEAPI DestroyWhenWoken(MdtBodyID b, MeBool enabled, void *) {
  if (enabled && b == gDestroyOnWake) MdtBodyDestroy(b);
}

TEST(MdtWorldStep, AnEnableCallbackThatDestroysAWokenBodyDoesNotStopTheIslandWaking) {
  World w;
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w), c = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 0, 0);
  MdtBodySetPosition(c, -1, 0, 0);
  MdtBSJointID jc = MdtBSJointCreate(w), jb = MdtBSJointCreate(w);
  MdtBSJointSetBodies(jc, a, c);
  MdtBSJointSetPosition(jc, (MeReal)-0.5, 0, 0);
  MdtBSJointSetBodies(jb, a, b);  // joined last: first in a's list
  MdtBSJointSetPosition(jb, (MeReal)0.5, 0, 0);
  MdtBSJointEnable(jc);
  MdtBSJointEnable(jb);
  MdtBodySetLinearVelocity(c, 0, 1, 0);
  MdtBodyEnable(a);
  gDestroyOnWake = b;
  MdtWorldSetBodyEnableCallback(w, DestroyWhenWoken, nullptr);
  WarningCapture warnings;  // "an enabled BSJoint still used this body"
  MdtWorldStep(w, (MeReal)0.01);
  MdtWorldSetBodyEnableCallback(w, nullptr, nullptr);
  EXPECT_TRUE(MdtBodyIsEnabled(c));
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 2u);
  MeVector3 p;
  MdtBodyGetPosition(c, p);
  EXPECT_GT(p[1], 0);  // c moved with its velocity
}

TEST(MdtContactGroup, ResettingAGroupOrOneOfItsContactsKeepsEveryContactInTheGroup) {
  World w;
  MdtBodyID a = MdtBodyCreate(w);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  MdtContactGroupCreateContact(g);
  MdtContactID second = MdtContactGroupCreateContact(g);
  MdtContactGroupCreateContact(g);
  auto walked = [g] {
    int n = 0;
    for (MdtContactID k = MdtContactGroupGetFirstContact(g); k; k = MdtContactGroupGetNextContact(g, k)) ++n;
    return n;
  };
  MdtContactReset(second);
  EXPECT_EQ(walked(), 3);
  MdtContactGroupReset(g);
  EXPECT_EQ(walked(), 3);
  EXPECT_EQ(MdtContactGroupGetCount(g), 3);
  MdtContactGroupDestroy(g);
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 0u);  // the group took all three with it
}

// A sleeper woken by the walk and disabled again by the callback leaves an
// enabled joint between an awake body and a disabled one, whose partition
// index is stale: the partitions treat it as the world.
MdtBodyID gDisableOnWake = nullptr;
void MEAPI DisableWhenWoken(MdtBodyID b, MeBool enabled, void *) {
  if (enabled && b == gDisableOnWake) MdtBodyDisable(b);
}

TEST(MdtWorldStep, ABodyTheEnableCallbackDisablesAgainActsAsTheWorld) {
  World w;
  MdtWorldSetGravity(w, 0, (MeReal)-9.81, 0);
  constexpr int kBodies = 8;
  MdtBodyID body[kBodies];
  for (int i = 0; i < kBodies; ++i) {
    body[i] = MdtBodyCreate(w);
    MdtBodySetPosition(body[i], (MeReal)i, 0, 0);
    MdtBodyEnable(body[i]);
  }
  for (int i = 0; i + 1 < kBodies; ++i) {
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, body[i], body[i + 1]);
    MdtBSJointSetPosition(j, (MeReal)i + (MeReal)0.5, 0, 0);
    MdtBSJointEnable(j);
  }
  MdtWorldStep(w, (MeReal)0.01);  // the last body's index is 7 of 8
  WarningCapture warnings;  // destroying bodies that enabled joints still use
  for (int i = 1; i + 1 < kBodies; ++i) MdtBodyDestroy(body[i]);
  MdtBodyID first = body[0], last = body[kBodies - 1];
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, first, last);
  MdtBSJointSetPosition(j, 1, 0, 0);
  MdtBSJointEnable(j);
  MdtBodyDisable(first);
  MdtBodyDisable(last);
  gDisableOnWake = last;
  MdtWorldSetBodyEnableCallback(w, DisableWhenWoken, nullptr);
  MdtBodyEnable(first);
  MeVector3 before;
  MdtBodyGetPosition(last, before);
  MdtWorldStep(w, (MeReal)0.01);  // wrote past the partition arrays
  MdtWorldSetBodyEnableCallback(w, nullptr, nullptr);
  EXPECT_TRUE(MdtBodyIsEnabled(first));
  EXPECT_FALSE(MdtBodyIsEnabled(last));
  MeVector3 after, v;
  MdtBodyGetPosition(last, after);
  EXPECT_EQ(after[1], before[1]);  // held still
  // Pinned to a still body at (1, 0, 0), 1 m from its centre: the joint
  // stops that point (within its softness), where gravity and the velocity
  // it had from the first step would take it down at 0.196 m/s.
  MeVector3 pivot;
  MdtBodyGetPosition(first, pivot);
  pivot[0] = 1 - pivot[0], pivot[1] = -pivot[1], pivot[2] = -pivot[2];  // from the centre
  MeVector3 spin, pivotVelocity;
  MdtBodyGetLinearVelocity(first, v);
  MdtBodyGetAngularVelocity(first, spin);
  MeVector3Cross(pivotVelocity, spin, pivot);
  MeVector3Add(pivotVelocity, pivotVelocity, v);
  EXPECT_LT(MeVector3Magnitude(pivotVelocity), (MeReal)0.02);
}

}  // namespace
