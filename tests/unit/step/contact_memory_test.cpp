// Contacts with memory (engine/mst/contact_cache.h): a contact the
// collision reports again keeps its MdtContact, its place in the group and
// its impulses; new contacts start from zero; lost ones go.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact_internal.h"
#include "mdt_bridge.h"
#include "step_scene.h"
#include "support/warning_capture.h"

namespace {

using karma_test::WarningCapture;
using step_test::Contacts;
using step_test::kG;
using step_test::kH;
using step_test::Scene;

// A 1 m box of `mass` kg resting on the ground, settled for `steps`.
McdModelID RestingBox(Scene &s, MeReal mass, int steps) {
  McdModelID b = s.box(1, 1, 1, 0, (MeReal)0.5, 0, mass);  // density = mass for 1 m^3
  s.step(steps);
  return b;
}

TEST(ContactMemory, ARestingBoxKeepsItsFourContactsAndTheirOrder) {
  Scene s;
  McdModelID b = RestingBox(s, 10, 30);
  MdtContactID first[8], later[8];
  const int n = Contacts(b, first, 8);
  ASSERT_EQ(n, 4);
  for (int i = 0; i < 50; ++i) {
    s.step();
    ASSERT_EQ(Contacts(b, later, 8), 4) << "step " << i;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(later[k], first[k]) << "step " << i << ", contact " << k;
  }
}

// Two aligned boxes of one size, stacked: their corners coincide, and
// rounding decides from step to step which box's vertex names a corner.
// The contacts are the same points whatever their names (the matching
// rule's pass 3), so they keep their MdtContacts, and each step the resting
// stack's exact solve is either one linear solve (with a fresh or a kept
// factorisation, KeaOptions::factorMemory) or none, its warm start kept
// (MdtWorldSetKeaAcceptWarmStart).
TEST(ContactMemory, CoincidentCornersKeepTheirContactsWhenRenamed) {
  Scene s;
  McdModelID lower = s.box(1, 1, 1, 0, (MeReal)0.5, 0);
  McdModelID upper = s.box(1, 1, 1, 0, (MeReal)1.5, 0);
  (void)lower;
  s.step(60);
  MdtContactID first[8], later[8];
  ASSERT_EQ(Contacts(upper, first, 8), 4);
  int solves = 0, steps = 0, factorizations = 0, staleSolves = 0, warmStarts = 0;
  for (int i = 0; i < 60; ++i, ++steps) {
    s.step();
    ASSERT_EQ(Contacts(upper, later, 8), 4) << "step " << i;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(later[k], first[k]) << "step " << i << ", contact " << k;
    MdtWorldStepStats stats;
    MdtWorldGetStepStats(s.u->world, &stats);
    EXPECT_EQ(stats.keaSolved, stats.partitions) << "step " << i;
    solves += stats.keaIterations;
    factorizations += stats.keaFactorizations;
    staleSolves += stats.keaStaleSolves;
    warmStarts += stats.keaWarmStarts;
  }
  EXPECT_EQ(solves + warmStarts, steps);  // one partition: one solve a step, or its warm start kept
  EXPECT_EQ(staleSolves + factorizations + warmStarts, steps);
}

TEST(ContactMemory, TheImpulsesOfARestingBoxAreItsWeightShared) {
  Scene s;
  const MeReal mass = 10;
  McdModelID b = RestingBox(s, mass, 60);
  MdtContactID c[8];
  const int n = Contacts(b, c, 8);
  ASSERT_EQ(n, 4);
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    MeVector3 friction;
    const MeReal normal = MdtContactGetImpulse(c[k], friction);
    EXPECT_GT(normal, 0);
    EXPECT_LT(MeVector3Magnitude(friction), 1e-3 * mass * kG * kH);  // nothing pushes sideways
    EXPECT_NEAR(normal, MdtContactGetNormalForce(c[k]) * kH, 1e-5 * mass * kG * kH);
    sum += normal;
  }
  // The four impulses carry the weight over the step: m g h, within 0.5%.
  EXPECT_NEAR(sum, mass * kG * kH, 5e-3 * mass * kG * kH);
}

