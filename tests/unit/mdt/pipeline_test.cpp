// The step pipeline: partitions, waking, auto-disable, matrix capping and
// determinism under sort keys.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "mdt_test_support.h"
#include "support/state_hash.h"

using namespace mdt_test;

namespace {

const MeReal g = (MeReal)9.81;

MdtBodyID bodyAt(MdtWorldID w, MeReal x, MeReal y, MeReal z) {
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, x, y, z);
  MdtBodyEnable(b);
  return b;
}

// A group of four contacts under a unit square centred below `b` (or at
// height y between two bodies), normal +y, penetrations depth0 + i * spread
// (hand-made contacts keep their depth, so a non-zero depth keeps pushing:
// only the capping tests use one).
MdtContactGroupID squareGroup(MdtWorldID w, MdtBodyID b0, MdtBodyID b1, MeReal y, MeReal depth0, MdtContactType type,
                              MeReal spread = 0) {
  MdtContactGroupID grp = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(grp, b0, b1);
  MeVector3 c;
  MdtBodyGetPosition(b0, c);
  for (int i = 0; i < 4; ++i) {
    MdtContactID k = MdtContactGroupCreateContact(grp);
    MdtContactSetPosition(k, c[0] + ((i & 1) ? (MeReal)0.5 : -(MeReal)0.5), y,
                          c[2] + ((i & 2) ? (MeReal)0.5 : -(MeReal)0.5));
    MdtContactSetNormal(k, 0, 1, 0);
    MdtContactSetPenetration(k, depth0 + spread * (MeReal)i);
    MdtContactParamsSetType(MdtContactGetParams(k), type);
  }
  MdtContactGroupEnable(grp);
  return grp;
}

bool inPartition(MdtWorldID w, int p, MdtBodyID b) {
  for (int i = 0; i < MdtWorldGetPartitionBodyCount(w, p); ++i)
    if (MdtWorldGetPartitionBody(w, p, i) == b) return true;
  return false;
}

}  // namespace

TEST(Partition, WorldContactsDoNotJoinBodyContactsAndJointsDo) {
  World w(8, 1, 1, 64);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID a = bodyAt(w, 0, (MeReal)0.5, 0);
  MdtBodyID b = bodyAt(w, 5, (MeReal)0.5, 0);
  MdtBodyID c = bodyAt(w, 5, (MeReal)1.5, 0);
  MdtBodyID d = bodyAt(w, 10, 0, 0);
  MdtBodyID e = bodyAt(w, 11, 0, 0);
  squareGroup(w, a, nullptr, 0, 0, MdtContactTypeFrictionZero);
  squareGroup(w, b, nullptr, 0, 0, MdtContactTypeFrictionZero);
  squareGroup(w, c, b, 1, 0, MdtContactTypeFrictionZero);  // c rests on b
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, d, e);
  MdtBSJointSetPosition(j, (MeReal)10.5, 0, 0);
  MdtBSJointEnable(j);
  MdtWorldStep(w, (MeReal)0.01);
  ASSERT_EQ(MdtWorldGetPartitionCount(w), 3);  // {a}, {b, c}, {d, e}
  EXPECT_EQ(MdtWorldGetPartitionBodyCount(w, 0), 1);
  EXPECT_TRUE(inPartition(w, 0, a));
  EXPECT_EQ(MdtWorldGetPartitionBodyCount(w, 1), 2);
  EXPECT_TRUE(inPartition(w, 1, b) && inPartition(w, 1, c));
  EXPECT_TRUE(inPartition(w, 2, d) && inPartition(w, 2, e));
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 4);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 1), 8);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 2), 3);
  MdtWorldStepStats st;
  MdtWorldGetStepStats(w, &st);
  EXPECT_EQ(st.partitions, 3);
  EXPECT_EQ(st.bodies, 5);
  EXPECT_EQ(st.rows, 15);
}

TEST(Partition, EnabledBodyWakesADisabledOneItTouches) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID a = bodyAt(w, 0, 0, 0);
  MdtBodyID b = bodyAt(w, 0, 1, 0);
  MdtBodyDisable(b);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, a, b);
  MdtBSJointSetPosition(j, 0, (MeReal)0.5, 0);
  MdtBSJointEnable(j);
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_TRUE(MdtBodyIsEnabled(b));
  EXPECT_EQ(MdtWorldGetPartitionCount(w), 1);
}

