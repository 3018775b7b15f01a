// constraint_slots_test.cpp: a world's constraint slots grow when full
// (constraint_slots.cpp): every constraint is made, keeps its address, is
// counted and walked, the growth is reported once, and destroying frees
// slots for reuse before the world grows again.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "Mdt.h"
#include "support/warning_capture.h"

namespace {

TEST(ConstraintSlots, AFullWorldGrowsOnceReportedAndKeepsEveryConstraint) {
  MdtWorldID world = MdtWorldCreate(2, 4, 1, 1);
  MdtBodyID a = MdtBodyCreate(world), b = MdtBodyCreate(world);
  karma_test::WarningCapture warnings;
  std::vector<MdtBSJointID> joints;
  for (int i = 0; i < 40; ++i) {
    MdtBSJointID j = MdtBSJointCreate(world);
    ASSERT_NE(j, nullptr) << "joint " << i;
    MdtBSJointSetBodies(j, a, b);
    MdtBSJointSetPosition(j, (MeReal)i, 0, 0);
    joints.push_back(j);
  }
  EXPECT_EQ(warnings.count(), 1u);  // grown from 4 to 8, 16, 32, 64: one report
  EXPECT_EQ(MdtWorldGetConstraintCount(world), 40u);
  EXPECT_EQ(MdtWorldGetMaxConstraints(world), 4u);  // as created
  // Addresses kept: each joint still has its own position.
  for (int i = 0; i < 40; ++i) {
    MeVector3 p;
    MdtBSJointGetPosition(joints[(size_t)i], p);
    EXPECT_EQ(p[0], (MeReal)i);
  }
  // Destroying frees slots; new joints take them without another report.
  for (int i = 0; i < 40; i += 2) MdtBSJointDestroy(joints[(size_t)i]);
  EXPECT_EQ(MdtWorldGetConstraintCount(world), 20u);
  for (int i = 0; i < 20; ++i) EXPECT_NE(MdtBSJointCreate(world), nullptr);
  EXPECT_EQ(MdtWorldGetConstraintCount(world), 40u);
  EXPECT_EQ(warnings.count(), 1u);
  MdtWorldDestroy(world);
}

TEST(ConstraintSlots, ContactsInGrownSlotsAreFoundFromTheirBody) {
  MdtWorldID world = MdtWorldCreate(2, 2, 1, 1);
  MdtBodyID a = MdtBodyCreate(world), b = MdtBodyCreate(world);
  karma_test::WarningCapture warnings;
  std::set<MdtContactID> made;
  for (int i = 0; i < 10; ++i) {
    MdtContactID c = MdtContactCreate(world);
    ASSERT_NE(c, nullptr);
    MdtContactSetBodies(c, a, b);
    MdtContactEnable(c);
    made.insert(c);
  }
  std::set<MdtContactID> found;
  for (MdtContactID c = MdtBodyGetFirstContact(a); c; c = MdtBodyGetNextContact(a, c)) found.insert(c);
  EXPECT_EQ(found, made);
  MdtWorldDestroy(world);
}

}  // namespace
