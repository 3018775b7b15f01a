// MeCommandLineOptions: copying, flags, values, numbers, eating, lists,
// repeated options, splitting strings, NULL handling.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "MeCommandLineOptions.h"
#include "runtime_test_support.h"

using karma_test::MessageCapture;

namespace {

// The arguments left, program name included.
std::vector<std::string> argsOf(const MeCommandLineOptions *options) {
  std::vector<std::string> args;
  for (int i = 0; i < MeCommandLineOptionsGetCount(options); ++i)
    args.emplace_back(MeCommandLineOptionsGetArg(options, i));
  return args;
}

// Owns options built from a string for the length of a test.
class Options {
 public:
  explicit Options(const char *line) : options_(MeCommandLineOptionsCreateFromString(line)) {}
  ~Options() { MeCommandLineOptionsDestroy(options_); }
  Options(const Options &) = delete;
  Options &operator=(const Options &) = delete;
  MeCommandLineOptions *get() const { return options_; }

 private:
  MeCommandLineOptions *options_;
};

TEST(CommandLineTest, CreateCopiesTheArguments) {
  char name[] = "quadbike";
  char flag[] = "-frames";
  char value[] = "600";
  const char *argv[] = {name, flag, value};
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(3, argv);
  ASSERT_NE(options, nullptr);
  name[0] = flag[1] = value[0] = 'X';  // the copy must not follow
  EXPECT_EQ(argsOf(options), (std::vector<std::string>{"quadbike", "-frames", "600"}));
  EXPECT_EQ(options->m_argc, 3);
  EXPECT_EQ(options->m_argv[3], nullptr);
  EXPECT_EQ(MeCommandLineOptionsGetArg(options, 3), nullptr);
  EXPECT_EQ(MeCommandLineOptionsGetArg(options, -1), nullptr);
  MeCommandLineOptionsDestroy(options);
}

TEST(CommandLineTest, BadArgumentListsGiveAnEmptyCommandLine) {
  MessageCapture capture;
  const char *argv[] = {"prog", "-x"};
  MeCommandLineOptions *fromNull = MeCommandLineOptionsCreate(2, nullptr);
  MeCommandLineOptions *fromNegative = MeCommandLineOptionsCreate(-1, argv);
  MeCommandLineOptions *fromZero = MeCommandLineOptionsCreate(0, argv);
  EXPECT_EQ(capture.warnings().size(), 2u);
  for (MeCommandLineOptions *options : {fromNull, fromNegative, fromZero}) {
    ASSERT_NE(options, nullptr);
    EXPECT_EQ(argsOf(options), std::vector<std::string>{""});
    EXPECT_FALSE(MeCommandLineOptionsCheckFor(options, "-x", 1));
    MeCommandLineOptionsDestroy(options);
  }
}

TEST(CommandLineTest, NullEntriesBecomeEmptyStrings) {
  const char *argv[] = {"prog", nullptr, "-a"};
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(3, argv);
  EXPECT_EQ(argsOf(options), (std::vector<std::string>{"prog", "", "-a"}));
  MeCommandLineOptionsDestroy(options);
}

TEST(CommandLineTest, CheckForWithAndWithoutEating) {
  Options options("demo -gl -nofriction -gl");
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-nofriction", 0));
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-nofriction", 0));
  EXPECT_EQ(MeCommandLineOptionsGetCount(options.get()), 4);

  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-nofriction", 1));
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options.get(), "-nofriction", 1));
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-gl", "-gl"}));

  // Each eat consumes one occurrence.
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-gl", 1));
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-gl", 1));
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options.get(), "-gl", 1));
  EXPECT_EQ(argsOf(options.get()), std::vector<std::string>{"demo"});
  EXPECT_EQ(options.get()->m_argv[1], nullptr);
}

TEST(CommandLineTest, MatchingIsExactAndSkipsTheProgramName) {
  Options options("-gl -GL -glx");
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options.get(), "-gl", 0));
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options.get(), "-g", 0));
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-GL", 0));
  EXPECT_TRUE(MeCommandLineOptionsCheckFor(options.get(), "-glx", 0));
}

TEST(CommandLineTest, GetStringReturnsTheFollowingArgument) {
  Options options("demo -out frames/ -size 640x480");
  EXPECT_STREQ(MeCommandLineOptionsGetString(options.get(), "-out", 0), "frames/");
  EXPECT_EQ(MeCommandLineOptionsGetCount(options.get()), 5);
  const char *size = MeCommandLineOptionsGetString(options.get(), "-size", 1);
  const char *out = MeCommandLineOptionsGetString(options.get(), "-out", 1);
  EXPECT_EQ(argsOf(options.get()), std::vector<std::string>{"demo"});
  EXPECT_EQ(MeCommandLineOptionsGetString(options.get(), "-out", 1), nullptr);
  // Eaten strings stay valid until Destroy.
  EXPECT_STREQ(size, "640x480");
  EXPECT_STREQ(out, "frames/");
  EXPECT_EQ(MeCommandLineOptionsGetString(options.get(), "-absent", 1), nullptr);
}

