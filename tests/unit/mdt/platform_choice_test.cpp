// platform_choice_test.cpp: choosing the platform backend (MdtPlatform.h,
// MdtWorldSetPlatform): the list of backends, the process default and a
// world's own choice, the fallback with a warning for names that cannot be
// used, and the name the step stats and the diagnostics report.
#include "mdt_test_support.h"

#include <cstring>
#include <string>
#include <vector>

using namespace mdt_test;

namespace {

std::vector<std::string> AllNames() {
  std::vector<std::string> names;
  for (int i = 0; i < MdtPlatformCount(); ++i) names.emplace_back(MdtPlatformName(i));
  return names;
}

std::vector<std::string> SupportedNames() {
  std::vector<std::string> names;
  for (const std::string &n : AllNames())
    if (MdtPlatformIsSupported(n.c_str())) names.push_back(n);
  return names;
}

// The list is in increasing order of preference: the best is the last one
// the CPU supports.
std::string BestName() { return SupportedNames().back(); }

// A known backend this CPU cannot run, or "" when it runs them all.
std::string UnsupportedName() {
  for (const std::string &n : AllNames())
    if (!MdtPlatformIsSupported(n.c_str())) return n;
  return "";
}

// Restores the process default the test found.
class DefaultGuard {
 public:
  DefaultGuard() : saved_(MdtPlatformGetDefaultName()) {}
  ~DefaultGuard() { MdtPlatformSetDefault(saved_.c_str()); }
  DefaultGuard(const DefaultGuard &) = delete;
  DefaultGuard &operator=(const DefaultGuard &) = delete;

 private:
  std::string saved_;
};

TEST(MdtPlatform, ListsTheFourBackendsReferenceFirst) {
  const std::vector<std::string> names = AllNames();
  EXPECT_EQ(names, (std::vector<std::string>{"reference", "sse4", "avx2", "avx512"}));
  EXPECT_TRUE(MdtPlatformIsSupported("reference"));  // portable: every CPU
  EXPECT_FALSE(MdtPlatformIsSupported("neon"));
  EXPECT_FALSE(MdtPlatformIsSupported(""));
  EXPECT_FALSE(MdtPlatformIsSupported(nullptr));
  WarningCapture w;
  EXPECT_EQ(MdtPlatformName(-1), nullptr);
  EXPECT_EQ(MdtPlatformName(MdtPlatformCount()), nullptr);
  EXPECT_EQ(w.count(), 2u);
  EXPECT_TRUE(w.lastMentions("MdtPlatformName"));
}

TEST(MdtPlatform, TheDefaultAndTheBestAreSupported) {
  EXPECT_TRUE(MdtPlatformIsSupported(MdtPlatformGetDefaultName())) << MdtPlatformGetDefaultName();
  EXPECT_EQ(MdtPlatformGetBestName(), BestName());
}

TEST(MdtPlatform, AWorldStartsWithTheProcessDefaultAndKeepsItsOwn) {
  DefaultGuard guard;
  for (const std::string &name : SupportedNames()) {
    SCOPED_TRACE(name);
    World before;
    MdtWorldSetPlatform(before, "reference");
    WarningCapture w;
    MdtPlatformSetDefault(name.c_str());
    EXPECT_STREQ(MdtPlatformGetDefaultName(), name.c_str());
    World after;
    EXPECT_STREQ(MdtWorldGetPlatformName(after), name.c_str());
    EXPECT_STREQ(MdtWorldGetPlatformName(before), "reference");  // set before: unchanged
    EXPECT_EQ(w.count(), 0u);
  }
}

TEST(MdtPlatform, ADefaultThatCannotBeUsedWarnsAndTakesTheBest) {
  DefaultGuard guard;
  MdtPlatformSetDefault("reference");
  WarningCapture w;
  MdtPlatformSetDefault("neon");
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("'neon'")) << w.last();
  EXPECT_EQ(MdtPlatformGetDefaultName(), BestName());
  MdtPlatformSetDefault("reference");
  MdtPlatformSetDefault(nullptr);
  EXPECT_EQ(w.count(), 2u);
  EXPECT_EQ(MdtPlatformGetDefaultName(), BestName());
}

