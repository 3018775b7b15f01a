// video_test.cpp: -video. Without ffmpeg on $PATH the context says so and
// carries on; with a stand-in ffmpeg (a script recording its arguments)
// the run ends by calling it on the frames, which for a video alone live in
// a temporary directory removed afterwards.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cstdlib>
#include <fstream>
#include <iterator>

using viewer_test::MakeContext;
using viewer_test::Messages;
using viewer_test::TempDir;

namespace {

class PathGuard {
 public:
  explicit PathGuard(const std::string &path) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", path.c_str(), 1);
  }
  ~PathGuard() { ::setenv("PATH", old_.c_str(), 1); }
  PathGuard(const PathGuard &) = delete;
  PathGuard &operator=(const PathGuard &) = delete;

 private:
  std::string old_;
};

TEST(Video, WithoutFfmpegTheRunGoesOnWithAMessage) {
  TempDir empty("noffmpeg");
  PathGuard path(empty.str());
  Messages m;
  RRender *rc = MakeContext("prog -frames 1 -size 32x32 -video out.mp4");
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("ffmpeg is not installed (Debian package ffmpeg)")) << Messages::All();
  EXPECT_TRUE(rc->m_pPrivate->options.video.empty());
  RRenderContextDestroy(rc);
}

TEST(Video, IgnoredWhenNothingIsDrawn) {
  Messages m;
  RRender *rc = MakeContext("prog -null -video out.mp4");
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("-video out.mp4 is ignored"));
  RRenderContextDestroy(rc);
}

void MakeFakeFfmpeg(const TempDir &dir) {
  const std::string script = (dir.path() / "ffmpeg").string();
  std::ofstream(script) << "#!/bin/sh\n"
                           "printf '%s\\n' \"$@\" > \"$(dirname \"$0\")/args.txt\"\n"
                           "for last; do :; done\n"
                           "ls \"$(dirname \"$0\")\" > /dev/null\n"
                           "echo video > \"$last\"\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
}

class VideoDeathTest : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(VideoDeathTest, AGifFromTemporaryFramesThroughFfmpeg) {
  TempDir dir("fakeffmpeg");
  MakeFakeFfmpeg(dir);
  PathGuard path(dir.str() + ":" + (std::getenv("PATH") ? std::getenv("PATH") : ""));
  const std::string gif = (dir.path() / "out.gif").string();
  EXPECT_EXIT(
      {
        RRender *rc = MakeContext("prog -frames 3 -size 32x32 -video " + gif);
        RRun(rc, static_cast<RMainLoopCallBack>(nullptr), nullptr);
      },
      ::testing::ExitedWithCode(0), "video written to .*out.gif");
  std::ifstream f(dir.path() / "args.txt");
  const std::string args((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(args.find("-pattern_type\nglob\n-i\n"), std::string::npos) << args;
  EXPECT_NE(args.find("palettegen"), std::string::npos) << args;
  EXPECT_NE(args.find("/frame_*.png\n"), std::string::npos) << args;
  EXPECT_TRUE(std::filesystem::exists(gif));
  // The frames were in a temporary directory, gone now.
  const std::size_t i = args.find("-i\n") + 3;
  const std::string pattern = args.substr(i, args.find('\n', i) - i);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(pattern).parent_path())) << pattern;
}

TEST_F(VideoDeathTest, AnMp4FromTheOutDirectoryKeepsTheFrames) {
  TempDir dir("fakeffmpeg-mp4");
  MakeFakeFfmpeg(dir);
  PathGuard path(dir.str() + ":" + (std::getenv("PATH") ? std::getenv("PATH") : ""));
  const std::string out = (dir.path() / "frames").string(), mp4 = (dir.path() / "out.mp4").string();
  EXPECT_EXIT(
      {
        RRender *rc = MakeContext("prog -frames 2 -size 32x32 -bmp -out " + out + " -video " + mp4);
        RRun(rc, static_cast<RMainLoopCallBack>(nullptr), nullptr);
      },
      ::testing::ExitedWithCode(0), "video written");
  std::ifstream f(dir.path() / "args.txt");
  const std::string args((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(args.find("libx264"), std::string::npos) << args;
  EXPECT_NE(args.find(out + "/frame_*.bmp\n"), std::string::npos) << args;
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / "frame_00001.bmp"));
}

}  // namespace
