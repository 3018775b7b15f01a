// The step touches only what is awake (issue 17): the awake bodies, the
// constraints reached from them and the sleeping bodies that forces drive
// (engine/mdt/active_sets.h). These tests pin what the lists must keep true
// through the ways bodies and constraints change: waking islands whole,
// contacts moving in and out of groups, bodies destroyed and their slots
// handed out again, constraints moved to other bodies; and the free bodies
// stepped in one batch while the partition API still lists each of them.
#include "mdt_test_support.h"

namespace mdt_test {
namespace {

constexpr MeReal kH = (MeReal)1 / 60;

MdtBodyID awakeBody(MdtWorldID w, MeReal x) {
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, x, 0, 0);
  MdtBodyEnable(b);
  return b;
}

MdtBSJointID joint(MdtWorldID w, MdtBodyID a, MdtBodyID b) {
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MeVector3 p;
  MdtBodyGetPosition(a, p);
  MdtBSJointSetPosition(j, p[0] + (MeReal)0.5, p[1], p[2]);
  MdtBSJointEnable(j);
  return j;
}

MdtWorldStepStats step(MdtWorldID w) {
  MdtWorldStep(w, kH);
  MdtWorldStepStats s;
  MdtWorldGetStepStats(w, &s);
  return s;
}

TEST(ActiveSets, SleepingIslandsCostNothingAndOneWakesWhole) {
  World w(64, 1, 1, 64);
  MdtWorldSetGravity(w, 0, -10, 0);
  awakeBody(w, -10);
  std::vector<MdtBodyID> chain;
  for (int i = 0; i < 6; ++i) chain.push_back(awakeBody(w, (MeReal)i));
  for (int i = 0; i + 1 < 6; ++i) joint(w, chain[(size_t)i], chain[(size_t)i + 1]);
  for (int i = 0; i < 20; ++i) joint(w, awakeBody(w, 20 + (MeReal)(2 * i)), awakeBody(w, 21 + (MeReal)(2 * i)));
  // Every body but the first goes to sleep: the chain and the 20 pairs.
  for (MdtBodyID b : chain) MdtBodyDisable(b);
  step(w);
  for (int p = MdtWorldGetPartitionCount(w) - 1; p >= 0; --p) {
    for (int i = MdtWorldGetPartitionBodyCount(w, p) - 1; i >= 0; --i) {
      MdtBodyID b = MdtWorldGetPartitionBody(w, p, i);
      MeVector3 x;
      MdtBodyGetPosition(b, x);
      if (x[0] > 10) MdtBodyDisable(b);
    }
  }
  MdtWorldStepStats s = step(w);
  EXPECT_EQ(s.bodies, 1);
  EXPECT_EQ(s.constraints, 0);
  EXPECT_EQ(s.partitions, 1);
  // Waking the middle of the chain wakes all of it through its joints.
  MdtBodyEnable(chain[3]);
  s = step(w);
  EXPECT_EQ(s.bodies, 7);
  EXPECT_EQ(s.constraints, 5);
  for (MdtBodyID b : chain) EXPECT_TRUE(MdtBodyIsEnabled(b));
}

TEST(ActiveSets, AContactTakenOutOfItsGroupAndEnabledIsStepped) {
  World w(8, 1, 1, 16);
  MdtBodyID a = awakeBody(w, 0), b = awakeBody(w, 1);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, b);
  MdtContactID c = MdtContactGroupCreateContact(g);
  MdtContactSetNormal(c, 1, 0, 0);
  EXPECT_EQ(step(w).constraints, 0);  // the group is not enabled
  MdtContactGroupRemoveContact(g, c);
  MdtContactEnable(c);
  EXPECT_EQ(step(w).constraints, 1);
  // Only body b awake: the contact still reaches the step through b.
  MdtBodyDisable(a);
  MdtBodySetLinearVelocity(b, 1, 0, 0);
  EXPECT_EQ(step(w).constraints, 1);
}

