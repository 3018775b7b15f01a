// MeProfile, driven by a fake clock so that every time is exact.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "MeProfile.h"
#include "runtime_test_support.h"

using karma_test::MessageCapture;

namespace {

struct FakeClock {
  double now = 0;  // milliseconds
  int reads = 0;
};

double MEAPI readFakeClock(void *user) {
  auto *clock = static_cast<FakeClock *>(user);
  ++clock->reads;
  return clock->now;
}

class ProfileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    MeProfileSetClock(&readFakeClock, &clock);
    MeProfileSetEnabled(TRUE);
    MeProfileReset();
  }
  void TearDown() override {
    MeProfileSetClock(nullptr, nullptr);
    MeProfileSetEnabled(TRUE);
    MeProfileReset();
  }

  // Advances the fake clock to `t` ms.
  void at(double t) { clock.now = t; }

  // Times `name` from `from` to `to`.
  void section(const char *name, double from, double to) {
    at(from);
    MeProfileStartSection(name);
    at(to);
    MeProfileEndSection(name);
  }

  FakeClock clock;
};

TEST_F(ProfileTest, BuiltInSectionsExistFromTheStart) {
  ASSERT_EQ(MeProfileGetSectionCount(), 4);
  EXPECT_STREQ(MeProfileGetSectionName(0), "collision");
  EXPECT_STREQ(MeProfileGetSectionName(1), "dynamics");
  EXPECT_STREQ(MeProfileGetSectionName(2), "render");
  EXPECT_STREQ(MeProfileGetSectionName(3), "user");
  EXPECT_EQ(MeProfileGetSectionName(4), nullptr);
  EXPECT_EQ(MeProfileGetSectionName(-1), nullptr);
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), 0);
  EXPECT_EQ(MeProfileGetFrameTime(), 0);
  EXPECT_EQ(MeProfileGetFrameCount(), 0);
  EXPECT_TRUE(MeProfileIsEnabled());
}

TEST_F(ProfileTest, SectionTimesAreExact) {
  at(100);
  MeProfileStartFrame();
  section("collision", 101, 103);
  section("dynamics", 103, 107.5);
  section("render", 108, 109.25);
  at(110);
  MeProfileEndFrame();

  EXPECT_EQ(MeProfileGetSectionTime("collision"), (MeReal)2);
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)4.5);
  EXPECT_EQ(MeProfileGetSectionTime("render"), (MeReal)1.25);
  EXPECT_EQ(MeProfileGetSectionTime("user"), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionTime("never-heard-of"), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionTime(nullptr), (MeReal)0);
  EXPECT_EQ(MeProfileGetFrameTime(), (MeReal)10);
  EXPECT_EQ(MeProfileGetFrameCount(), 1);
}

TEST_F(ProfileTest, NestedSectionsIncludeTheirChildren) {
  at(0);
  MeProfileStartFrame();
  MeProfileStartSection("user");
  section("mine", 2, 5);
  section("collision", 5, 6);
  at(10);
  MeProfileEndSection("user");
  MeProfileEndFrame();

  EXPECT_EQ(MeProfileGetSectionTime("user"), (MeReal)10);
  EXPECT_EQ(MeProfileGetSectionTime("mine"), (MeReal)3);
  EXPECT_EQ(MeProfileGetSectionTime("collision"), (MeReal)1);
  ASSERT_EQ(MeProfileGetSectionCount(), 5);
  EXPECT_STREQ(MeProfileGetSectionName(4), "mine");
}

TEST_F(ProfileTest, RepeatedSectionsAddUpAndRecursionCountsOnce) {
  at(0);
  MeProfileStartFrame();
  section("dynamics", 1, 2);
  section("dynamics", 3, 5);
  at(6);
  MeProfileStartSection("collision");
  section("collision", 7, 8);  // nested inside itself
  at(9);
  MeProfileEndSection("collision");
  at(20);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)3);
  EXPECT_EQ(MeProfileGetSectionTime("collision"), (MeReal)3);
}

