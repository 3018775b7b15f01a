// platform_hash_test.cpp: the platform backends give bit-identical steps.
// Every backend computes the kernels' operations in the reference's order
// (engine/platform/kernels.h), so an anchor scene stepped on any backend
// this CPU supports ends in exactly the state it reaches on `reference`:
// the same state hash. A backend the CPU lacks is skipped, with a message.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "anchor_scene.h"
#include "support/state_hash.h"

namespace {

using SceneMaker = std::function<std::unique_ptr<karma::scenes::AnchorScene>()>;

// The state hash of every dynamic body after `steps` steps on `backend`,
// and the backend the step stats name.
std::uint64_t HashAfter(const SceneMaker &make, const char *backend, int steps, std::string &ran) {
  auto scene = make();
  MdtWorldSetPlatform(scene->world(), backend);
  for (int i = 0; i < steps; ++i) scene->step();
  MdtWorldStepStats st;
  MdtWorldGetStepStats(scene->world(), &st);
  ran = st.platform ? st.platform : "";
  std::vector<MdtBodyID> bodies;
  for (McdModelID m : scene->models()) bodies.push_back(McdModelGetBody(m));
  return karma_test::HashBodies(bodies);
}

class PlatformHash : public ::testing::TestWithParam<int> {
 protected:
  void ExpectSameAsReference(const SceneMaker &make, int steps) {
    const char *backend = MdtPlatformName(GetParam());
    ASSERT_NE(backend, nullptr);
    if (!MdtPlatformIsSupported(backend)) GTEST_SKIP() << "this CPU does not support the " << backend << " backend";
    std::string ran;
    const std::uint64_t reference = HashAfter(make, "reference", steps, ran);
    EXPECT_EQ(ran, "reference");
    EXPECT_EQ(HashAfter(make, backend, steps, ran), reference) << backend << " differs from reference";
    EXPECT_EQ(ran, backend);
  }
};

// Topple: six stacks of cubes settling, a partition each, solved exactly.
TEST_P(PlatformHash, ToppleMatchesTheReference) { ExpectSameAsReference(karma::scenes::MakeTopple, 150); }

// The rag doll: joints with limits, one partition.
TEST_P(PlatformHash, RagdollMatchesTheReference) { ExpectSameAsReference(karma::scenes::MakeRagdoll, 150); }

// pile1000's first second: 1,000 cubes landing, large partitions.
TEST_P(PlatformHash, PileMatchesTheReference) { ExpectSameAsReference(karma::scenes::MakePile1000, 60); }

std::string BackendName(const ::testing::TestParamInfo<int> &info) { return MdtPlatformName(info.param); }

INSTANTIATE_TEST_SUITE_P(EveryBackend, PlatformHash, ::testing::Range(0, 4), BackendName);

}  // namespace