TEST(CommandLineTest, ValueMayLookLikeAnOption) {
  Options options("demo -offset -5 -x");
  int offset = 0;
  EXPECT_TRUE(MeCommandLineOptionsGetInt(options.get(), "-offset", &offset, 1));
  EXPECT_EQ(offset, -5);
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-x"}));
}

TEST(CommandLineTest, MissingValueWarnsAndEatsTheLoneFlag) {
  MessageCapture capture;
  Options options("demo -a -out");
  EXPECT_EQ(MeCommandLineOptionsGetString(options.get(), "-out", 0), nullptr);
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("-out needs a value"), std::string::npos) << capture.lastWarning();
  EXPECT_EQ(MeCommandLineOptionsGetCount(options.get()), 3);
  EXPECT_EQ(MeCommandLineOptionsGetString(options.get(), "-out", 1), nullptr);
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-a"}));
}

TEST(CommandLineTest, GetIntParsesWholeNumbersOnly) {
  MessageCapture capture;
  Options options("demo -frames 600 -n 12x -big 99999999999 -blank \" 5\" -empty \"\" -neg -42");
  int value = 7;
  EXPECT_TRUE(MeCommandLineOptionsGetInt(options.get(), "-frames", &value, 0));
  EXPECT_EQ(value, 600);
  EXPECT_TRUE(MeCommandLineOptionsGetInt(options.get(), "-neg", &value, 0));
  EXPECT_EQ(value, -42);
  EXPECT_TRUE(capture.warnings().empty());

  value = 7;
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-n", &value, 0));
  EXPECT_EQ(value, 7) << "untouched on failure";
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("-n"), std::string::npos);
  EXPECT_NE(capture.lastWarning().find("\"12x\""), std::string::npos) << capture.lastWarning();

  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-big", &value, 0));
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-blank", &value, 0));
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-empty", &value, 0));
  EXPECT_EQ(capture.warnings().size(), 4u);
  EXPECT_EQ(value, 7);

  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-absent", &value, 0));
  EXPECT_EQ(capture.warnings().size(), 4u) << "an absent option is not an error";
}

TEST(CommandLineTest, GetFloatParsesFiniteNumbers) {
  MessageCapture capture;
  Options options("demo -g 9.81 -e 1e-3 -bad 0.5.1 -nan nan -inf inf -huge 1e400 -w abc");
  MeReal value = 3;
  EXPECT_TRUE(MeCommandLineOptionsGetFloat(options.get(), "-g", &value, 0));
  EXPECT_EQ(value, (MeReal)9.81);
  EXPECT_TRUE(MeCommandLineOptionsGetFloat(options.get(), "-e", &value, 0));
  EXPECT_EQ(value, (MeReal)0.001);
  EXPECT_TRUE(capture.warnings().empty());

  value = 3;
  for (const char *bad : {"-bad", "-nan", "-inf", "-huge", "-w"})
    EXPECT_FALSE(MeCommandLineOptionsGetFloat(options.get(), bad, &value, 0)) << bad;
  EXPECT_EQ(value, (MeReal)3);
  ASSERT_EQ(capture.warnings().size(), 5u);
  EXPECT_NE(capture.warnings()[0].text.find("-bad"), std::string::npos);
  EXPECT_NE(capture.warnings()[0].text.find("\"0.5.1\""), std::string::npos);
}

TEST(CommandLineTest, FloatRangeFollowsThePrecision) {
  MessageCapture capture;
  Options options("demo -v 1e39");
  MeReal value = 0;
  const bool parsed = MeCommandLineOptionsGetFloat(options.get(), "-v", &value, 0);
#if KARMA_DOUBLE
  EXPECT_TRUE(parsed);
  EXPECT_EQ(value, 1e39);
#else
  EXPECT_FALSE(parsed) << "1e39 does not fit in a float";
#endif
}

TEST(CommandLineTest, BadNumbersAreStillEaten) {
  MessageCapture capture;
  Options options("demo -n 12x -rest");
  int value = 0;
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-n", &value, 1));
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-rest"}));
}