TEST_F(ProfileTest, AveragesCoverEveryFrameSinceReset) {
  // Frame lengths 10, 20, 30; dynamics 2, 4, absent.
  at(0);
  MeProfileStartFrame();
  section("dynamics", 1, 3);
  at(10);
  MeProfileEndFrame();

  MeProfileStartFrame();
  section("dynamics", 11, 15);
  at(30);
  MeProfileEndFrame();

  at(40);  // time between frames belongs to no frame
  MeProfileStartFrame();
  at(70);
  MeProfileEndFrame();

  EXPECT_EQ(MeProfileGetFrameCount(), 3);
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionAverage("dynamics"), (MeReal)2);
  EXPECT_EQ(MeProfileGetFrameTime(), (MeReal)30);
  EXPECT_EQ(MeProfileGetFrameAverage(), (MeReal)20);
  EXPECT_EQ(MeProfileGetSectionAverage("nothing"), (MeReal)0);
}

TEST_F(ProfileTest, MismatchedEndWarnsAndIsIgnored) {
  MessageCapture capture;
  at(0);
  MeProfileStartFrame();
  at(1);
  MeProfileStartSection("dynamics");
  at(2);
  MeProfileEndSection("collision");  // not the innermost
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("\"collision\" is not the innermost open section"), std::string::npos)
      << capture.lastWarning();
  EXPECT_NE(capture.lastWarning().find("\"dynamics\""), std::string::npos);
  at(4);
  MeProfileEndSection("dynamics");
  MeProfileEndSection("dynamics");  // nothing open any more
  EXPECT_EQ(capture.warnings().size(), 2u);
  MeProfileEndSection("unknown");
  EXPECT_EQ(capture.warnings().size(), 3u);
  at(5);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)3);
  EXPECT_EQ(MeProfileGetSectionTime("collision"), (MeReal)0);
}

TEST_F(ProfileTest, EndFrameClosesOpenSectionsWithAWarning) {
  MessageCapture capture;
  at(0);
  MeProfileStartFrame();
  at(2);
  MeProfileStartSection("render");
  at(7);
  MeProfileEndFrame();
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("\"render\" is still open"), std::string::npos);
  EXPECT_EQ(MeProfileGetSectionTime("render"), (MeReal)5);

  // The next frame starts clean.
  MeProfileStartFrame();
  section("render", 8, 9);
  at(10);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetSectionTime("render"), (MeReal)1);
  EXPECT_EQ(capture.warnings().size(), 1u);
}

TEST_F(ProfileTest, FrameCallsOutOfOrderWarn) {
  MessageCapture capture;
  MeProfileEndFrame();  // no frame open
  EXPECT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(MeProfileGetFrameCount(), 0);

  at(0);
  MeProfileStartFrame();
  at(4);
  MeProfileStartFrame();  // ends the first frame
  EXPECT_EQ(capture.warnings().size(), 2u);
  EXPECT_EQ(MeProfileGetFrameCount(), 1);
  EXPECT_EQ(MeProfileGetFrameTime(), (MeReal)4);
  at(10);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetFrameTime(), (MeReal)6);
}

TEST_F(ProfileTest, SectionsOutsideAFrameAreIgnoredSilently) {
  MessageCapture capture;
  section("dynamics", 0, 5);
  EXPECT_TRUE(capture.warnings().empty());
  at(5);
  MeProfileStartFrame();
  at(6);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)0);
}

TEST_F(ProfileTest, DisabledProfilingDoesNothingAndReadsNoClock) {
  at(0);
  MeProfileStartFrame();
  section("dynamics", 1, 3);
  at(4);
  MeProfileEndFrame();

  MeProfileSetEnabled(FALSE);
  EXPECT_FALSE(MeProfileIsEnabled());
  const int readsBefore = clock.reads;
  MessageCapture capture;
  MeProfileStartFrame();
  section("dynamics", 5, 50);
  section("brand-new", 50, 60);
  MeProfileEndSection("mismatch");
  MeProfileEndFrame();
  MeProfileEndFrame();
  EXPECT_EQ(clock.reads, readsBefore);
  EXPECT_TRUE(capture.warnings().empty());
  // Earlier results are still readable.
  EXPECT_EQ(MeProfileGetFrameCount(), 1);
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)2);
  EXPECT_EQ(MeProfileGetSectionCount(), 4);

  // Disabling mid-frame drops that frame.
  MeProfileSetEnabled(TRUE);
  at(100);
  MeProfileStartFrame();
  MeProfileSetEnabled(FALSE);
  MeProfileSetEnabled(TRUE);
  at(110);
  MeProfileEndFrame();
  EXPECT_EQ(capture.warnings().size(), 1u);  // "no frame is open"
  EXPECT_EQ(MeProfileGetFrameCount(), 1);
}

