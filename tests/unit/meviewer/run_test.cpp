// run_test.cpp: RRun's loop and exit. Each run ends the process through
// exit(), so every test runs it in a death-test child and checks the exit
// status, what the child printed, and the files it left behind.
#include "viewer_test_support.h"

#include <karma/golden/Image.h>

#include "MdtPlatform.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

using viewer_test::MakeContext;
using viewer_test::TempDir;

namespace {

RRender *gRc = nullptr;
int gTicks = 0;
int gQuitAt = -1;

void MEAPI Tick(RRender *rc, void *userdata) {
  ++gTicks;
  if (userdata) *static_cast<int *>(userdata) += 1;
  if (gTicks == gQuitAt) RRenderQuit(rc);
}

void MEAPI_CDECL Cleanup() {
  std::fprintf(stderr, "cleanup after %d ticks\n", gTicks);
  RRenderContextDestroy(gRc);
}

// In the child: stdout joins stderr (the matcher reads stderr), the
// context is made, cleanup registered and RRun entered.
void RunChild(const std::string &commandLine, int quitAt = -1) {
  dup2(2, 1);
  gQuitAt = quitAt;
  gRc = MakeContext(commandLine);
  static int counter = 0;
  std::atexit(Cleanup);
  RRun(gRc, Tick, &counter);
}

class RunDeathTest : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(RunDeathTest, FramesEndsTheProgramThroughExitSoCleanupRuns) {
  EXPECT_EXIT(RunChild("prog -null -frames 3"), ::testing::ExitedWithCode(0), "cleanup after 3 ticks");
}

TEST_F(RunDeathTest, ZeroFramesRunsNoTick) {
  EXPECT_EXIT(RunChild("prog -null -frames 0"), ::testing::ExitedWithCode(0), "cleanup after 0 ticks");
}

TEST_F(RunDeathTest, RRenderQuitStopsAfterTheCurrentFrame) {
  EXPECT_EXIT(RunChild("prog -null -frames 100", 4), ::testing::ExitedWithCode(0), "cleanup after 4 ticks");
}

TEST_F(RunDeathTest, NullContextEndsWithStatusOne) {
  EXPECT_EXIT(RRun(nullptr, Tick, nullptr), ::testing::ExitedWithCode(1), "RRun: rc is NULL");
}

TEST_F(RunDeathTest, BenchPrintsFrameStatistics) {
  EXPECT_EXIT(RunChild("prog -bench -frames 5"), ::testing::ExitedWithCode(0),
              "MeViewer -bench: 5 frames\n  frame time \\(ms\\): mean");
}

TEST_F(RunDeathTest, ProfilePrintsAPhaseTable) {
  EXPECT_EXIT(RunChild("prog -profile -frames 2 -size 64x48"), ::testing::ExitedWithCode(0),
              "MeViewer -profile: 2 frames(.|\n)*render(.|\n)*frame");
}

// Without a dynamics world the line names the process default, so marked
// (a world's own backend is read through the diagnostic sources: the
// platform_choice tests of mdt_test check what a world reports).
TEST_F(RunDeathTest, ProfileNamesThePlatformBackend) {
  const std::string line = std::string("platform backend: ") + MdtPlatformGetDefaultName() + " \\(the process default";
  EXPECT_EXIT(RunChild("prog -profile -frames 2 -size 64x48"), ::testing::ExitedWithCode(0), line);
}

TEST_F(RunDeathTest, OutWritesNumberedPngsOfTheFrameSize) {
  TempDir dir("pngs");
  EXPECT_EXIT(RunChild("prog -frames 3 -size 64x48 -out " + dir.str()), ::testing::ExitedWithCode(0), "cleanup");
  for (int i = 0; i < 3; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    ASSERT_TRUE(std::filesystem::exists(dir.path() / name)) << name;
    const karma::golden::Image img = karma::golden::LoadPng(dir.path() / name);
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    // An empty scene is the background colour (0.2, 0.25, 0.35).
    EXPECT_NEAR(img.Pixel(10, 10)[0], 51, 1);
    EXPECT_NEAR(img.Pixel(10, 10)[2], 89, 1);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frame_00003.png"));
}

TEST_F(RunDeathTest, EveryAndBmpChooseWhichFramesAndTheFormat) {
  TempDir dir("bmps");
  EXPECT_EXIT(RunChild("prog -frames 5 -every 2 -bmp -size 32x32 -out " + dir.str()), ::testing::ExitedWithCode(0),
              "cleanup after 5 ticks");
  for (const char *name : {"frame_00000.bmp", "frame_00002.bmp", "frame_00004.bmp"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / name)) << name;
  for (const char *name : {"frame_00001.bmp", "frame_00003.bmp", "frame_00000.png"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() / name)) << name;
  EXPECT_EQ(std::filesystem::file_size(dir.path() / "frame_00000.bmp"), 54u + 32u * 32u * 3u);
}

extern "C" void ViewerCRunTwoArguments(RRender *rc);
extern "C" void ViewerCRunNoDataThreeArguments(RRender *rc);
extern "C" void ViewerCRunWithData(RRender *rc);

TEST_F(RunDeathTest, GuideTickAndRunFormsFromC) {
  EXPECT_EXIT(ViewerCRunTwoArguments(MakeContext("prog -null -frames 2")), ::testing::ExitedWithCode(0),
              "C tick without user data 2");
  EXPECT_EXIT(ViewerCRunNoDataThreeArguments(MakeContext("prog -null -frames 2")), ::testing::ExitedWithCode(0),
              "C tick without user data 2");
  EXPECT_EXIT(ViewerCRunWithData(MakeContext("prog -null -frames 3")), ::testing::ExitedWithCode(0),
              "C tick with user data 3");
}

void MEAPI TickNoData(RRender *) { std::fprintf(stderr, "C++ tick %d\n", ++gTicks); }

TEST_F(RunDeathTest, GuideTickAndRunFormsFromCxx) {
  EXPECT_EXIT(RRun(MakeContext("prog -null -frames 2"), TickNoData), ::testing::ExitedWithCode(0), "C\\+\\+ tick 2");
  EXPECT_EXIT(RRun(MakeContext("prog -null -frames 2"), TickNoData, nullptr), ::testing::ExitedWithCode(0),
              "C\\+\\+ tick 2");
  static int n = 0;
  EXPECT_EXIT(RRun(MakeContext("prog -null -frames 2"), Tick), ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(RRun(MakeContext("prog -null -frames 2"), Tick, &n), ::testing::ExitedWithCode(0), "");
}

}  // namespace