TEST(ActiveSets, AContactEnabledAloneThenGroupedGoesWithItsGroup) {
  World w(8, 1, 1, 16);
  MdtBodyID a = awakeBody(w, 0), b = awakeBody(w, 1);
  MdtContactID c = MdtContactCreate(w);
  MdtContactSetBodies(c, a, b);
  MdtContactSetNormal(c, 1, 0, 0);
  MdtContactEnable(c);
  EXPECT_EQ(step(w).constraints, 1);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, b);
  MdtContactGroupAppendContact(g, c);
  EXPECT_EQ(step(w).constraints, 0);
  MdtContactGroupDestroy(g);  // frees c as well
  // New constraints take the freed slots; the bodies' lists hold them only.
  joint(w, a, b);
  MdtBSJointID j2 = joint(w, b, a);
  EXPECT_EQ(step(w).constraints, 2);
  MdtBSJointDestroy(j2);
  EXPECT_EQ(step(w).constraints, 1);
}

TEST(ActiveSets, ADestroyedBodyLeavesNoConstraintToItsSlotsNextBody) {
  World w(2, 1, 1, 8);
  MdtBodyID a = awakeBody(w, 0), b = awakeBody(w, 1);
  MdtBSJointID j = joint(w, a, b);
  {
    WarningCapture warnings;  // the joint was still enabled
    MdtBodyDestroy(b);
    EXPECT_EQ(warnings.count(), 1u);
  }
  MdtBodyID c = MdtBodyCreate(w);  // the pool is full: b's slot again
  ASSERT_EQ(c, b);
  MdtBodyEnable(c);
  EXPECT_EQ(step(w).constraints, 0);
  MdtBSJointSetBodies(j, a, c);
  MdtBSJointEnable(j);
  EXPECT_EQ(step(w).constraints, 1);
}

TEST(ActiveSets, ConstraintsFollowTheirBodiesWhenTheyChange) {
  World w(8, 1, 1, 8);
  MdtBodyID a = awakeBody(w, 0), b = awakeBody(w, 1), c = awakeBody(w, 2);
  MdtBSJointID j = joint(w, a, b);
  MdtBSJointDisable(j);
  MdtBSJointSetBodies(j, a, c);
  MdtBSJointEnable(j);
  MdtBodyDisable(a);
  MdtBodyDisable(c);
  // b alone is awake: the joint left b's list and wakes nothing.
  MdtWorldStepStats s = step(w);
  EXPECT_EQ(s.bodies, 1);
  EXPECT_EQ(s.constraints, 0);
  EXPECT_FALSE(MdtBodyIsEnabled(a));
  MdtBodyEnable(c);  // c wakes a through the joint
  s = step(w);
  EXPECT_EQ(s.constraints, 1);
  EXPECT_TRUE(MdtBodyIsEnabled(a));
}

TEST(ActiveSets, ForcesOnSleepingBodiesWakeOrClear) {
  World w(1, 1, 1, 4);
  MdtBodyID a = MdtBodyCreate(w);  // created disabled
  MdtBodyAddForce(a, (MeReal)1e-4, 0, 0);
  step(w);
  EXPECT_FALSE(MdtBodyIsEnabled(a));
  MeVector3 f;
  MdtBodyGetForce(a, f);
  EXPECT_EQ(f[0], 0);  // below the thresholds: cleared
  MdtBodyAddForce(a, 100, 0, 0);
  MdtBodyDestroy(a);
  MdtBodyID b = MdtBodyCreate(w);  // the same slot
  ASSERT_EQ(a, b);
  {
    WarningCapture warnings;
    step(w);
    EXPECT_EQ(warnings.count(), 0u);
  }
  EXPECT_FALSE(MdtBodyIsEnabled(b));  // the destroyed body's force drives nothing
  MdtBodyAddImpulse(b, 10, 0, 0);
  step(w);
  EXPECT_TRUE(MdtBodyIsEnabled(b));
}

