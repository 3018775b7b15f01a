/* menu.cpp: the on-screen menus of the guide's "Menu System".
 *
 * A menu is a title and entries of three kinds: toggle (on/off), value (a
 * number stepped by `increment` and kept in [lo, hi]) and submenu. One menu
 * of a context is open at a time (RRenderPrivate::shownMenu); it draws as
 * a translucent panel of text at the top left of the 2D screen, the
 * highlighted entry in yellow and marked '>'. Key handling is described in
 * MeViewer.h. A submenu remembers the menu it was opened from, so Escape
 * goes back there. */
#include "viewer_internal.h"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace karma::viewer;

struct RMenuEntry {
  enum Kind { Toggle, Value, Submenu } kind = Toggle;
  std::string name;
  RMenuToggleCallback toggle = nullptr;
  RMenuValueCallback value = nullptr;
  MeReal hi = 0, lo = 0, increment = 0, current = 0;
  bool on = false;
  RMenu *submenu = nullptr;
};

struct RMenu {
  RRender *rc = nullptr;
  std::string name;
  std::vector<RMenuEntry> entries;
  int highlight = 0;
  RMenu *parent = nullptr; /* the menu this one was opened from */
};

namespace {

void Step(RMenuEntry &e, int direction) {
  if (e.kind == RMenuEntry::Toggle) {
    e.on = !e.on;
    if (e.toggle) e.toggle(e.on ? 1 : 0);
  } else if (e.kind == RMenuEntry::Value) {
    const MeReal v = std::clamp(e.current + MeReal(direction) * e.increment, e.lo, e.hi);
    if (v != e.current) {
      e.current = v;
      if (e.value) e.value(v);
    }
  }
}

std::string EntryText(const RMenuEntry &e) {
  char buffer[64];
  switch (e.kind) {
    case RMenuEntry::Toggle:
      return e.name + ": " + (e.on ? "on" : "off");
    case RMenuEntry::Value:
      std::snprintf(buffer, sizeof buffer, "%g", double(e.current));
      return e.name + ": " + buffer;
    case RMenuEntry::Submenu:
      return e.name + " >";
  }
  return e.name;
}

RGraphic *Detached(RRender *rc, RGraphic *g) {
  if (g) RGraphicRemoveFromList(rc, g, 1);
  return g;
}

}  // namespace

namespace karma::viewer {

bool MenuHandleKey(RRender *rc, int key) {
  RRenderPrivate *p = rc->m_pPrivate;
  RMenu *m = p->shownMenu;
  if (!m) return false;
  const int n = int(m->entries.size());
  if (key == kKeyEscape) {
    p->shownMenu = m->parent;
    m->parent = nullptr;
    return true;
  }
  if (key == p->controls.actionKey[1]) {
    p->shownMenu = nullptr;
    return true;
  }
  if (n == 0) return false;
  RMenuEntry &e = m->entries[std::size_t(m->highlight)];
  switch (key) {
    case kKeyUp:
      m->highlight = (m->highlight + n - 1) % n;
      return true;
    case kKeyDown:
      m->highlight = (m->highlight + 1) % n;
      return true;
    case kKeyLeft:
      Step(e, -1);
      return true;
    case kKeyRight:
      Step(e, +1);
      return true;
    case kKeyReturn:
      if (e.kind == RMenuEntry::Submenu) {
        if (e.submenu) {
          e.submenu->parent = m;
          p->shownMenu = e.submenu;
        }
      } else if (e.kind == RMenuEntry::Toggle) {
        Step(e, +1);
      }
      return true;
    default:
      return false;
  }
}

std::vector<RGraphic *> MenuOverlay(RRender *rc) {
  std::vector<RGraphic *> out;
  const RMenu *m = rc->m_pPrivate->shownMenu;
  if (!m) return out;
  constexpr float x = 20, y = 20, line = R_TEXT_CHAR_HEIGHT + 4, pad = 8;
  std::size_t widest = m->name.size();
  for (const RMenuEntry &e : m->entries) widest = std::max(widest, EntryText(e).size() + 2);
  const float panel[4] = {0, 0, 0, 0.6f}, white[4] = {1, 1, 1, 1}, yellow[4] = {1, 0.9f, 0.2f, 1},
              title[4] = {0.6f, 0.8f, 1, 1};
  out.push_back(Detached(rc, RGraphic2DRectangleCreate(rc, x, y, 2 * pad + float(widest) * 6.5f,
                                                       2 * pad + line * float(m->entries.size() + 1), panel)));
  std::string text = m->name;
  out.push_back(Detached(rc, RGraphicTextCreate(rc, text.data(), x + pad, y + pad, title)));
  for (std::size_t i = 0; i < m->entries.size(); ++i) {
    const bool lit = int(i) == m->highlight;
    text = (lit ? "> " : "  ") + EntryText(m->entries[i]);
    out.push_back(Detached(
        rc, RGraphicTextCreate(rc, text.data(), x + pad, y + pad + line * float(i + 1), lit ? yellow : white)));
  }
  out.erase(std::remove(out.begin(), out.end(), nullptr), out.end());
  return out;
}

void DestroyMenus(RRender *rc) {
  while (!rc->m_pPrivate->menus.empty()) RMenuDestroy(rc->m_pPrivate->menus.back());
}

}  // namespace karma::viewer