TEST_F(ProfileTest, SectionTableIsBoundedWithOneWarning) {
  MessageCapture capture;
  at(0);
  MeProfileStartFrame();
  for (int i = 0; i < ME_PROFILE_MAX_SECTIONS; ++i) {  // 4 built-ins + 28 new fit
    char name[16];
    std::snprintf(name, sizeof name, "s%d", i);
    section(name, i, i + 0.5);
  }
  EXPECT_EQ(MeProfileGetSectionCount(), ME_PROFILE_MAX_SECTIONS);
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("\"s28\" is not timed"), std::string::npos) << capture.lastWarning();
  EXPECT_EQ(capture.warnings().size(), 1u);

  const std::string longName(ME_PROFILE_MAX_NAME, 'n');
  section(longName.c_str(), 40, 41);
  EXPECT_EQ(capture.warnings().size(), 1u) << "one warning per reset";
  section("dynamics", 41, 42);  // existing sections still work
  at(50);
  MeProfileEndFrame();
  EXPECT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(MeProfileGetSectionTime("s27"), (MeReal)0.5);
  EXPECT_EQ(MeProfileGetSectionTime("s28"), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionTime("dynamics"), (MeReal)1);

  MeProfileReset();
  EXPECT_EQ(MeProfileGetSectionCount(), 4);
  MeProfileStartFrame();
  section(longName.c_str(), 60, 61);
  ASSERT_EQ(capture.warnings().size(), 2u);
  EXPECT_NE(capture.lastWarning().find("longer than"), std::string::npos);
  MeProfileEndFrame();
}

TEST_F(ProfileTest, NestingDeeperThanTheLimitIsNotTimed) {
  MessageCapture capture;
  at(0);
  MeProfileStartFrame();
  char names[ME_PROFILE_MAX_DEPTH + 2][16];
  for (int i = 0; i < ME_PROFILE_MAX_DEPTH + 2; ++i) {
    std::snprintf(names[i], sizeof names[i], "d%d", i);
    MeProfileStartSection(names[i]);
  }
  EXPECT_EQ(capture.warnings().size(), 1u);
  at(3);
  for (int i = ME_PROFILE_MAX_DEPTH + 1; i >= 0; --i) MeProfileEndSection(names[i]);
  EXPECT_EQ(capture.warnings().size(), 1u);
  MeProfileEndFrame();
  EXPECT_EQ(MeProfileGetSectionTime("d0"), (MeReal)3);
  EXPECT_EQ(MeProfileGetSectionTime(names[ME_PROFILE_MAX_DEPTH - 1]), (MeReal)3);
  EXPECT_EQ(MeProfileGetSectionTime(names[ME_PROFILE_MAX_DEPTH]), (MeReal)0);
}

TEST_F(ProfileTest, ResetForgetsResultsAndUserSections) {
  at(0);
  MeProfileStartFrame();
  section("custom", 1, 2);
  at(3);
  MeProfileEndFrame();
  ASSERT_EQ(MeProfileGetSectionCount(), 5);
  MeProfileReset();
  EXPECT_EQ(MeProfileGetSectionCount(), 4);
  EXPECT_EQ(MeProfileGetFrameCount(), 0);
  EXPECT_EQ(MeProfileGetFrameTime(), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionTime("custom"), (MeReal)0);
  EXPECT_EQ(MeProfileGetSectionAverage("custom"), (MeReal)0);
}

TEST_F(ProfileTest, ChangingTheClockDropsTheOpenFrame) {
  MessageCapture capture;
  at(0);
  MeProfileStartFrame();
  FakeClock other;
  MeProfileSetClock(&readFakeClock, &other);
  MeProfileEndFrame();
  EXPECT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(MeProfileGetFrameCount(), 0);
  EXPECT_EQ(clock.reads, 1);
}

TEST(ProfileDefaultClockTest, MeasuresRealTime) {
  MeProfileSetClock(nullptr, nullptr);
  MeProfileReset();
  MeProfileStartFrame();
  MeProfileStartSection("user");
  std::this_thread::sleep_for(std::chrono::milliseconds(3));
  MeProfileEndSection("user");
  MeProfileEndFrame();
  EXPECT_GE(MeProfileGetSectionTime("user"), (MeReal)2.5);
  EXPECT_LT(MeProfileGetSectionTime("user"), (MeReal)5000);
  EXPECT_GE(MeProfileGetFrameTime(), MeProfileGetSectionTime("user"));
  MeProfileReset();
}

}  // namespace
