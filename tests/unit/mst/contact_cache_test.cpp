// The contact matching rule (engine/mst/contact_cache.h) when the world's
// constraint pool has no room for a new contact: the new contacts without
// room are dropped, and every contact matched to an old one is still
// brought to this step's position, normal and depth.
#include <gtest/gtest.h>

#include <cstring>

#include "MeMemory.h"
#include "Mst.h"
#include "contact_cache.h"
#include "../mcd/mcd_test_support.h"

namespace {

// MeMemoryAPI's allocators, failing while `failing` is set, so that the
// constraint pool cannot grow.
struct FailingAllocation {
  static inline bool failing = false;
  static inline void *(MEAPI *create)(size_t) = nullptr;
  static inline void *(MEAPI *createAligned)(size_t, unsigned) = nullptr;
  static inline void *(MEAPI *createZeroed)(size_t) = nullptr;
  static void *MEAPI Create(size_t n) { return failing ? nullptr : create(n); }
  static void *MEAPI CreateAligned(size_t n, unsigned a) { return failing ? nullptr : createAligned(n, a); }
  static void *MEAPI CreateZeroed(size_t n) { return failing ? nullptr : createZeroed(n); }
  FailingAllocation() {
    create = MeMemoryAPI.create;
    createAligned = MeMemoryAPI.createAligned;
    createZeroed = MeMemoryAPI.createZeroed;
    MeMemoryAPI.create = Create;
    MeMemoryAPI.createAligned = CreateAligned;
    MeMemoryAPI.createZeroed = CreateZeroed;
  }
  ~FailingAllocation() {
    failing = false;
    MeMemoryAPI.create = create;
    MeMemoryAPI.createAligned = createAligned;
    MeMemoryAPI.createZeroed = createZeroed;
  }
};

McdContact ContactAt(MeReal x, MeReal y, MeReal depth, MeU32 feature) {
  McdContact c;
  std::memset(&c, 0, sizeof c);
  c.position[0] = x;
  c.position[1] = y;
  c.normal[1] = 1;
  c.separation = -depth;
  c.feature = feature;
  return c;
}

}  // namespace

TEST(ContactCache, AFullPoolDropsNewContactsAndStillUpdatesTheKeptOnes) {
  FailingAllocation allocation;
  MdtWorldID w = MdtWorldCreate(4, 3, 1, 1);  // room for a group and two contacts
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, b, nullptr);
  MdtContactParams params;
  MdtContactParamsReset(&params);

  McdContact first[2] = {ContactAt(0, 0, (MeReal)0.01, 1), ContactAt(1, 0, (MeReal)0.01, 2)};
  McdIntersectResult r{};
  r.contacts = first;
  r.contactCount = r.contactMaxCount = 2;
  const karma::mst::MatchCounts made = karma::mst::MatchContacts(g, first, 2, 1, params, (MeReal)0.05, nullptr, &r);
  ASSERT_EQ(made.created, 2);

  // Next step: two new features first, then feature 2 moved and deeper.
  // Feature 1 goes, which frees one slot; the pool cannot grow for more.
  FailingAllocation::failing = true;
  mcd_test::WarningCapture warnings;
  McdContact second[3] = {ContactAt(5, 0, (MeReal)0.01, 7), ContactAt(6, 0, (MeReal)0.01, 8),
                          ContactAt(1, (MeReal)0.3, (MeReal)0.2, 2)};
  r.contacts = second;
  r.contactCount = r.contactMaxCount = 3;
  const karma::mst::MatchCounts counts = karma::mst::MatchContacts(g, second, 3, 1, params, (MeReal)0.05, nullptr, &r);
  FailingAllocation::failing = false;

  EXPECT_EQ(counts.removed, 1);
  EXPECT_EQ(counts.kept, 1);
  EXPECT_EQ(counts.created, 1);  // feature 7 takes the freed slot; feature 8 finds none
  EXPECT_EQ(MdtContactGroupGetCount(g), 2);
  bool sawKept = false;
  for (MdtContactID c = MdtContactGroupGetFirstContact(g); c; c = MdtContactGroupGetNextContact(g, c)) {
    MeVector3 p;
    MdtContactGetPosition(c, p);
    if (p[0] != 1) continue;
    sawKept = true;
    EXPECT_EQ(p[1], (MeReal)0.3);
    EXPECT_EQ(MdtContactGetPenetration(c), (MeReal)0.2);
  }
  EXPECT_TRUE(sawKept);
  EXPECT_GE(warnings.count(), 1u);
  MdtWorldDestroy(w);
}