TEST(CommandLineTest, CheckForListFindsTheEarliestListedName) {
  const char *renderers[] = {"-gl", "-null", "-bench", "-profile"};
  Options options("demo -x -bench -gl");
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), renderers, 4, 0), 2);
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), renderers, 4, 1), 2);
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-x", "-gl"}));
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), renderers, 4, 1), 0);
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), renderers, 4, 1), -1);
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-x"}));
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), renderers, 0, 1), -1);
}

TEST(CommandLineTest, RepeatedOptionsAreReadOneAtATime) {
  Options options("demo -I a -v -I b -I c");
  std::vector<std::string> dirs;
  while (const char *dir = MeCommandLineOptionsGetString(options.get(), "-I", 1)) dirs.emplace_back(dir);
  EXPECT_EQ(dirs, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"demo", "-v"}));
}

TEST(CommandLineTest, ViewerThenApplication) {
  // The viewer eats what it understands; the application sees the rest.
  const char *argv[] = {"chair", "-null", "-frames", "30", "-bodies", "8"};
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(6, argv);
  const char *renderers[] = {"-gl", "-null"};
  int frames = 0;
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options, renderers, 2, 1), 1);
  EXPECT_TRUE(MeCommandLineOptionsGetInt(options, "-frames", &frames, 1));
  EXPECT_EQ(frames, 30);

  int bodies = 0;
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options, "-null", 0));
  EXPECT_TRUE(MeCommandLineOptionsGetInt(options, "-bodies", &bodies, 0));
  EXPECT_EQ(bodies, 8);
  EXPECT_EQ(argsOf(options), (std::vector<std::string>{"chair", "-bodies", "8"}));
  MeCommandLineOptionsDestroy(options);
}

TEST(CommandLineTest, CreateFromStringSplitsAndHonoursQuotes) {
  Options options("  prog\t-title \"two words\" \"\" x\\\"y \"a\\\"b c\"  say\"s o\"k  ");
  EXPECT_EQ(argsOf(options.get()),
            (std::vector<std::string>{"prog", "-title", "two words", "", "x\"y", "a\"b c", "says ok"}));
  EXPECT_EQ(options.get()->m_argv[7], nullptr);
  EXPECT_STREQ(MeCommandLineOptionsGetString(options.get(), "-title", 0), "two words");
}

TEST(CommandLineTest, CreateFromEmptyStrings) {
  for (const char *line : {"", "   \t ", static_cast<const char *>(nullptr)}) {
    Options options(line);
    ASSERT_NE(options.get(), nullptr);
    EXPECT_EQ(argsOf(options.get()), std::vector<std::string>{""});
  }
  Options single("prog");
  EXPECT_EQ(argsOf(single.get()), std::vector<std::string>{"prog"});
}

TEST(CommandLineTest, UnclosedQuoteWarnsAndRunsToTheEnd) {
  MessageCapture capture;
  Options options("prog -t \"open  text");
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(argsOf(options.get()), (std::vector<std::string>{"prog", "-t", "open  text"}));
}

TEST(CommandLineTest, NullOptionsReadAsEmpty) {
  MessageCapture capture;
  const char *names[] = {"-gl"};
  int i = 5;
  MeReal r = 5;
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(nullptr, "-gl", 1));
  EXPECT_EQ(MeCommandLineOptionsCheckForList(nullptr, names, 1, 1), -1);
  EXPECT_EQ(MeCommandLineOptionsGetString(nullptr, "-gl", 1), nullptr);
  EXPECT_FALSE(MeCommandLineOptionsGetInt(nullptr, "-gl", &i, 1));
  EXPECT_FALSE(MeCommandLineOptionsGetFloat(nullptr, "-gl", &r, 1));
  EXPECT_EQ(MeCommandLineOptionsGetCount(nullptr), 0);
  EXPECT_EQ(MeCommandLineOptionsGetArg(nullptr, 0), nullptr);
  MeCommandLineOptionsDestroy(nullptr);
  EXPECT_TRUE(capture.warnings().empty());
  EXPECT_EQ(i, 5);
}

TEST(CommandLineTest, NullNamesWarn) {
  MessageCapture capture;
  Options options("prog -a");
  int i = 0;
  EXPECT_FALSE(MeCommandLineOptionsCheckFor(options.get(), nullptr, 0));
  EXPECT_EQ(MeCommandLineOptionsGetString(options.get(), nullptr, 0), nullptr);
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), "-a", nullptr, 0));
  EXPECT_FALSE(MeCommandLineOptionsGetInt(options.get(), nullptr, &i, 0));
  EXPECT_EQ(MeCommandLineOptionsCheckForList(options.get(), nullptr, 2, 0), -1);
  EXPECT_EQ(capture.warnings().size(), 5u);
  EXPECT_EQ(MeCommandLineOptionsGetCount(options.get()), 2);
}

}  // namespace
