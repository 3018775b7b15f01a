// The state hash of each anchor scene on each platform backend, pinned
// (issue 18): every backend computes the reference's bits (kernels.h: no
// FMA, one lane order), so one pinned hash per scene and precision holds for
// all of them. Each (scene, backend) runs anchor_scene_hash in its own
// process with KARMA_PLATFORM=<backend>, for the backends of the cache
// option KARMA_GOLDEN_BACKENDS (ANCHOR_HASH_BACKENDS; the asan preset keeps
// the reference only); a backend this CPU lacks is skipped.
//
// The pinned hashes change whenever the step's arithmetic does (a new
// reduction order in Kea, a solver change): after such a change, rerun this
// test, check that every backend still agrees with the others, and update
// kPinned below (the failure message prints the new value).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "MePrecision.h"
#include "kernels.h"

namespace {

struct PinnedHash {
  const char *scene;
  int steps;               // from the start: the scene's whole run (pile1000: its first second)
  const char *hashSingle;  // MeReal = float
  const char *hashDouble;  // MeReal = double
};

// clang-format off
constexpr PinnedHash kPinned[] = {
    {"car",      300,  "0x95271ad45448d9e1", "0xbbcbb8bf8896052c"},
    {"topple",   600,  "0xea8a587b223cedc2", "0x24623ef175b2134c"},
    {"ragdoll",  600,  "0x87a6ac4806cc8906", "0x328bc835f5af19c7"},
    {"stack21",  1200, "0x68c37f6269bb1051", "0x8cd2312c0f1ca41d"},
    {"pile1000", 60,   "0xb0879d880f4aabd4", "0xc1e9070c093ddfbd"},
};
// clang-format on

const char *PinnedFor(const PinnedHash &p) { return KARMA_DOUBLE ? p.hashDouble : p.hashSingle; }

struct SceneRun {
  bool ok = false;
  std::string backend, hash, output;
};

// Runs anchor_scene_hash SCENE STEPS with KARMA_PLATFORM=backend.
SceneRun RunScene(const PinnedHash &p, const std::string &backend) {
  const std::string command =
      "KARMA_PLATFORM=" + backend + " '" + ANCHOR_SCENE_HASH + "' " + p.scene + " " + std::to_string(p.steps) + " 2>&1";
  SceneRun run;
  FILE *pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char line[256];
  while (std::fgets(line, sizeof line, pipe)) {
    run.output += line;
    char word[128];
    if (std::sscanf(line, "backend %127s", word) == 1) run.backend = word;
    if (std::sscanf(line, "state hash %127s", word) == 1) run.hash = word;
  }
  run.ok = pclose(pipe) == 0;
  return run;
}

// ANCHOR_HASH_BACKENDS, "reference,sse4,...", as a list.
std::vector<std::string> Backends() {
  std::vector<std::string> out;
  std::istringstream in(ANCHOR_HASH_BACKENDS);
  for (std::string name; std::getline(in, name, ',');)
    if (!name.empty()) out.push_back(name);
  return out;
}

using Param = std::tuple<int, std::string>;  // index into kPinned, backend

class AnchorHash : public ::testing::TestWithParam<Param> {};

TEST_P(AnchorHash, MatchesPinnedValue) {
  const PinnedHash &p = kPinned[std::get<0>(GetParam())];
  const std::string &backend = std::get<1>(GetParam());
  const karma::platform::Kernels *k = karma::platform::FindKernels(backend.c_str());
  ASSERT_NE(k, nullptr) << backend;
  if (!karma::platform::Supported(*k))
    GTEST_SKIP() << "this CPU does not support the platform backend '" << backend << "'";
  const SceneRun run = RunScene(p, backend);
  ASSERT_TRUE(run.ok) << run.output;
  EXPECT_EQ(run.backend, backend) << "the process did not run the backend it asked for:\n" << run.output;
  EXPECT_EQ(run.hash, PinnedFor(p)) << p.scene << ", " << p.steps << " steps, backend " << backend
                                    << ": update kPinned when the step's arithmetic changed on purpose";
}

std::string ParamName(const ::testing::TestParamInfo<Param> &info) {
  return std::string(kPinned[std::get<0>(info.param)].scene) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, AnchorHash,
                         ::testing::Combine(::testing::Range(0, static_cast<int>(std::size(kPinned))),
                                            ::testing::ValuesIn(Backends())),
                         ParamName);

// Every backend the build asks for exists.
TEST(AnchorHashBackends, AreKnown) {
  ASSERT_FALSE(Backends().empty());
  for (const std::string &name : Backends()) EXPECT_NE(karma::platform::FindKernels(name.c_str()), nullptr) << name;
}

}  // namespace
