/* CheckAgainstGolden on temporary golden/actual directories, and GoldenKey. */
#include "GoldenTestSupport.h"

#include <karma/golden/Error.h>
#include <karma/golden/GoldenCheck.h>
#include <karma/golden/GoldenKey.h>
#include <karma/golden/Image.h>
#include <karma/golden/TrajectoryWriter.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace kg = karma::golden;
namespace ts = karma::golden::test_support;
namespace fs = std::filesystem;

namespace {

kg::Image Frame(int seed) {
  kg::Image img(64, 48);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::uint8_t *p = img.Pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 3 + seed);
      p[1] = static_cast<std::uint8_t>(y * 5 + seed);
      p[2] = static_cast<std::uint8_t>((x ^ y) + seed);
      p[3] = 255;
    }
  return img;
}

/* golden/ and actual/ each with trajectory.txt and frames 0 and 10. */
class GoldenCheckTest : public ::testing::Test {
 protected:
  GoldenCheckTest() : dir_("check"), golden_(dir_.path() / "golden"), actual_(dir_.path() / "actual") {
    fs::create_directories(golden_);
    fs::create_directories(actual_);
    for (const fs::path &d : {golden_, actual_}) {
      kg::WriteTrajectoryFile(d / kg::kTrajectoryFileName, ts::SyntheticTrajectory());
      kg::WritePng(d / kg::FrameFileName(0), Frame(0));
      kg::WritePng(d / kg::FrameFileName(10), Frame(10));
    }
  }

  kg::CheckResult Check() const { return kg::CheckAgainstGolden(golden_, actual_, kg::CheckOptions{}); }

  ts::TempDir dir_;
  fs::path golden_, actual_;
};

}  // namespace

TEST_F(GoldenCheckTest, MatchingOutputMatches) {
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Match) << r.report;
  EXPECT_EQ(r.itemsChecked, 3);
  EXPECT_EQ(r.itemsFailed, 0);
  EXPECT_NE(r.report.find("MATCH"), std::string::npos) << r.report;
}

TEST_F(GoldenCheckTest, MissingActualFrameIsMismatch) {
  kg::WritePng(golden_ / kg::FrameFileName(20), Frame(20));
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Mismatch) << r.report;
  EXPECT_EQ(r.itemsChecked, 4);
  EXPECT_EQ(r.itemsFailed, 1);
  EXPECT_NE(r.report.find("frame_00020.png"), std::string::npos) << r.report;
}

TEST_F(GoldenCheckTest, ExtraActualFrameIsIgnored) {
  kg::WritePng(actual_ / kg::FrameFileName(30), Frame(99));
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Match) << r.report;
  EXPECT_EQ(r.itemsChecked, 3);
  EXPECT_EQ(r.report.find("frame_00030.png"), std::string::npos) << r.report;
}

TEST_F(GoldenCheckTest, DifferentFrameIsMismatchAndWritesDiff) {
  kg::WritePng(actual_ / kg::FrameFileName(10), Frame(40));
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Mismatch) << r.report;
  EXPECT_EQ(r.itemsFailed, 1);
  EXPECT_TRUE(fs::exists(actual_ / "frame_00010.diff.png"));
  EXPECT_FALSE(fs::exists(actual_ / "frame_00000.diff.png"));
}

TEST_F(GoldenCheckTest, PerturbedTrajectoryIsMismatch) {
  kg::Trajectory t = ts::SyntheticTrajectory();
  t.frames[3].bodies[1].position[1] = ts::Real(t.frames[3].bodies[1].position[1] + 0.01);
  kg::WriteTrajectoryFile(actual_ / kg::kTrajectoryFileName, t);
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Mismatch) << r.report;
  EXPECT_EQ(r.itemsFailed, 1);
  EXPECT_NE(r.report.find("body 1"), std::string::npos) << r.report;

  fs::remove(actual_ / kg::kTrajectoryFileName);
  const kg::CheckResult missing = Check();
  EXPECT_EQ(missing.status, kg::CheckStatus::Mismatch) << missing.report;
  EXPECT_NE(missing.report.find(kg::kTrajectoryFileName), std::string::npos) << missing.report;
}

