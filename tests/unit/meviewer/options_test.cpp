// options_test.cpp: the viewer's command line: each option, eating,
// overrides, malformed values, unknown options, unwritable output
// directories and -help.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include "MdtPlatform.h"

#include <fstream>

using karma::viewer::BackendKind;
using karma::viewer::ParseViewerOptions;
using karma::viewer::ViewerOptions;
using viewer_test::MakeContext;
using viewer_test::Messages;
using viewer_test::TempDir;

namespace {

struct Parsed {
  bool ok;
  ViewerOptions options;
  std::string error;
  std::vector<std::string> left;  // arguments left after eating
};

Parsed Parse(const char *commandLine, const char *overrides = nullptr, bool eat = true) {
  Parsed p;
  MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString(commandLine);
  MeCommandLineOptions *v = overrides ? MeCommandLineOptionsCreateFromString(overrides) : nullptr;
  p.ok = ParseViewerOptions(o, v, eat, p.options, p.error);
  for (int i = 1; i < MeCommandLineOptionsGetCount(o); ++i) p.left.emplace_back(MeCommandLineOptionsGetArg(o, i));
  MeCommandLineOptionsDestroy(o);
  MeCommandLineOptionsDestroy(v);
  return p;
}

TEST(Options, Defaults) {
  const Parsed p = Parse("prog");
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.options.backend, BackendKind::GL);
  EXPECT_EQ(p.options.frames, -1);
  EXPECT_TRUE(p.options.outDir.empty());
  EXPECT_EQ(p.options.every, 1);
  EXPECT_FALSE(p.options.bmp);
  EXPECT_EQ(p.options.width, 640);
  EXPECT_EQ(p.options.height, 480);
}

TEST(Options, Backends) {
  EXPECT_EQ(Parse("prog -gl").options.backend, BackendKind::GL);
  EXPECT_EQ(Parse("prog -d3d").options.backend, BackendKind::GL);
  EXPECT_EQ(Parse("prog -null").options.backend, BackendKind::Null);
  EXPECT_EQ(Parse("prog -bench").options.backend, BackendKind::Bench);
  EXPECT_EQ(Parse("prog -profile").options.backend, BackendKind::Profile);
  EXPECT_EQ(Parse("prog -null", nullptr, false).options.backend, BackendKind::Null);
}

TEST(Options, ValuesAreReadAndEatenLeavingTheProgramsOwn) {
  const Parsed p = Parse("prog -frames 12 -balls 3 -out dir -every 3 -bmp -size 320x200 extra");
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.options.frames, 12);
  EXPECT_EQ(p.options.outDir, "dir");
  EXPECT_EQ(p.options.every, 3);
  EXPECT_TRUE(p.options.bmp);
  EXPECT_EQ(p.options.width, 320);
  EXPECT_EQ(p.options.height, 200);
  EXPECT_EQ(p.left, (std::vector<std::string>{"-balls", "3", "extra"}));
}

TEST(Options, WithoutEatingEverythingStays) {
  const Parsed p = Parse("prog -frames 2 -null", nullptr, false);
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.options.frames, 2);
  EXPECT_EQ(p.left.size(), 3u);
}

TEST(Options, OverridesWin) {
  const Parsed p = Parse("prog -frames 5 -null -size 100x100", "x -frames 7 -bench");
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.options.frames, 7);
  EXPECT_EQ(p.options.backend, BackendKind::Bench);
  EXPECT_EQ(p.options.width, 100);
}

TEST(Options, MalformedValuesAreRefusedNamingTheOption) {
  Messages m;  // the command-line reader warns too
  struct Case {
    const char *line, *mention;
  } cases[] = {{"prog -frames abc", "-frames"}, {"prog -frames -2", "-frames"}, {"prog -every 0", "-every"},
               {"prog -size 10x10", "-size"},   {"prog -size 320", "-size"},    {"prog -size x240", "-size"},
               {"prog -out", "-out"},           {"prog -frames", "-frames"}};
  for (const Case &c : cases) {
    const Parsed p = Parse(c.line);
    EXPECT_FALSE(p.ok) << c.line;
    EXPECT_NE(p.error.find(c.mention), std::string::npos) << c.line << ": " << p.error;
  }
}

TEST(Options, ContextCreationFailsCleanlyOnAMalformedValue) {
  Messages m;
  EXPECT_EQ(MakeContext("prog -size banana"), nullptr);
  EXPECT_TRUE(Messages::Warned("RRenderContextCreate: bad value 'banana' for -size")) << Messages::All();
}