TEST(AutoDisable, RestingBodySleepsAndForceWaitsForEnable) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtBodyID box = bodyAt(w, 0, (MeReal)0.5, 0);
  squareGroup(w, box, nullptr, 0, 0, MdtContactTypeFrictionZero);
  int slept = -1;
  for (int i = 0; i < 200 && slept < 0; ++i) {
    MdtWorldStep(w, (MeReal)0.01);
    if (!MdtBodyIsEnabled(box)) slept = i;
  }
  ASSERT_GE(slept, 0) << "never went to sleep";
  // Rested for the alive window (0.2 s) before sleeping.
  EXPECT_GE(slept + 1, 20);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  // A force on a sleeping body waits (the guide's Q&A reading, selected
  // here; by default a force this large wakes it: MdtWorld.h).
  MdtWorldSetWakeByForce(w, 0);
  MdtBodyAddForce(box, 100, 0, 0);
  MeVector3 x0, x1;
  MdtBodyGetPosition(box, x0);
  for (int i = 0; i < 10; ++i) MdtWorldStep(w, (MeReal)0.01);
  MdtBodyGetPosition(box, x1);
  EXPECT_EQ(x0[0], x1[0]);
  MeVector3 f;
  MdtBodyGetForce(box, f);
  EXPECT_EQ(f[0], 100);
  // ... until it is enabled: the stored force acts in the next step
  // (frictionless: dv = F h / m = 1).
  MdtBodyEnable(box);
  MdtWorldStep(w, (MeReal)0.01);
  MeVector3 v;
  MdtBodyGetLinearVelocity(box, v);
  EXPECT_NEAR(v[0], 1, 1e-5);
}

TEST(AutoDisable, ContactFromEnabledBodyWakesASleeper) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtBodyID box = bodyAt(w, 0, (MeReal)0.5, 0);
  squareGroup(w, box, nullptr, 0, 0, MdtContactTypeFrictionZero);
  for (int i = 0; i < 100; ++i) MdtWorldStep(w, (MeReal)0.01);
  ASSERT_FALSE(MdtBodyIsEnabled(box));
  MdtBodyID ball = bodyAt(w, 0, (MeReal)1.5, 0);
  MdtBodySetLinearVelocity(ball, 0, -1, 0);
  MdtContactID c = MdtContactCreate(w);
  MdtContactSetBodies(c, ball, box);
  MdtContactSetPosition(c, 0, 1, 0);
  MdtContactSetNormal(c, 0, 1, 0);
  MdtContactEnable(c);
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_TRUE(MdtBodyIsEnabled(box));
}

TEST(AutoDisable, OffKeepsBodiesAwake) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID box = bodyAt(w, 0, (MeReal)0.5, 0);
  squareGroup(w, box, nullptr, 0, 0, MdtContactTypeFrictionZero);
  for (int i = 0; i < 200; ++i) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_TRUE(MdtBodyIsEnabled(box));
}

namespace {

// Box a on the world (4 contacts, depths 0.010..0.013), box b on a (4
// contacts, depths 0.020..0.023), both Friction2D: 24 rows in one partition.
struct Stack {
  MdtBodyID a, b;
  MdtContactGroupID ga, gb;
  Stack(MdtWorldID w) {
    a = bodyAt(w, 0, (MeReal)0.5, 0);
    b = bodyAt(w, 0, (MeReal)1.5, 0);
    ga = squareGroup(w, a, nullptr, 0, (MeReal)0.010, MdtContactTypeFriction2D, (MeReal)0.001);
    gb = squareGroup(w, b, a, 1, (MeReal)0.020, MdtContactTypeFriction2D, (MeReal)0.001);
  }
  // Which contacts of a group still carried force in the last step.
  static std::vector<bool> carrying(MdtContactGroupID grp) {
    std::vector<bool> out;
    for (MdtContactID c = MdtContactGroupGetFirstContact(grp); c; c = MdtContactGroupGetNextContact(grp, c))
      out.push_back(MdtContactGetNormalForce(c) > 0);
    return out;
  }
};

}  // namespace

TEST(MatrixCapping, RemovesFrictionThenBodyContactsThenWorldContacts) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  Stack s(w);
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 24);

  MdtWorldSetMaxMatrixSize(w, 20);  // four friction rows go
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 20);

  MdtWorldSetMaxMatrixSize(w, 8);  // all 16 friction rows go, normals stay
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 8);
  EXPECT_EQ(Stack::carrying(s.ga), std::vector<bool>(4, true));
  EXPECT_EQ(Stack::carrying(s.gb), std::vector<bool>(4, true));

  MdtWorldSetMaxMatrixSize(w, 5);  // body-body contacts go first, shallowest first
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 5);
  EXPECT_EQ(Stack::carrying(s.ga), std::vector<bool>(4, true));
  EXPECT_EQ(Stack::carrying(s.gb), (std::vector<bool>{false, false, false, true}));

  MdtWorldSetMaxMatrixSize(w, 1);  // every group keeps its deepest contact
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 2);
  EXPECT_EQ(Stack::carrying(s.ga), (std::vector<bool>{false, false, false, true}));
  MdtWorldStepStats st;
  MdtWorldGetStepStats(w, &st);
  EXPECT_EQ(st.rowsRemoved, 22);
}

TEST(MatrixCapping, JointRowsAreNeverRemoved) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  Stack s(w);
  MdtBSJointID j = MdtBSJointCreate(w);
  MdtBSJointSetBodies(j, s.a, s.b);
  MdtBSJointSetPosition(j, 0, 1, 0);
  MdtBSJointEnable(j);
  MdtWorldSetMaxMatrixSize(w, 1);
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetPartitionRowCount(w, 0), 3 + 2);
}