RMenu *MEAPI RMenuCreate(RRender *rc, const char *name) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RMenuCreate", "rc is NULL");
  RMenu *m = new RMenu;
  m->rc = rc;
  m->name = name ? name : "";
  rc->m_pPrivate->menus.push_back(m);
  return m;
}

void MEAPI RMenuDestroy(RMenu *rm) {
  if (!rm) return;
  RRenderPrivate *p = rm->rc->m_pPrivate;
  if (p->shownMenu == rm) p->shownMenu = nullptr;
  if (p->defaultMenu == rm) p->defaultMenu = nullptr;
  for (RMenu *other : p->menus) {
    if (other->parent == rm) other->parent = nullptr;
    for (RMenuEntry &e : other->entries)
      if (e.submenu == rm) e.submenu = nullptr; /* the entry stays and does nothing */
  }
  p->menus.erase(std::remove(p->menus.begin(), p->menus.end(), rm), p->menus.end());
  delete rm;
}

void MEAPI RRenderSetDefaultMenu(RRender *rc, RMenu *menu) {
  ME_REQUIRE_ARG(rc, "RRenderSetDefaultMenu", "rc is NULL");
  ME_REQUIRE_ARG(!menu || menu->rc == rc, "RRenderSetDefaultMenu", "the menu belongs to another render context");
  rc->m_pPrivate->defaultMenu = menu;
}

void MEAPI RMenuDisplay(RMenu *rm) {
  ME_REQUIRE_ARG(rm, "RMenuDisplay", "rm is NULL");
  rm->rc->m_pPrivate->shownMenu = rm;
}

void MEAPI RMenuAddToggleEntry(RMenu *rm, const char *name, RMenuToggleCallback func, MeBool defaultValue) {
  ME_REQUIRE_ARG(rm && name, "RMenuAddToggleEntry", "rm or name is NULL");
  RMenuEntry e;
  e.kind = RMenuEntry::Toggle, e.name = name, e.toggle = func, e.on = defaultValue != 0;
  rm->entries.push_back(e);
}

void MEAPI RMenuAddValueEntry(RMenu *rm, const char *name, RMenuValueCallback func, MeReal hi, MeReal lo,
                              MeReal increment, MeReal defaultValue) {
  ME_REQUIRE_ARG(rm && name, "RMenuAddValueEntry", "rm or name is NULL");
  ME_REQUIRE_ARG(lo <= hi && increment >= 0, "RMenuAddValueEntry", "'%s': need lo <= hi and increment >= 0", name);
  RMenuEntry e;
  e.kind = RMenuEntry::Value, e.name = name, e.value = func;
  e.hi = hi, e.lo = lo, e.increment = increment, e.current = defaultValue;
  rm->entries.push_back(e);
}

void MEAPI RMenuAddSubmenuEntry(RMenu *rm, const char *name, RMenu *submenu) {
  ME_REQUIRE_ARG(rm && name, "RMenuAddSubmenuEntry", "rm or name is NULL");
  ME_REQUIRE_ARG(submenu != rm, "RMenuAddSubmenuEntry", "a menu cannot be its own submenu");
  RMenuEntry e;
  e.kind = RMenuEntry::Submenu, e.name = name, e.submenu = submenu;
  rm->entries.push_back(e);
}