TEST(MdtWorldPlatform, SetAndGetRoundTripOnEverySupportedBackend) {
  World world;
  WarningCapture w;
  for (const std::string &name : SupportedNames()) {
    MdtWorldSetPlatform(world, name.c_str());
    EXPECT_STREQ(MdtWorldGetPlatformName(world), name.c_str());
  }
  EXPECT_EQ(w.count(), 0u) << w.last();
}

TEST(MdtWorldPlatform, AnUnknownNameWarnsAndTakesTheBest) {
  World world;
  MdtWorldSetPlatform(world, "reference");
  WarningCapture w;
  MdtWorldSetPlatform(world, "avx1024");
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("'avx1024'")) << w.last();
  EXPECT_TRUE(w.lastMentions("no backend by that name")) << w.last();
  EXPECT_EQ(MdtWorldGetPlatformName(world), BestName());
  MdtWorldSetPlatform(world, "reference");
  MdtWorldSetPlatform(world, nullptr);
  EXPECT_EQ(w.count(), 2u);
  EXPECT_EQ(MdtWorldGetPlatformName(world), BestName());
}

TEST(MdtWorldPlatform, ABackendTheCpuLacksWarnsAndTakesTheBest) {
  const std::string lacking = UnsupportedName();
  if (lacking.empty()) GTEST_SKIP() << "this CPU supports every backend: no unsupported one to ask for";
  World world;
  MdtWorldSetPlatform(world, "reference");
  WarningCapture w;
  MdtWorldSetPlatform(world, lacking.c_str());
  EXPECT_EQ(w.count(), 1u);
  EXPECT_TRUE(w.lastMentions("does not support")) << w.last();
  EXPECT_EQ(MdtWorldGetPlatformName(world), BestName());
  MdtPlatformSetDefault("reference");
  MdtPlatformSetDefault(lacking.c_str());
  EXPECT_EQ(w.count(), 2u);
  EXPECT_EQ(MdtPlatformGetDefaultName(), BestName());
}

TEST(MdtWorldPlatform, ANullWorldWarns) {
  WarningCapture w;
  MdtWorldSetPlatform(nullptr, "reference");
  EXPECT_TRUE(w.lastMentions("MdtWorldSetPlatform")) << w.last();
  EXPECT_EQ(MdtWorldGetPlatformName(nullptr), nullptr);
  EXPECT_TRUE(w.lastMentions("MdtWorldGetPlatformName")) << w.last();
  EXPECT_EQ(w.count(), 2u);
}

// The stats name the backend the last step ran on: a change takes effect
// at the next step; before the first step they name the world's choice.
TEST(MdtWorldPlatform, StepStatsNameTheBackendThatRan) {
  World world;
  MdtBodyID b = MdtBodyCreate(world);
  MdtBodyEnable(b);
  MdtWorldStepStats st;
  for (const std::string &name : SupportedNames()) {
    SCOPED_TRACE(name);
    MdtWorldSetPlatform(world, name.c_str());
    MdtWorldStep(world, (MeReal)0.01);
    MdtWorldGetStepStats(world, &st);
    EXPECT_STREQ(st.platform, name.c_str());
    MeDiagnosticFigures f;
    MdtWorldGetDiagnostics(world, &f);
    EXPECT_STREQ(f.platform, name.c_str());
  }
  MdtWorldSetPlatform(world, "reference");
  MdtWorldGetStepStats(world, &st);
  EXPECT_EQ(st.platform, SupportedNames().back());  // the last step's
  World fresh;
  MdtWorldSetPlatform(fresh, "reference");
  MdtWorldGetStepStats(fresh, &st);
  EXPECT_STREQ(st.platform, "reference");
}

}  // namespace