TEST(Options, MisspeltOptionsAreNamedWithASuggestion) {
  Messages m;
  RRender *rc = MakeContext("prog -null -frame 5 -platform reference -trajectory t.txt -wibble");
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("unknown option '-frame' (did you mean -frames?")) << Messages::All();
  bool noted = false;
  for (const std::string &i : Messages::Infos())
    noted = noted || i.find("'-wibble' is not a viewer option") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_FALSE(Messages::Warned("-platform"));
  RRenderContextDestroy(rc);
}

TEST(Options, UnwritableOutputDirectoryFailsWithAMessage) {
  TempDir dir("unwritable");
  const std::string file = (dir.path() / "a-file").string();
  std::ofstream(file) << "x";
  Messages m;
  EXPECT_EQ(MakeContext("prog -frames 1 -out " + file + "/frames"), nullptr);
  EXPECT_TRUE(Messages::Warned("cannot create the output directory")) << Messages::All();
  EXPECT_EQ(MakeContext("prog -frames 1 -out " + file), nullptr);
  EXPECT_TRUE(Messages::Warned("is not a directory")) << Messages::All();
}

TEST(Options, OutIsIgnoredWithTheNullBackends) {
  TempDir dir("nullout");
  Messages m;
  RRender *rc = MakeContext("prog -null -out " + (dir.path() / "never").string());
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(Messages::Warned("is ignored"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "never"));
  RRenderContextDestroy(rc);
}

TEST(Options, OutputDirectoryIsCreated) {
  TempDir dir("created");
  const std::filesystem::path out = dir.path() / "a" / "b";
  RRender *rc = MakeContext("prog -frames 1 -size 32x32 -out " + out.string());
  ASSERT_NE(rc, nullptr);
  EXPECT_TRUE(std::filesystem::is_directory(out));
  EXPECT_EQ(rc->m_nWidth, 32);
  RRenderContextDestroy(rc);
}

// -platform NAME: a known backend is read and left for the program; any
// other name, or none, is refused like a malformed value. As with the
// tutorials' record, the last one given counts.
TEST(Options, PlatformIsReadAndLeftInPlace) {
  const Parsed p = Parse("prog -platform reference -null");
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.options.platform, "reference");
  EXPECT_EQ(p.left, (std::vector<std::string>{"-platform", "reference"}));
  EXPECT_TRUE(Parse("prog -null").options.platform.empty());
  EXPECT_EQ(Parse("prog -platform neon -null -platform sse4").options.platform, "sse4");  // the last counts
  Messages m;
  for (const char *line : {"prog -platform neon", "prog -platform"}) {
    const Parsed bad = Parse(line);
    EXPECT_FALSE(bad.ok) << line;
    EXPECT_NE(bad.error.find("-platform"), std::string::npos) << bad.error;
    EXPECT_NE(bad.error.find("reference, sse4, avx2, avx512"), std::string::npos) << bad.error;
  }
  EXPECT_EQ(MakeContext("prog -null -platform neon"), nullptr);
  EXPECT_TRUE(Messages::Warned("bad value 'neon' for -platform")) << Messages::All();
}

// A context made with -platform sets the process default of the worlds
// made later; a backend the CPU cannot run falls back with a warning.
TEST(Options, PlatformSetsTheProcessDefault) {
  const std::string saved = MdtPlatformGetDefaultName();
  for (int i = 0; i < MdtPlatformCount(); ++i) {
    const std::string name = MdtPlatformName(i);
    Messages m;
    RRender *rc = MakeContext("prog -null -platform " + name);
    ASSERT_NE(rc, nullptr) << name;
    const bool supported = MdtPlatformIsSupported(name.c_str());
    EXPECT_EQ(MdtPlatformGetDefaultName(), supported ? name : std::string(MdtPlatformGetBestName())) << name;
    EXPECT_EQ(Messages::Warned("platform backend '" + name + "' is not available"), !supported) << Messages::All();
    RRenderContextDestroy(rc);
  }
  MdtPlatformSetDefault(saved.c_str());
}

TEST(Options, HelpListsEveryOption) {
  const std::string help = karma::viewer::HelpText();
  for (const char *o : {"-gl", "-d3d", "-null", "-bench", "-profile", "-frames", "-out", "-every", "-bmp", "-size",
                        "-platform", "-help"})
    EXPECT_NE(help.find(std::string("  ") + o), std::string::npos) << o;
}

TEST(OptionsDeathTest, HelpPrintsAndExitsWithZero) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        dup2(2, 1);  // the help goes to stdout; let the matcher see it
        MakeContext("prog -help");
      },
      ::testing::ExitedWithCode(0), "-frames N");
}

}  // namespace
