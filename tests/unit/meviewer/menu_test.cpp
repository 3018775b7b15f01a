// menu_test.cpp: menus driven by keys: opening the default menu with
// Action1's key, moving the highlight, stepping values within their
// bounds, toggles, submenus and Escape, callbacks on every change, and
// menus changed by a -keys script inside RRun.
#include "viewer_internal.h"
#include "viewer_test_support.h"

using karma::viewer::PressKey;
using karma::viewer::ReleaseKey;
using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

std::vector<double> gValues;
std::vector<int> gToggles;
void MEAPI OnValue(MeReal v) { gValues.push_back(double(v)); }
void MEAPI OnToggle(MeBool on) { gToggles.push_back(on); }

class Menus : public ::testing::Test {
 protected:
  void SetUp() override {
    gValues.clear(), gToggles.clear();
    rc = MakeContext("prog -null");
    ASSERT_NE(rc, nullptr);
    main = RMenuCreate(rc, "Options");
    sub = RMenuCreate(rc, "More");
    RMenuAddToggleEntry(main, "gravity", OnToggle, 1);
    RMenuAddValueEntry(main, "friction", OnValue, 1, 0, 0.25, 0.5);
    RMenuAddSubmenuEntry(main, "more", sub);
    RMenuAddValueEntry(sub, "speed", OnValue, 10, -10, 5, 0);
    RRenderSetDefaultMenu(rc, main);
  }
  void TearDown() override { RRenderContextDestroy(rc); }
  void Tap(int key) { PressKey(rc, key), ReleaseKey(rc, key); }
  RMenu *Shown() { return rc->m_pPrivate->shownMenu; }
  RRender *rc = nullptr;
  RMenu *main = nullptr, *sub = nullptr;
};

TEST_F(Menus, Action1KeyOpensAndClosesTheDefaultMenu) {
  EXPECT_EQ(Shown(), nullptr);
  Tap(karma::viewer::kKeyTab);
  EXPECT_EQ(Shown(), main);
  Tap(karma::viewer::kKeyTab);
  EXPECT_EQ(Shown(), nullptr);
}

TEST_F(Menus, ValuesStepWithinBoundsAndCallBackOnChange) {
  using namespace karma::viewer;
  RMenuDisplay(main);
  Tap(kKeyDown);                                   // friction
  Tap(kKeyRight), Tap(kKeyRight), Tap(kKeyRight);  // 0.75, 1, stays 1
  Tap(kKeyLeft);                                   // 0.75
  EXPECT_EQ(gValues, (std::vector<double>{0.75, 1, 0.75}));
  Tap(kKeyUp);  // gravity
  Tap(kKeyReturn), Tap(kKeyLeft);
  EXPECT_EQ(gToggles, (std::vector<int>{0, 1}));
}

TEST_F(Menus, SubmenusOpenWithReturnAndEscapeGoesBack) {
  using namespace karma::viewer;
  RMenuDisplay(main);
  Tap(kKeyUp);  // wraps to the last entry: "more"
  Tap(kKeyReturn);
  EXPECT_EQ(Shown(), sub);
  Tap(kKeyLeft);
  EXPECT_EQ(gValues, (std::vector<double>{-5}));
  Tap(kKeyEscape);
  EXPECT_EQ(Shown(), main);
  EXPECT_FALSE(rc->m_pPrivate->quit);  // Escape closed a menu, not the program
  Tap(kKeyEscape);
  EXPECT_EQ(Shown(), nullptr);
  Tap(kKeyEscape);
  EXPECT_TRUE(rc->m_pPrivate->quit);
}

TEST_F(Menus, DestroyingAMenuDetachesItEverywhere) {
  RMenuDisplay(sub);
  RMenuDestroy(sub);
  EXPECT_EQ(Shown(), nullptr);
  RMenuDisplay(main);
  Tap(karma::viewer::kKeyUp);
  Tap(karma::viewer::kKeyReturn);  // the submenu entry now does nothing
  EXPECT_EQ(Shown(), main);
  RMenuDestroy(main);
  EXPECT_EQ(rc->m_pPrivate->defaultMenu, nullptr);
  Tap(karma::viewer::kKeyTab);  // no default menu: nothing opens
  EXPECT_EQ(Shown(), nullptr);
}

TEST_F(Menus, AnAction1CallbackTakesTheKeyFromTheMenu) {
  static int calls = 0;
  RRenderSetActionNCallBack(
      rc, 1, [](RRender *, void *) { ++calls; }, nullptr);
  Tap(karma::viewer::kKeyTab);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(Shown(), nullptr);
}

TEST_F(Menus, OverlayShowsTitleAndEveryEntry) {
  RMenuDisplay(main);
  const std::vector<RGraphic *> g = karma::viewer::MenuOverlay(rc);
  EXPECT_EQ(g.size(), 1u + 1u + 3u);  // panel, title, three entries
  for (RGraphic *x : g) RGraphicDestroy(x);
  EXPECT_EQ(rc->m_pRG_First2D, nullptr);  // nothing left in the program's list
}

TEST(MenusBadInput, NullsAndBadRangesWarn) {
  Messages m;
  RRender *rc = MakeContext("prog -null");
  RMenu *menu = RMenuCreate(rc, "m");
  RMenuAddValueEntry(menu, "bad", OnValue, 0, 1, 0.1, 0.5);  // lo > hi
  RMenuAddSubmenuEntry(menu, "self", menu);
  RMenuDisplay(nullptr);
  EXPECT_EQ(RMenuCreate(nullptr, "x"), nullptr);
  RMenuDestroy(nullptr);
  EXPECT_GE(Messages::Warnings().size(), 4u) << Messages::All();
  RRenderContextDestroy(rc);  // frees the menu
}

void MEAPI PrintValue(MeReal v) { std::fprintf(stderr, "value %g\n", double(v)); }

TEST(MenusDeathTest, AScriptChangesAMenuValueInsideRRun) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        RRender *rc = MakeContext("prog -null -frames 5 -keys \"1:key Tab; 2:key Right; 3:key Right; 4:key Tab\"");
        RMenu *menu = RMenuCreate(rc, "Options");
        RMenuAddValueEntry(menu, "speed", PrintValue, 3, 0, 1.5, 0);
        RRenderSetDefaultMenu(rc, menu);
        RRun(rc, static_cast<RMainLoopCallBack>(nullptr), nullptr);
      },
      ::testing::ExitedWithCode(0), "value 1.5\nvalue 3\n$");
}

}  // namespace
