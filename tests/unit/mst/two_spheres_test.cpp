// The guide's "Two Spheres Colliding" walk-through (lines 728-831), step by
// step through the bridge's own loop: five stages, each with the pair state,
// the contact group and the partitions the guide describes.
#include "mst_test_support.h"

#include <string>
#include <vector>

using namespace mst_test;

namespace {

struct Stage {
  std::string pair;  // "none", "hello", "staying", "goodbye"
  bool group;        // a contact group exists after the collisions
  int contacts;      // its contacts
  int partitions;    // after MdtWorldStep
  bool operator==(const Stage &o) const {
    return pair == o.pair && group == o.group && (contacts > 0) == (o.contacts > 0) && partitions == o.partitions;
  }
};

std::string Describe(const Stage &s) {
  return s.pair + (s.group ? " group" : " no-group") + (s.contacts > 0 ? " touching" : "") +
         " partitions=" + std::to_string(s.partitions);
}

// One MstUniverseStep with the bridge's loop written out, observed.
Stage ObservedStep(MstUniverseID u, McdModelPair **seen) {
  Stage st{"none", false, 0, 0};
  McdSpaceUpdateAll(u->space);
  McdSpaceEndChanges(u->space);
  McdModelPairContainer *pairs = McdModelPairContainerCreate(4);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(u->space, &it);
  McdModelPairContainerReset(pairs);
  EXPECT_EQ(McdSpaceGetPairs(u->space, &it, pairs), 0);
  McdModelPair *pair = nullptr;
  if (pairs->goodbyeEnd > pairs->goodbyeFirst) st.pair = "goodbye", pair = pairs->array[0];
  if (pairs->helloEnd > pairs->helloFirst) st.pair = "hello", pair = pairs->array[pairs->helloFirst];
  if (pairs->stayingEnd > pairs->stayingFirst) st.pair = "staying", pair = pairs->array[pairs->stayingFirst];
  if (pair) {
    if (*seen) {
      EXPECT_EQ(pair, *seen);  // one McdModelPair from hello to goodbye
    }
    *seen = pair;
  }
  MstHandleTransitions(pairs);
  MstHandleCollisions(pairs, u->space, u->world, u->bridge);
  if (pair && pair->responseData) {
    st.group = true;
    st.contacts = MdtContactGroupGetCount(static_cast<MdtContactGroupID>(pair->responseData));
  }
  McdSpaceBeginChanges(u->space);
  McdModelPairContainerDestroy(pairs);
  MdtWorldStep(u->world, (MeReal)0.05);
  st.partitions = MdtWorldGetPartitionCount(u->world);
  return st;
}

}  // namespace

TEST(MstTwoSpheres, TheGuidesFiveStages) {
  Scene s(false);
  MdtWorldSetGravity(s.u->world, 0, 0, 0);
  MdtWorldSetAutoDisable(s.u->world, FALSE);
  MdtContactParamsID p = MstBridgeGetContactParams(s.u->bridge, 0, 0);
  MdtContactParamsSetType(p, MdtContactTypeFrictionZero);
  MdtContactParamsSetRestitution(p, 1);
  // Unit spheres offset by 1 in y: the AABBs overlap for |dx| <= 2, the
  // spheres touch for |dx| <= sqrt(3).
  McdModelID a = s.ball(1, (MeReal)-1.55, (MeReal)-0.5, 0);
  McdModelID b = s.ball(1, (MeReal)1.55, (MeReal)0.5, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(a), 1, 0, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(b), -1, 0, 0);

  std::vector<Stage> stages;
  McdModelPair *seen = nullptr;
  for (int i = 0; i < 80; ++i) {
    const Stage st = ObservedStep(s.u, &seen);
    // Stage 2 may last several steps: its hello, then staying while apart.
    const bool stillStage2 = !stages.empty() && stages.back().pair == "hello" && st.pair == "staying" && !st.group;
    if (!stillStage2 && (stages.empty() || !(stages.back() == st))) stages.push_back(st);
  }
  const std::vector<Stage> guide = {
      {"none", false, 0, 2},     // 1. AABBs apart
      {"hello", false, 0, 2},    // 2. AABBs overlap, spheres apart: no contacts
      {"staying", true, 1, 1},   // 3. touching: a group with contacts, one partition
      {"staying", true, 0, 2},   // 4. moving apart: the group's contacts removed
      {"goodbye", false, 0, 2},  // 5. AABBs apart: the group destroyed
      {"none", false, 0, 2},
  };
  std::string got;
  for (const Stage &st : stages) got += Describe(st) + "; ";
  ASSERT_EQ(stages.size(), guide.size()) << got;
  for (size_t i = 0; i < guide.size(); ++i) EXPECT_EQ(stages[i], guide[i]) << "stage " << i + 1 << ": " << got;
  // The spheres rebounded (restitution 1, no friction): moving apart in x.
  MeVector3 va;
  MdtBodyGetLinearVelocity(McdModelGetBody(a), va);
  EXPECT_LT(va[0], 0);
}