// Free bodies (no constraint) are stepped in one batch, but each is still
// a partition of its own with 0 rows, numbered in the order partitions are
// found from the bodies in (sort key, creation) order.
TEST(ActiveSets, FreeBodiesStayPartitionsOfOneWithNoRows) {
  World w(8, 1, 1, 8);
  MdtBodyID f2 = awakeBody(w, 10), p1 = awakeBody(w, 0), p2 = awakeBody(w, 1), f1 = awakeBody(w, -10);
  joint(w, p1, p2);
  MdtBodySetSortKey(f1, 0);
  MdtBodySetSortKey(p1, 1);
  MdtBodySetSortKey(p2, 1);
  MdtBodySetSortKey(f2, 2);
  const MdtWorldStepStats s = step(w);
  EXPECT_EQ(s.partitions, 3);
  EXPECT_EQ(s.bodies, 4);
  ASSERT_EQ(MdtWorldGetPartitionCount(w), 3);
  EXPECT_EQ(MdtWorldGetPartitionBody(w, 0, 0), f1);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 0);
  EXPECT_EQ(MdtWorldGetPartitionBodyCount(w, 1), 2);
  EXPECT_EQ(MdtWorldGetPartitionBody(w, 1, 0), p1);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 1), 3);
  EXPECT_EQ(MdtWorldGetPartitionBody(w, 2, 0), f2);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 2), 0);
}

// A free body's motion is its own: stepped beside a jointed pair and other
// free bodies it ends bit for bit where it ends alone, and it goes to sleep
// on the same step (damping brings it to rest; no gravity).
void tumbler(MdtBodyID b) {
  const MeMatrix3 I = {{(MeReal)0.2, 0, 0}, {0, (MeReal)0.5, 0}, {0, 0, (MeReal)0.9}};
  MdtBodySetInertiaTensor(b, I);
  MdtBodySetAngularVelocity(b, 1, 2, 3);
  MdtBodySetLinearVelocity(b, 1, 5, 0);
  MdtBodySetAngularVelocityDamping(b, (MeReal)2);
  MdtBodySetLinearVelocityDamping(b, (MeReal)2);
}

TEST(ActiveSets, AFreeBodyStepsTheSameAloneOrInABatch) {
  World alone(4, 1, 1, 4), crowd(16, 1, 1, 16);
  MdtBodyID a = awakeBody(alone, 0);
  tumbler(a);
  joint(crowd, awakeBody(crowd, -5), awakeBody(crowd, -4));
  awakeBody(crowd, 5);
  MdtBodyID b = awakeBody(crowd, 0);
  tumbler(b);
  awakeBody(crowd, 7);
  int sleptAlone = -1, sleptInCrowd = -1;
  for (int i = 0; i < 600; ++i) {
    step(alone);
    step(crowd);
    if (sleptAlone < 0 && !MdtBodyIsEnabled(a)) sleptAlone = i;
    if (sleptInCrowd < 0 && !MdtBodyIsEnabled(b)) sleptInCrowd = i;
  }
  MeVector3 xa, xb, va, vb;
  MeVector4 qa, qb;
  MdtBodyGetPosition(a, xa);
  MdtBodyGetPosition(b, xb);
  MdtBodyGetQuaternion(a, qa);
  MdtBodyGetQuaternion(b, qb);
  MdtBodyGetAngularVelocity(a, va);
  MdtBodyGetAngularVelocity(b, vb);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(xa[k], xb[k]);
    EXPECT_EQ(va[k], vb[k]);
  }
  for (int k = 0; k < 4; ++k) EXPECT_EQ(qa[k], qb[k]);
  EXPECT_GT(sleptAlone, 0);  // damped to rest
  EXPECT_EQ(sleptAlone, sleptInCrowd);
}

}  // namespace
}  // namespace mdt_test
