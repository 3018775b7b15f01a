/* The C API of KarmaTrajectory.h (what C tutorials call): a file it writes reads
 * back with the hash it reports, and misuse is recorded, never a crash. */
#include "GoldenTestSupport.h"

#include <karma/golden/KarmaTrajectory.h>
#include <karma/golden/StateHash.h>
#include <karma/golden/TrajectoryReader.h>

#include <gtest/gtest.h>

#include <string>

namespace karma::golden {
namespace {

const MeReal kPos[3] = {1, 2, 3}, kQuat[4] = {1, 0, 0, 0}, kLin[3] = {0, MeReal(-9.81), 0}, kAng[3] = {0, 0, 1};

TEST(KarmaTrajectoryCApi, WritesAFileThatReadsBackWithTheReportedHash) {
  test_support::TempDir dir("capi");
  const std::string path = (dir.path() / "c.txt").string();
  const KarmaTrajectoryInfo info = {"capi", nullptr, nullptr, "every frame", MeReal(0.5), 2};
  KarmaTrajectoryWriter *w = KarmaTrajectoryWriterCreate(path.c_str(), &info);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(KarmaTrajectoryWriterError(w), nullptr);
  for (long frame = 0; frame < 3; ++frame) {
    EXPECT_TRUE(KarmaTrajectoryWriterBeginFrame(w, frame, MeReal(frame) * MeReal(0.5)));
    EXPECT_TRUE(KarmaTrajectoryWriterAddBody(w, kPos, kQuat, kLin, kAng));
    EXPECT_TRUE(KarmaTrajectoryWriterAddBody(w, kPos, kQuat, kLin, kAng));
    EXPECT_TRUE(KarmaTrajectoryWriterEndFrame(w));
  }
  const std::uint64_t hash = KarmaTrajectoryWriterHash(w);
  char text[KARMA_GOLDEN_HASH_TEXT_SIZE];
  KarmaGoldenFormatHash(hash, text);
  EXPECT_EQ(std::string(text), FormatHash(hash));
  EXPECT_TRUE(KarmaTrajectoryWriterDestroy(w));

  const Trajectory t = ReadTrajectoryFile(path);
  EXPECT_EQ(t.header.program, "capi");
  EXPECT_EQ(t.header.step, "main");         /* NULL step */
  EXPECT_EQ(t.header.backend, "reference"); /* NULL backend */
  EXPECT_EQ(t.header.precision, kBuildPrecision);
  EXPECT_EQ(t.frames.size(), 3u);
  EXPECT_EQ(t.finalHash, hash);
  EXPECT_EQ(HashTrajectory(t), hash);
}

TEST(KarmaTrajectoryCApi, MisuseIsRecordedAndLaterCallsAreRefused) {
  const KarmaTrajectoryInfo info = {"capi", "main", "reference", "", MeReal(0.5), 2};
  KarmaTrajectoryWriter *w = KarmaTrajectoryWriterCreate(nullptr, &info); /* hash only */
  EXPECT_TRUE(KarmaTrajectoryWriterBeginFrame(w, 0, 0));
  EXPECT_TRUE(KarmaTrajectoryWriterAddBody(w, kPos, kQuat, kLin, kAng));
  EXPECT_TRUE(KarmaTrajectoryWriterAddBody(w, kPos, kQuat, kLin, kAng));
  EXPECT_FALSE(KarmaTrajectoryWriterAddBody(w, kPos, kQuat, kLin, kAng)); /* a third body */
  ASSERT_NE(KarmaTrajectoryWriterError(w), nullptr);
  EXPECT_NE(std::string(KarmaTrajectoryWriterError(w)).find("more than the 2 bodies"), std::string::npos);
  EXPECT_FALSE(KarmaTrajectoryWriterEndFrame(w));
  EXPECT_FALSE(KarmaTrajectoryWriterDestroy(w));

  w = KarmaTrajectoryWriterCreate(nullptr, &info);
  EXPECT_TRUE(KarmaTrajectoryWriterBeginFrame(w, 0, 0));
  EXPECT_FALSE(KarmaTrajectoryWriterAddBody(w, kPos, nullptr, kLin, kAng));
  EXPECT_NE(KarmaTrajectoryWriterError(w), nullptr);
  EXPECT_FALSE(KarmaTrajectoryWriterDestroy(w));

  KarmaTrajectoryInfo noProgram = info;
  noProgram.program = nullptr;
  w = KarmaTrajectoryWriterCreate(nullptr, &noProgram);
  ASSERT_NE(w, nullptr);
  EXPECT_NE(KarmaTrajectoryWriterError(w), nullptr);
  EXPECT_FALSE(KarmaTrajectoryWriterBeginFrame(w, 0, 0));
  EXPECT_FALSE(KarmaTrajectoryWriterDestroy(w));

  w = KarmaTrajectoryWriterCreate("/nonexistent-dir/sub/trajectory.txt", &info);
  ASSERT_NE(w, nullptr);
  EXPECT_NE(std::string(KarmaTrajectoryWriterError(w)).find("cannot create"), std::string::npos);
  EXPECT_FALSE(KarmaTrajectoryWriterDestroy(w));

  EXPECT_FALSE(KarmaTrajectoryWriterDestroy(nullptr));
  EXPECT_EQ(KarmaTrajectoryWriterHash(nullptr), 0u);
}

TEST(KarmaTrajectoryCApi, FrameFileNameTruncatesSafely) {
  char name[32];
  KarmaGoldenFrameFileName(42, name, sizeof name);
  EXPECT_STREQ(name, "frame_00042.png");
  char small[6];
  KarmaGoldenFrameFileName(42, small, sizeof small);
  EXPECT_STREQ(small, "frame");
}

}  // namespace
}  // namespace karma::golden