TEST(ContactMemory, ClearedImpulsesAreZeroAndTheNextStepRestoresThem) {
  Scene s;
  McdModelID b = RestingBox(s, 10, 60);
  MdtContactID c[8];
  ASSERT_EQ(Contacts(b, c, 8), 4);
  const MeReal before = MdtContactGetImpulse(c[0], nullptr);
  MdtContactClearImpulse(c[0]);
  EXPECT_EQ(MdtContactGetImpulse(c[0], nullptr), 0);
  s.step();
  EXPECT_NEAR(MdtContactGetImpulse(c[0], nullptr), before, 1e-3 * std::fabs(before));
}

TEST(ContactMemory, ANewContactStartsFromZeroAndALostOneIsDestroyed) {
  Scene s;
  // A ball rolling off a block's edge: it loses the block, then meets the
  // ground with a new contact.
  McdModelID ball = s.ball((MeReal)0.25, 0, 3, 0);
  s.step(1);
  MdtContactID c[8];
  EXPECT_EQ(Contacts(ball, c, 8), 0);  // in the air
  int steps = 0;
  while (Contacts(ball, c, 8) == 0 && steps < 200) {
    s.step();
    ++steps;
  }
  ASSERT_EQ(Contacts(ball, c, 8), 1);
  // Its first solve started from zero, so its memory now is this step's.
  EXPECT_GE(MdtContactGetImpulse(c[0], nullptr), 0);
  MdtBodySetLinearVelocity(McdModelGetBody(ball), 0, 20, 0);  // thrown up
  s.step(3);
  EXPECT_EQ(Contacts(ball, c, 8), 0);
}

TEST(ContactMemory, FeaturesComeFromTheCollision) {
  Scene s;
  McdModelID b = RestingBox(s, 10, 10);
  MdtContactID c[8];
  ASSERT_EQ(Contacts(b, c, 8), 4);
  // Each contact knows which features made it; a face-on-plane rest has a
  // distinct identity per corner, or none at all (then position matches).
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (MdtContactGetFeature(c[i]) != 0) {
        EXPECT_NE(MdtContactGetFeature(c[i]), MdtContactGetFeature(c[j]));
      }
}

TEST(ContactMemory, BadArgumentsWarnAndDoNothing) {
  WarningCapture warnings;
  MeVector3 f = {1, 2, 3};
  EXPECT_EQ(MdtContactGetImpulse(nullptr, f), 0);
  EXPECT_EQ(f[0], 1);  // untouched
  EXPECT_EQ(MdtContactGetFeature(nullptr), 0u);
  MdtContactClearImpulse(nullptr);
  MdtContactSetFeature(nullptr, 7);
  EXPECT_EQ(warnings.count(), 4u);
  EXPECT_TRUE(warnings.saw("MdtContactGetImpulse"));
}

}  // namespace

// The prefetch hints of a contact group (contact_internal.h) name its
// first min(count, kContactHints) contacts in list order through appends,
// removals from the front, the middle and the end, growth past the hint
// array, and a list relinked by hand (MdtContactSetNext).
namespace {

void ExpectHintsAreTheFirstContacts(MdtContactGroupID g) {
  const MdtContactGroup *group = g;
  int j = 0;
  for (MdtContactID k = MdtContactGroupGetFirstContact(g); k && j < karma::mdt::kContactHints;
       k = MdtContactGroupGetNextContact(g, k), ++j)
    EXPECT_EQ(group->hint[j], k) << "hint " << j;
  EXPECT_EQ(j, std::min(MdtContactGroupGetCount(g), karma::mdt::kContactHints));
}

TEST(ContactMemory, AGroupsPrefetchHintsAreItsFirstContactsInOrder) {
  MdtWorldID w = MdtWorldCreate(4, 64, 1, 1);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, b);
  MdtContactID made[12];
  for (int i = 0; i < 12; ++i) {
    made[i] = MdtContactGroupCreateContact(g);
    ASSERT_NE(made[i], nullptr);
    ExpectHintsAreTheFirstContacts(g);
  }
  MdtContactGroupDestroyContact(g, made[0]);  // the front
  ExpectHintsAreTheFirstContacts(g);
  MdtContactGroupDestroyContact(g, made[5]);  // the middle, within the hints
  ExpectHintsAreTheFirstContacts(g);
  MdtContactGroupRemoveContact(g, made[11]);  // the end, beyond the hints
  ExpectHintsAreTheFirstContacts(g);
  MdtContactSetNext(made[2], made[4]);  // made[3] unlinked by hand
  ExpectHintsAreTheFirstContacts(g);
  MdtContactSetNext(made[2], made[3]);  // and linked back
  ExpectHintsAreTheFirstContacts(g);
  for (int i : {1, 2, 3, 4, 6, 7, 8, 9, 10}) MdtContactGroupDestroyContact(g, made[i]);
  EXPECT_EQ(MdtContactGroupGetCount(g), 0);
  ExpectHintsAreTheFirstContacts(g);
  MdtContactGroupAppendContact(g, made[11]);
  ExpectHintsAreTheFirstContacts(g);
  MdtWorldDestroy(w);
}

