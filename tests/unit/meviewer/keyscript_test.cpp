// keyscript_test.cpp: the key-script parser, key names, and scripted input
// driving the control callbacks as a user's key presses would.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <fstream>

using karma::viewer::KeyEvent;
using karma::viewer::ParseKeyScript;
using viewer_test::MakeContext;
using viewer_test::Messages;
using viewer_test::TempDir;

namespace {

TEST(KeyScript, ParsesEveryVerbCommentsAndSeparators) {
  std::vector<KeyEvent> e;
  std::string error;
  ASSERT_TRUE(
      ParseKeyScript("10:press Up; 12:release up # a comment; ignored\n"
                     " 11 : key q\n5:action 2;7:mouse 320, 240 ,5; 9:mouse -3,4; 20:quit; ;",
                     e, error))
      << error;
  ASSERT_EQ(e.size(), 7u);
  // Sorted by frame, stable within a frame.
  EXPECT_EQ(e[0].kind, KeyEvent::Action);
  EXPECT_EQ(e[0].frame, 5);
  EXPECT_EQ(e[0].action, 2);
  EXPECT_EQ(e[1].kind, KeyEvent::Mouse);
  EXPECT_EQ(e[1].x, 320);
  EXPECT_EQ(e[1].y, 240);
  EXPECT_EQ(e[1].buttons, 5);
  EXPECT_EQ(e[2].x, -3);
  EXPECT_EQ(e[2].buttons, 0);
  EXPECT_EQ(e[3].kind, KeyEvent::Press);
  EXPECT_EQ(e[3].key, karma::viewer::kKeyUp);
  EXPECT_EQ(e[4].kind, KeyEvent::Tap);
  EXPECT_EQ(e[4].key, 'q');
  EXPECT_EQ(e[5].kind, KeyEvent::Release);
  EXPECT_EQ(e[5].frame, 12);
  EXPECT_EQ(e[6].kind, KeyEvent::Quit);
}

TEST(KeyScript, KeyNamesRoundTrip) {
  using namespace karma::viewer;
  for (int key : {int(kKeyUp), int(kKeyDown), int(kKeyLeft), int(kKeyRight), int(kKeyReturn), int(kKeyEscape),
                  int(kKeyTab), int(kKeySpace), int(kKeyF1), int(kKeyF1) + 11, int('a'), int('Z'), int('+')})
    EXPECT_EQ(ParseKeyName(KeyName(key)), key) << KeyName(key);
  EXPECT_EQ(ParseKeyName("RETURN"), kKeyReturn);
  EXPECT_EQ(ParseKeyName("F13"), -1);
  EXPECT_EQ(ParseKeyName("Enter"), -1);
}

TEST(KeyScript, BadScriptsNameTheEvent) {
  struct Case {
    const char *script, *mention;
  } cases[] = {{"10 press Up", "event 1 '10 press Up': want FRAME:VERB"},
               {"1:key a; x:key b", "event 2 'x:key b': the frame"},
               {"-1:key a", "the frame"},
               {"3:press Enter", "unknown key 'Enter'"},
               {"3:press", "unknown key ''"},
               {"3:action 6", "the action number must be 0..5"},
               {"3:mouse 1", "want mouse X,Y"},
               {"3:mouse 1,2,9", "want mouse X,Y"},
               {"3:quit now", "quit takes no argument"},
               {"3:jump", "unknown verb 'jump'"}};
  for (const Case &c : cases) {
    std::vector<KeyEvent> e;
    std::string error;
    EXPECT_FALSE(ParseKeyScript(c.script, e, error)) << c.script;
    EXPECT_NE(error.find(c.mention), std::string::npos) << c.script << " -> " << error;
  }
}

TEST(KeyScript, ContextCreationRefusesBadScriptsAndMissingFiles) {
  Messages m;
  EXPECT_EQ(MakeContext("prog -null -keys \"3:jump\""), nullptr);
  EXPECT_TRUE(Messages::Warned("unknown verb 'jump'")) << Messages::All();
  EXPECT_EQ(MakeContext("prog -null -keyfile /no/such/file.keys"), nullptr);
  EXPECT_TRUE(Messages::Warned("cannot read the key file")) << Messages::All();
}

// Records which callbacks ran, in order.
std::string gLog;
void MEAPI Up(RRender *, void *) { gLog += "up "; }
void MEAPI Up2(RRender *, void *) { gLog += "up2 "; }
void MEAPI Right(RRender *, void *) { gLog += "right "; }
void MEAPI Action(RRender *, void *data) { gLog += "action" + std::to_string(*static_cast<int *>(data)) + " "; }
void MEAPI Mouse(RRender *, int x, int y, int b, void *) {
  gLog += "mouse" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(b) + " ";
}

TEST(Controls, ScriptedInputRunsTheCallbacksFrameByFrame) {
  TempDir dir("keys");
  { std::ofstream(dir.path() / "more.keys") << "# from a file, after -keys\n4:key d\n4:key q\n"; }
  RRender *rc = MakeContext(
      "prog -null -keys \"0:key Up; 1:press w; 2:press w; 2:release w; 3:key w; "
      "1:key Return; 2:action 4; 3:mouse 7,8,1; 5:key Escape\" -keyfile " +
      (dir.path() / "more.keys").string());
  ASSERT_NE(rc, nullptr);
  static int two = 2, four = 4, five = 5;
  RRenderSetUpCallBack(rc, Up);
  RRenderSetUp2CallBack(rc, Up2);
  RRenderSetRight2CallBack(rc, Right);
  RRenderSetActionNCallBack(rc, 2, Action, &two);
  RRenderSetActionNCallBack(rc, 4, Action, &four);
  RRenderSetActionNCallBack(rc, 5, Action, &five);
  RRenderSetActionNKey(rc, 5, 'q');  // 'q' now presses action 5
  RRenderSetMouseCallBack(rc, Mouse, nullptr);
  gLog.clear();
  const char *expected[] = {"up ", "up2 action2 ", "action4 ", "up2 mouse7,8,1 ", "right action5 ", ""};
  for (int frame = 0; frame < 6; ++frame) {
    rc->m_nFrame = frame;
    gLog.clear();
    karma::viewer::ProcessInput(rc);
    EXPECT_EQ(gLog, expected[frame]) << "frame " << frame;  // w held at frame 2: no second press
  }
  EXPECT_TRUE(rc->m_pPrivate->quit);  // Escape at frame 5
  RRenderContextDestroy(rc);
}

TEST(Controls, BadArgumentsWarn) {
  Messages m;
  RRender *rc = MakeContext("prog -null");
  RRenderSetActionNCallBack(rc, 6, Action, nullptr);
  RRenderSetActionNKey(rc, 9, 'a');
  RRenderSetActionNKey(rc, 1, '\n');
  RRenderSetUpCallBack(nullptr, Up);
  EXPECT_GE(Messages::Warnings().size(), 4u) << Messages::All();
  EXPECT_TRUE(Messages::Warned("not an action"));
  RRenderContextDestroy(rc);
}

void MEAPI LogTick(RRender *rc, void *) { std::fprintf(stderr, "tick %d\n", rc->m_nFrame); }
void MEAPI PrintAction(RRender *rc, void *) { std::fprintf(stderr, "action2 at frame %d\n", rc->m_nFrame); }

TEST(ControlsDeathTest, RunAppliesEachFramesEventsBeforeItsTick) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        RRender *rc = MakeContext("prog -null -frames 10 -keys \"2:key Return; 3:quit\"");
        RRenderSetActionNCallBack(rc, 2, PrintAction, nullptr);
        RRun(rc, LogTick, nullptr);
      },
      ::testing::ExitedWithCode(0), "tick 1\naction2 at frame 2\ntick 2\ntick 3\n$");
}

}  // namespace
