// window_options_test.cpp: when the viewer chooses the window. -window asks
// for it; without a backend option it is the default when $DISPLAY is set
// and -frames is not given; -frames or an explicit backend keep offscreen.
// -record and -screenshot are read, and ignored (with a warning) without a
// window. The window itself is tested under Xvfb by window_test.sh.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cstdlib>

using karma::viewer::BackendKind;
using karma::viewer::ParseViewerOptions;
using karma::viewer::ViewerOptions;
using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

/* The MeViewer tests make contexts without -frames, which must draw
 * offscreen even in a developer's session with a display: $DISPLAY is
 * removed before any test runs (static initialisation of this file). */
[[maybe_unused]] const int kNoDisplayForTheTests = ::unsetenv("DISPLAY");

class DisplayGuard {
 public:
  explicit DisplayGuard(const char *value) {
    if (const char *old = std::getenv("DISPLAY")) had_ = true, old_ = old;
    if (value)
      ::setenv("DISPLAY", value, 1);
    else
      ::unsetenv("DISPLAY");
  }
  ~DisplayGuard() {
    if (had_)
      ::setenv("DISPLAY", old_.c_str(), 1);
    else
      ::unsetenv("DISPLAY");
  }
  DisplayGuard(const DisplayGuard &) = delete;
  DisplayGuard &operator=(const DisplayGuard &) = delete;

 private:
  bool had_ = false;
  std::string old_;
};

BackendKind BackendFor(const char *commandLine) {
  MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString(commandLine);
  ViewerOptions out;
  std::string error;
  EXPECT_TRUE(ParseViewerOptions(o, nullptr, true, out, error)) << error;
  MeCommandLineOptionsDestroy(o);
  return out.backend;
}

TEST(WindowOptions, DefaultWithADisplayAndNoFrameLimit) {
  DisplayGuard display(":42");
  EXPECT_EQ(BackendFor("prog"), BackendKind::Window);
  EXPECT_EQ(BackendFor("prog -frames 10"), BackendKind::GL);
  EXPECT_EQ(BackendFor("prog -gl"), BackendKind::GL);
  EXPECT_EQ(BackendFor("prog -null"), BackendKind::Null);
}

TEST(WindowOptions, OffscreenWithoutADisplayUnlessAsked) {
  DisplayGuard none(nullptr);
  EXPECT_EQ(BackendFor("prog"), BackendKind::GL);
  DisplayGuard empty("");
  EXPECT_EQ(BackendFor("prog"), BackendKind::GL);
  EXPECT_EQ(BackendFor("prog -window -frames 3"), BackendKind::Window);
}

TEST(WindowOptions, RecordAndScreenshotAreRead) {
  MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString("prog -window -record a.keys -screenshot s.png");
  ViewerOptions out;
  std::string error;
  ASSERT_TRUE(ParseViewerOptions(o, nullptr, true, out, error)) << error;
  EXPECT_EQ(MeCommandLineOptionsGetCount(o), 1);
  MeCommandLineOptionsDestroy(o);
  EXPECT_EQ(out.record, "a.keys");
  EXPECT_EQ(out.screenshot, "s.png");
}

TEST(WindowOptions, RecordWithoutAWindowIsIgnoredWithAWarning) {
  DisplayGuard none(nullptr);
  Messages m;
  RRender *rc = MakeContext("prog -frames 1 -size 32x32 -record a.keys");
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("-record and -screenshot need a window")) << Messages::All();
  EXPECT_TRUE(rc->m_pPrivate->options.record.empty());
  RRenderContextDestroy(rc);
}

TEST(WindowOptions, NoDisplayFallsBackToOffscreenWithAWarning) {
  DisplayGuard none(nullptr);
  Messages m;
  RRender *rc = MakeContext("prog -window -frames 1 -size 32x32");
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("drawing offscreen instead")) << Messages::All();
  EXPECT_EQ(rc->m_pPrivate->options.backend, BackendKind::GL);
  EXPECT_TRUE(rc->m_pPrivate->backend->Draws());
  RRenderContextDestroy(rc);
}

}  // namespace