// The bridge's prefetches take any group, a NULL one, or a constraint that
// is not a group, and change nothing (run under the sanitizers in CI).
TEST(ContactMemory, ThePrefetchesAcceptNullAndOtherConstraints) {
  MdtWorldID w = MdtWorldCreate(4, 64, 1, 1);
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodyEnable(a);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  MdtContactGroupCreateContact(g);
  MdtContactID alone = MdtContactCreate(w);
  MdtContactGroupPrefetch(nullptr);
  MdtContactGroupPrefetchContacts(nullptr);
  MdtContactGroupPrefetch(g);
  MdtContactGroupPrefetchContacts(g);
  MdtContactGroupPrefetchContacts(reinterpret_cast<MdtContactGroupID>(alone));
  EXPECT_EQ(MdtContactGroupGetCount(g), 1);
  MdtContactGroupDestroy(g);
  MdtWorldStep(w, kH);
  MdtWorldDestroy(w);
}

}  // namespace

namespace {

// Every constraint slot starts on a cache line (kConstraintSlotAlignment),
// in the first pool and in the pools the world grows, and in single
// precision the contact fields every step touches, from the normal to the
// warm memory, lie in one line, after the params' own (contact_internal.h).
TEST(ContactMemory, ContactSlotsStartOnALineAndKeepTheirStepFieldsInOne) {
  MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
  MdtBodyID a = MdtBodyCreate(w);
  MdtContactGroupID g = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(g, a, nullptr);
  WarningCapture grown;  // a world of 4 constraints grows its pools below
  std::vector<MdtContactID> made;
  for (int i = 0; i < 40; ++i) made.push_back(MdtContactGroupCreateContact(g));
  EXPECT_TRUE(grown.saw("MdtWorld"));
  for (MdtContactID k : made) {
    ASSERT_NE(k, nullptr);
    const auto at = [](const void *p) { return reinterpret_cast<std::uintptr_t>(p); };
    EXPECT_EQ(at(k) % karma::mdt::kConstraintSlotAlignment, 0u);
    EXPECT_EQ(at(&k->params) % 64, 0u);
    if (sizeof(MeReal) == 4) {
      EXPECT_EQ(at(&k->normal) / 64, at(&k->warmFriction[2]) / 64);
      EXPECT_EQ(at(&k->normal) / 64, at(&k->frictionAxis[2]) / 64);
      EXPECT_EQ(at(&k->normal) / 64, at(&k->next) / 64);
    }
    // Every line from the params to the end of the warm memory is one the
    // group's prefetch names (contact_group.cpp; two more in double).
    std::vector<std::uintptr_t> named = {at(&k->params) / 64, at(&k->normal) / 64};
    if (sizeof(MeReal) > 4) named.insert(named.end(), {at(&k->next) / 64, at(&k->warmFriction[2]) / 64});
    for (std::uintptr_t line = at(&k->params) / 64; line <= at(&k->warmFriction[2]) / 64; ++line)
      EXPECT_NE(std::find(named.begin(), named.end(), line), named.end()) << "line " << line;
  }
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(&g->first) % 64, 0u);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(&g->first) / 64, reinterpret_cast<std::uintptr_t>(&g->hint[0]) / 64);
  MdtWorldDestroy(w);
}

}  // namespace