TEST_F(GoldenCheckTest, EmptyGoldenDirectoryIsError) {
  const fs::path empty = dir_.path() / "empty";
  fs::create_directories(empty);
  const kg::CheckResult r = kg::CheckAgainstGolden(empty, actual_, kg::CheckOptions{});
  EXPECT_EQ(r.status, kg::CheckStatus::Error) << r.report;
  EXPECT_EQ(r.itemsChecked, 0);

  const kg::CheckResult nodir = kg::CheckAgainstGolden(dir_.path() / "nope", actual_, kg::CheckOptions{});
  EXPECT_EQ(nodir.status, kg::CheckStatus::Error) << nodir.report;
}

TEST_F(GoldenCheckTest, UnreadableGoldenTrajectoryIsError) {
  { std::ofstream(golden_ / kg::kTrajectoryFileName) << "not a trajectory\n"; }
  const kg::CheckResult r = Check();
  EXPECT_EQ(r.status, kg::CheckStatus::Error) << r.report;
}

// Backends share a golden through a relative link (docs/GOLDEN.md): the check
// follows it, reads the reference's files and passes an avx2 run whose only
// difference is the header's backend, noting it; a perturbed run still fails.
TEST_F(GoldenCheckTest, GoldenThroughRelativeLinkIsFollowed) {
  const fs::path link = dir_.path() / "avx2-single";
  fs::create_directory_symlink("golden", link);
  kg::Trajectory t = ts::SyntheticTrajectory();
  t.header.backend = "avx2";
  kg::WriteTrajectoryFile(actual_ / kg::kTrajectoryFileName, t);
  const kg::CheckResult r = kg::CheckAgainstGolden(link, actual_, kg::CheckOptions{});
  EXPECT_EQ(r.status, kg::CheckStatus::Match) << r.report;
  EXPECT_EQ(r.itemsChecked, 3);
  EXPECT_NE(r.report.find("backends differ (expected reference, actual avx2)"), std::string::npos) << r.report;

  t.frames[3].bodies[1].position[1] = ts::Real(t.frames[3].bodies[1].position[1] + 0.01);
  kg::WriteTrajectoryFile(actual_ / kg::kTrajectoryFileName, t);
  const kg::CheckResult perturbed = kg::CheckAgainstGolden(link, actual_, kg::CheckOptions{});
  EXPECT_EQ(perturbed.status, kg::CheckStatus::Mismatch) << perturbed.report;
}

TEST(GoldenKey, RelativeDirectoryLayout) {
  kg::GoldenKey key;
  key.program = "demo";
  EXPECT_EQ(key.step, "main");
  EXPECT_EQ(key.backend, "reference");
  EXPECT_EQ(key.precision, kg::kBuildPrecision);
  key.precision = kg::Precision::Single;
  EXPECT_EQ(key.RelativeDirectory(), fs::path("demo") / "main" / "reference-single");
  key.program = "tutorial_2.1";
  key.step = "step-3";
  key.backend = "simd";
  key.precision = kg::Precision::Double;
  EXPECT_EQ(key.RelativeDirectory(), fs::path("tutorial_2.1") / "step-3" / "simd-double");
  EXPECT_EQ(key.Directory("golden"), fs::path("golden") / "tutorial_2.1" / "step-3" / "simd-double");
}

TEST(GoldenKey, InvalidPartsAreRejected) {
  for (const char *bad : {"", ".", "..", "a/b", "a b", "a\\b", "../x", "caf\xc3\xa9"}) {
    kg::GoldenKey program;
    program.program = bad;
    EXPECT_THROW(program.Validate(), kg::GoldenError) << "program '" << bad << "'";
    EXPECT_THROW(program.RelativeDirectory(), kg::GoldenError) << "program '" << bad << "'";

    kg::GoldenKey step;
    step.program = "demo";
    step.step = bad;
    EXPECT_THROW(step.Validate(), kg::GoldenError) << "step '" << bad << "'";

    kg::GoldenKey backend;
    backend.program = "demo";
    backend.backend = bad;
    EXPECT_THROW(backend.Validate(), kg::GoldenError) << "backend '" << bad << "'";
  }
  kg::GoldenKey ok;
  ok.program = "a.b-c_D9";
  EXPECT_NO_THROW(ok.Validate());
}

TEST(GoldenKey, FrameFileName) {
  EXPECT_EQ(kg::FrameFileName(0), "frame_00000.png");
  EXPECT_EQ(kg::FrameFileName(42), "frame_00042.png");
  EXPECT_EQ(kg::FrameFileName(1234567), "frame_1234567.png");
}
