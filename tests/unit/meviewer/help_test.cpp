// help_test.cpp: RParseText's substitutions and limits, text graphics going
// through it, and the help panel pausing the simulation.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cstring>

using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

std::string Parse(RRender *rc, const char *in, int size = 256) {
  std::vector<char> out(std::size_t(size) + 8, 'Z');
  std::string text = in;
  RParseText(rc, text.data(), out.data(), size);
  return out.data();
}

TEST(ParseText, SubstitutesEveryVariable) {
  RRender *rc = MakeContext("prog -null");
  ASSERT_NE(rc, nullptr);
  std::strcpy(rc->m_AppName, "RainbowChain");
  EXPECT_EQ(Parse(rc, "$UP $DOWN $LEFT $RIGHT"), "Up Down Left Right");
  EXPECT_EQ(Parse(rc, "$UP2 $DOWN2 $LEFT2 $RIGHT2"), "w s a d");
  EXPECT_EQ(Parse(rc, "$ACTION0 $ACTION1 $ACTION2 $ACTION3 $ACTION4 $ACTION5"), "Space Tab Return x c v");
  EXPECT_EQ(Parse(rc, "$ACTION1 - toggle options menu"), "Tab - toggle options menu");
  EXPECT_EQ(Parse(rc, "$MOUSE - apply mouse force"), "Mouse - apply mouse force");
  EXPECT_EQ(Parse(rc, "welcome to $APPNAME!"), "welcome to RainbowChain!");
  rc->m_AppName = const_cast<char *>("Other");  // assigning the pointer works too
  EXPECT_EQ(Parse(rc, "$APPNAME"), "Other");
  RRenderSetActionNKey(rc, 3, 'k');
  EXPECT_EQ(Parse(rc, "$ACTION3"), "k");
  RRenderContextDestroy(rc);
}

TEST(ParseText, LeavesUnknownVariablesAndLowercaseAlone) {
  RRender *rc = MakeContext("prog -null");
  EXPECT_EQ(Parse(rc, "$FOO $up $ $UPx 5$ $ACTION9"), "$FOO $up $ Upx 5$ $ACTION9");
  RRenderContextDestroy(rc);
}

TEST(ParseText, TruncatesToTheBufferAndTerminates) {
  RRender *rc = MakeContext("prog -null");
  EXPECT_EQ(Parse(rc, "$ACTION2 key", 5), "Retu");
  EXPECT_EQ(Parse(rc, "abc", 1), "");
  Messages m;
  char out[4];
  char in[] = "x";
  RParseText(rc, in, out, 0);
  RParseText(nullptr, in, out, 4);
  EXPECT_EQ(Messages::Warnings().size(), 2u);
  RRenderContextDestroy(rc);
}

TEST(ParseText, TextGraphicsAreParsedFirst) {
  RRender *rc = MakeContext("prog -null");
  const float white[4] = {1, 1, 1, 1};
  char text[] = "$ACTION2";
  RGraphic *g = RGraphicTextCreate(rc, text, 0, 0, white);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->m_pObject->m_nNumVertices, 6 * 6);  // "Return"
  RRenderContextDestroy(rc);
}

TEST(Help, PanelListsParsedLinesAndTogglesThePause) {
  RRender *rc = MakeContext("prog -null");
  char l0[] = "$ACTION1 - toggle options menu", l1[] = "$ACTION2 - reset", l2[] = "$MOUSE - apply mouse force";
  char *help[3] = {l0, l1, l2};
  RRenderCreateUserHelp(rc, help, 3);
  EXPECT_EQ(rc->m_pPrivate->help[1], "Return - reset");
  EXPECT_TRUE(karma::viewer::HelpOverlay(rc).empty());
  RRenderToggleUserHelp(rc);
  EXPECT_TRUE(rc->m_pPrivate->paused);
  std::vector<RGraphic *> g = karma::viewer::HelpOverlay(rc);
  EXPECT_EQ(g.size(), 1u + 1u + 3u);  // panel, title, lines
  for (RGraphic *x : g) RGraphicDestroy(x);
  karma::viewer::PressKey(rc, karma::viewer::kKeyF1);
  EXPECT_FALSE(rc->m_pPrivate->paused);
  EXPECT_FALSE(rc->m_pPrivate->helpShown);
  RRenderContextDestroy(rc);
}

void MEAPI LogTick(RRender *rc, void *) { std::fprintf(stderr, "tick %d\n", rc->m_nFrame); }

TEST(HelpDeathTest, TheHelpPausesTheTickUntilF1) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        RRender *rc = MakeContext("prog -null -frames 5 -keys \"3:key F1\"");
        RRenderToggleUserHelp(rc);  // as RainbowChain does: start with the help shown
        RRun(rc, LogTick, nullptr);
      },
      ::testing::ExitedWithCode(0), "^tick 3\ntick 4\n$");
}

}  // namespace