namespace {
MeReal MEAPI deepestFirst(MdtContactID c) { return -MdtContactGetPenetration(c); }
}  // namespace

TEST(MatrixCapping, ImportanceCallbackReplacesDepthOrder) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  Stack s(w);
  MdtWorldSetContactImportanceCB(w, deepestFirst);
  MdtWorldSetMaxMatrixSize(w, 5);
  MdtWorldStep(w, (MeReal)0.01);
  // Now the deepest body-body contacts are the least important.
  EXPECT_EQ(Stack::carrying(s.gb), (std::vector<bool>{true, false, false, false}));
}

namespace {

// Six boxes: a chain of four hanging from a hinge, two resting on the
// ground with friction, one of them hit by the chain's end. Built with
// every body and constraint given a sort key; `reversed` creates them in
// the opposite order. Returns the bodies in key order.
std::vector<MdtBodyID> buildScene(MdtWorldID w, bool reversed) {
  const int nb = 6;
  std::vector<MdtBodyID> bodies((size_t)nb);
  for (int k = 0; k < nb; ++k) {
    const int i = reversed ? nb - 1 - k : k;
    MdtBodyID b = MdtBodyCreate(w);
    if (i < 4)
      MdtBodySetPosition(b, (MeReal)0.6 * (MeReal)i, 2, 0);  // horizontal chain
    else
      MdtBodySetPosition(b, (MeReal)(i - 3) * (MeReal)1.2, (MeReal)0.5, (MeReal)0.2);
    MdtBodySetSortKey(b, i);
    MdtBodyEnable(b);
    bodies[(size_t)i] = b;
  }
  std::vector<MdtConstraintID> made;
  const int nc = 6;
  for (int k = 0; k < nc; ++k) {
    const int i = reversed ? nc - 1 - k : k;
    MdtConstraintID c;
    if (i == 0) {
      MdtHingeID h = MdtHingeCreate(w);
      MdtHingeSetBodies(h, bodies[0], nullptr);
      MdtHingeSetPosition(h, -(MeReal)0.3, 2, 0);
      MdtHingeSetAxis(h, 0, 0, 1);
      c = MdtHingeQuaConstraint(h);
    } else if (i < 4) {
      MdtBSJointID j = MdtBSJointCreate(w);
      MdtBSJointSetBodies(j, bodies[(size_t)i], bodies[(size_t)i - 1]);
      MdtBSJointSetPosition(j, (MeReal)0.6 * (MeReal)i - (MeReal)0.3, 2, 0);
      c = MdtBSJointQuaConstraint(j);
    } else {
      MdtContactGroupID grp = squareGroup(w, bodies[(size_t)i], nullptr, 0, 0, MdtContactTypeFriction2D);
      MdtContactGroupDisable(grp);
      for (MdtContactID k2 = MdtContactGroupGetFirstContact(grp); k2; k2 = MdtContactGroupGetNextContact(grp, k2)) {
        MdtContactParamsSetFriction(MdtContactGetParams(k2), 3);
        MdtContactParamsSetRestitution(MdtContactGetParams(k2), (MeReal)0.3);
      }
      c = MdtContactGroupQuaConstraint(grp);
    }
    MdtConstraintSetSortKey(c, 100 + i);
    MdtConstraintEnable(c);
    made.push_back(c);
  }
  // The chain's last link leans on box 4.
  MdtContactID touch = MdtContactCreate(w);
  MdtContactSetBodies(touch, bodies[3], bodies[4]);
  MdtContactSetPosition(touch, (MeReal)1.8, (MeReal)1.0, 0);
  MdtContactSetNormal(touch, 0, 1, 0);
  MdtContactSetSortKey(touch, 200);
  MdtContactEnable(touch);
  return bodies;
}

std::uint64_t runScene(bool reversed, int steps) {
  World w(16, 1, 1, 64);
  MdtWorldSetGravity(w, 0, -g, 0);
  std::vector<MdtBodyID> bodies = buildScene(w, reversed);
  for (int i = 0; i < steps; ++i) {
    MdtBodyAddForce(bodies[5], (MeReal)(i % 50 == 0 ? 40 : 0), 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
  }
  for (MdtBodyID b : bodies) EXPECT_TRUE(bodyFinite(b));
  return karma_test::HashBodies(bodies);
}

}  // namespace

TEST(Determinism, SortKeysMakeCreationOrderIrrelevant) {
  const std::uint64_t forward = runScene(false, 600);
  const std::uint64_t again = runScene(false, 600);
  const std::uint64_t reversed = runScene(true, 600);
  std::printf("state hash after 600 steps: 0x%016llx\n", (unsigned long long)forward);
  EXPECT_EQ(forward, again);
  EXPECT_EQ(forward, reversed);
}
