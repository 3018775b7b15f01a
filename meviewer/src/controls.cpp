/* controls.cpp: the control callbacks and the input phase of a frame.
 *
 * Keys come from the -keys / -keyfile script (keyscript.cpp) and, with a
 * window, from the user (window_backend.cpp) after the script's events of
 * the frame; -record writes the user's events as a script that replays
 * them at the same frames. A key press runs, in this order of precedence: the open
 * menu's handling of it (menu.cpp), Escape's quit, F1's help toggle, the action whose key it
 * is (Action1 with no callback opens the default menu), the arrow-style
 * control bound to it. A key already down does not press again (no
 * auto-repeat); callbacks run on the press only, as the guide says. */
#include "viewer_internal.h"

#include <algorithm>

namespace karma::viewer {
namespace {

/* Up Up2 Down Down2 Left Left2 Right Right2 */
const int kArrowKeys[8] = {kKeyUp, 'w', kKeyDown, 's', kKeyLeft, 'a', kKeyRight, 'd'};

void RunAction(RRender *rc, int n) {
  Controls &c = rc->m_pPrivate->controls;
  if (c.action[n]) {
    c.action[n](rc, c.actionData[n]);
  } else if (n == 1 && rc->m_pPrivate->defaultMenu) {
    if (rc->m_pPrivate->shownMenu)
      rc->m_pPrivate->shownMenu = nullptr;
    else
      RMenuDisplay(rc->m_pPrivate->defaultMenu);
  }
}

void SetArrow(RRender *rc, int i, RButtonPressCallBack func, const char *fn) {
  ME_REQUIRE_ARG(rc, fn, "rc is NULL");
  rc->m_pPrivate->controls.arrows[i] = func;
}

}  // namespace

void PressKey(RRender *rc, int key) {
  RRenderPrivate *p = rc->m_pPrivate;
  Controls &c = p->controls;
  if (std::find(c.held.begin(), c.held.end(), key) != c.held.end()) return;
  c.held.push_back(key);
  if (p->shownMenu && MenuHandleKey(rc, key)) return;
  if (key == kKeyEscape) {
    p->quit = true;
    return;
  }
  if (key == kKeyF1) {
    RRenderToggleUserHelp(rc);
    return;
  }
  for (int n = 0; n < R_MAX_ACTIONS; ++n)
    if (c.actionKey[n] == key) {
      RunAction(rc, n);
      return;
    }
  for (int i = 0; i < 8; ++i)
    if (kArrowKeys[i] == key && c.arrows[i]) {
      c.arrows[i](rc, nullptr);
      return;
    }
}

void ReleaseKey(RRender *rc, int key) {
  std::vector<int> &held = rc->m_pPrivate->controls.held;
  held.erase(std::remove(held.begin(), held.end(), key), held.end());
}

namespace {

/* One recorded event: "FRAME:TEXT" on its own line. */
void Record(RRender *rc, const std::string &text) {
  std::FILE *f = rc->m_pPrivate->controls.record;
  if (!f) return;
  std::fprintf(f, "%d:%s\n", rc->m_nFrame, text.c_str());
  std::fflush(f);
}

}  // namespace

void LiveKey(RRender *rc, int key, bool down) {
  Record(rc, std::string(down ? "press " : "release ") + KeyName(key));
  if (down)
    PressKey(rc, key);
  else
    ReleaseKey(rc, key);
}

void LiveMouse(RRender *rc, int x, int y, int buttons) {
  Record(rc, "mouse " + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(buttons));
  Controls &c = rc->m_pPrivate->controls;
  if (c.mouse) c.mouse(rc, x, y, buttons, c.mouseData);
}

void LiveQuit(RRender *rc) {
  Record(rc, "quit");
  rc->m_pPrivate->quit = true;
}

void ProcessInput(RRender *rc) {
  RRenderPrivate *p = rc->m_pPrivate;
  Controls &c = p->controls;
  while (c.next < c.script.size() && c.script[c.next].frame <= rc->m_nFrame) {
    const KeyEvent &e = c.script[c.next++];
    switch (e.kind) {
      case KeyEvent::Press:
        PressKey(rc, e.key);
        break;
      case KeyEvent::Release:
        ReleaseKey(rc, e.key);
        break;
      case KeyEvent::Tap:
        PressKey(rc, e.key), ReleaseKey(rc, e.key);
        break;
      case KeyEvent::Action:
        RunAction(rc, e.action);
        break;
      case KeyEvent::Mouse:
        if (c.mouse) c.mouse(rc, e.x, e.y, e.buttons, c.mouseData);
        break;
      case KeyEvent::Quit:
        p->quit = true;
        break;
    }
  }
  p->backend->PollInput(rc);
}

}  // namespace karma::viewer

