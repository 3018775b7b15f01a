// live_input_test.cpp: a window's input (LiveKey, LiveMouse, LiveQuit) runs
// the same callbacks as a key script, and -record writes it as a key script
// that parses back to the same events at the same frame. Every key's name
// reads back as the key, in a script too (';' and '#' by name).
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cstdio>
#include <fstream>
#include <iterator>

using namespace karma::viewer;
using viewer_test::MakeContext;
using viewer_test::TempDir;

namespace {

int upPresses = 0;
int mouseX = -1, mouseY = -1, mouseButtons = -1;
void MEAPI OnUp(RRender *, void *) { ++upPresses; }
void MEAPI OnMouse(RRender *, int x, int y, int b, void *) { mouseX = x, mouseY = y, mouseButtons = b; }

TEST(LiveInput, RunsTheCallbacksAndRecordsAKeyScript) {
  TempDir dir("liveinput");
  const std::string path = (dir.path() / "live.keys").string();
  RRender *rc = MakeContext("prog -null");
  ASSERT_NE(rc, nullptr);
  RRenderSetUpCallBack(rc, OnUp);
  RRenderSetMouseCallBack(rc, OnMouse, nullptr);
  rc->m_pPrivate->controls.record = std::fopen(path.c_str(), "w");
  ASSERT_NE(rc->m_pPrivate->controls.record, nullptr);
  upPresses = 0;
  rc->m_nFrame = 7;
  LiveKey(rc, kKeyUp, true);
  LiveKey(rc, kKeyUp, true); /* held: no second press */
  LiveMouse(rc, 12, 34, 5);
  rc->m_nFrame = 9;
  LiveKey(rc, kKeyUp, false);
  LiveKey(rc, ';', true);
  LiveQuit(rc);
  EXPECT_EQ(upPresses, 1);
  EXPECT_EQ(mouseX, 12);
  EXPECT_EQ(mouseY, 34);
  EXPECT_EQ(mouseButtons, 5);
  EXPECT_TRUE(rc->m_pPrivate->quit);
  RRenderContextDestroy(rc); /* closes the record */

  std::ifstream f(path);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::vector<KeyEvent> events;
  std::string error;
  ASSERT_TRUE(ParseKeyScript(text, events, error)) << error << "\n" << text;
  ASSERT_EQ(events.size(), 6u) << text;
  /* press Up (the held repeat is recorded too, and replays as a no-op),
   * mouse, release Up, press ';', quit */
  EXPECT_EQ(events[0].frame, 7);
  EXPECT_EQ(events[0].kind, KeyEvent::Press);
  EXPECT_EQ(events[1].kind, KeyEvent::Press);
  EXPECT_EQ(events[0].key, kKeyUp);
  EXPECT_EQ(events[2].kind, KeyEvent::Mouse);
  EXPECT_EQ(events[2].frame, 7);
  EXPECT_EQ(events[2].x, 12);
  EXPECT_EQ(events[2].y, 34);
  EXPECT_EQ(events[2].buttons, 5);
  EXPECT_EQ(events[3].frame, 9);
  EXPECT_EQ(events[3].kind, KeyEvent::Release);
  EXPECT_EQ(events[4].kind, KeyEvent::Press);
  EXPECT_EQ(events[4].key, ';');
  EXPECT_EQ(events[5].kind, KeyEvent::Quit);
  EXPECT_EQ(events[5].frame, 9);
}

TEST(LiveInput, EveryKeyNameReadsBackInAScript) {
  std::vector<int> keys;
  for (int c = 33; c < 127; ++c) keys.push_back(c);
  for (int k = kKeyUp; k <= kKeyF12; ++k) keys.push_back(k);
  for (int key : keys) {
    const std::string name = KeyName(key);
    EXPECT_EQ(ParseKeyName(name), key) << name;
    std::vector<KeyEvent> events;
    std::string error;
    ASSERT_TRUE(ParseKeyScript("3:press " + name, events, error)) << name << ": " << error;
    ASSERT_EQ(events.size(), 1u) << name;
    EXPECT_EQ(events[0].key, key) << name;
  }
}

}  // namespace