using namespace karma::viewer;

void MEAPI RRenderSetUpCallBack(RRender *rc, RButtonPressCallBack f) { SetArrow(rc, 0, f, "RRenderSetUpCallBack"); }
void MEAPI RRenderSetUp2CallBack(RRender *rc, RButtonPressCallBack f) { SetArrow(rc, 1, f, "RRenderSetUp2CallBack"); }
void MEAPI RRenderSetDownCallBack(RRender *rc, RButtonPressCallBack f) { SetArrow(rc, 2, f, "RRenderSetDownCallBack"); }
void MEAPI RRenderSetDown2CallBack(RRender *rc, RButtonPressCallBack f) {
  SetArrow(rc, 3, f, "RRenderSetDown2CallBack");
}
void MEAPI RRenderSetLeftCallBack(RRender *rc, RButtonPressCallBack f) { SetArrow(rc, 4, f, "RRenderSetLeftCallBack"); }
void MEAPI RRenderSetLeft2CallBack(RRender *rc, RButtonPressCallBack f) {
  SetArrow(rc, 5, f, "RRenderSetLeft2CallBack");
}
void MEAPI RRenderSetRightCallBack(RRender *rc, RButtonPressCallBack f) {
  SetArrow(rc, 6, f, "RRenderSetRightCallBack");
}
void MEAPI RRenderSetRight2CallBack(RRender *rc, RButtonPressCallBack f) {
  SetArrow(rc, 7, f, "RRenderSetRight2CallBack");
}

void MEAPI RRenderSetActionNCallBack(RRender *rc, int N, RButtonPressCallBack func, void *userdata) {
  ME_REQUIRE_ARG(rc, "RRenderSetActionNCallBack", "rc is NULL");
  ME_REQUIRE_ARG(N >= 0 && N < R_MAX_ACTIONS, "RRenderSetActionNCallBack", "N = %d is not an action (0..%d)", N,
                 R_MAX_ACTIONS - 1);
  rc->m_pPrivate->controls.action[N] = func;
  rc->m_pPrivate->controls.actionData[N] = userdata;
}

void MEAPI RRenderSetActionNKey(RRender *rc, const unsigned int N, const char key) {
  ME_REQUIRE_ARG(rc, "RRenderSetActionNKey", "rc is NULL");
  ME_REQUIRE_ARG(N < R_MAX_ACTIONS, "RRenderSetActionNKey", "N = %u is not an action (0..%d)", N, R_MAX_ACTIONS - 1);
  ME_REQUIRE_ARG(key > 32 && key < 127, "RRenderSetActionNKey", "the key must be a printable character");
  rc->m_pPrivate->controls.actionKey[N] = key;
}

void MEAPI RRenderSetMouseCallBack(RRender *rc, RMouseCallBack func, void *userdata) {
  ME_REQUIRE_ARG(rc, "RRenderSetMouseCallBack", "rc is NULL");
  rc->m_pPrivate->controls.mouse = func;
  rc->m_pPrivate->controls.mouseData = userdata;
}
