/* help.cpp: RParseText and the user help panel.
 *
 * Variables are '$' followed by the longest run of capitals and digits:
 *   $UP $DOWN $LEFT $RIGHT        the arrow keys' names ("Up", ...)
 *   $UP2 $DOWN2 $LEFT2 $RIGHT2    "w" "s" "a" "d"
 *   $ACTION0 .. $ACTION5          the key bound to the action ("Tab", "Return", ...)
 *   $MOUSE                        "Mouse"
 *   $APPNAME                      rc->m_AppName
 * Anything else after '$' is copied as it is. The help panel is drawn like
 * a menu: a translucent panel of the parsed lines under the title
 * "<app name> help", while RRenderToggleUserHelp (or F1) has it shown. */
#include "viewer_internal.h"

#include <algorithm>
#include <cstring>

using namespace karma::viewer;

namespace karma::viewer {
namespace {

bool Lookup(const RRender *rc, const std::string &name, std::string &value) {
  static const struct {
    const char *name;
    int key;
  } kKeys[] = {{"UP", kKeyUp}, {"DOWN", kKeyDown}, {"LEFT", kKeyLeft}, {"RIGHT", kKeyRight},
               {"UP2", 'w'},   {"DOWN2", 's'},     {"LEFT2", 'a'},     {"RIGHT2", 'd'}};
  for (const auto &k : kKeys)
    if (name == k.name) return value = KeyName(k.key), true;
  if (name.size() == 7 && name.compare(0, 6, "ACTION") == 0 && name[6] >= '0' && name[6] < '0' + R_MAX_ACTIONS)
    return value = KeyName(rc->m_pPrivate->controls.actionKey[name[6] - '0']), true;
  if (name == "MOUSE") return value = "Mouse", true;
  if (name == "APPNAME") return value = rc->m_AppName ? rc->m_AppName : "", true;
  return false;
}

}  // namespace

std::string ParseText(const RRender *rc, const char *text) {
  std::string out;
  for (const char *c = text; *c;) {
    if (*c != '$') {
      out += *c++;
      continue;
    }
    const char *start = c + 1, *end = start;
    while ((*end >= 'A' && *end <= 'Z') || (*end >= '0' && *end <= '9')) ++end;
    std::string value;
    if (end > start && Lookup(rc, std::string(start, end), value)) {
      out += value;
      c = end;
    } else {
      out += *c++;
    }
  }
  return out;
}

std::vector<RGraphic *> HelpOverlay(RRender *rc) {
  std::vector<RGraphic *> out;
  RRenderPrivate *p = rc->m_pPrivate;
  if (!p->helpShown) return out;
  constexpr float line = R_TEXT_CHAR_HEIGHT + 4, pad = 10;
  std::string title = std::string(rc->m_AppName ? rc->m_AppName : "") + " help (F1 hides it)";
  std::size_t widest = title.size();
  for (const std::string &l : p->help) widest = std::max(widest, l.size());
  const float w = 2 * pad + float(widest) * 6.5f, h = 2 * pad + line * float(p->help.size() + 1);
  const float x = (R_2D_WIDTH - w) / 2, y = (R_2D_HEIGHT - h) / 2;
  const float panel[4] = {0, 0, 0.1f, 0.75f}, white[4] = {1, 1, 1, 1}, blue[4] = {0.6f, 0.8f, 1, 1};
  auto detach = [&](RGraphic *g) {
    if (g) RGraphicRemoveFromList(rc, g, 1), out.push_back(g);
  };
  detach(RGraphic2DRectangleCreate(rc, x, y, w, h, panel));
  detach(RGraphicTextCreate(rc, title.data(), x + pad, y + pad, blue));
  for (std::size_t i = 0; i < p->help.size(); ++i) {
    std::string text = p->help[i];
    detach(RGraphicTextCreate(rc, text.data(), x + pad, y + pad + line * float(i + 1), white));
  }
  return out;
}

}  // namespace karma::viewer

void MEAPI RParseText(RRender *rc, char *text_in, char *text_out, int outbuffersize) {
  ME_REQUIRE_ARG(rc && text_in && text_out && outbuffersize > 0, "RParseText",
                 "rc, text_in or text_out is NULL, or outbuffersize < 1");
  const std::string s = ParseText(rc, text_in);
  const std::size_t n = std::min(s.size(), std::size_t(outbuffersize) - 1);
  std::memcpy(text_out, s.data(), n);
  text_out[n] = 0;
}

void MEAPI RRenderCreateUserHelp(RRender *rc, char *help[], int arraySize) {
  ME_REQUIRE_ARG(rc, "RRenderCreateUserHelp", "rc is NULL");
  ME_REQUIRE_ARG(arraySize >= 0 && (help || arraySize == 0), "RRenderCreateUserHelp", "help is NULL or arraySize < 0");
  rc->m_pPrivate->help.clear();
  for (int i = 0; i < arraySize; ++i) rc->m_pPrivate->help.push_back(help[i] ? ParseText(rc, help[i]) : "");
}

void MEAPI RRenderToggleUserHelp(RRender *rc) {
  ME_REQUIRE_ARG(rc, "RRenderToggleUserHelp", "rc is NULL");
  rc->m_pPrivate->helpShown = !rc->m_pPrivate->helpShown;
  rc->m_pPrivate->paused = rc->m_pPrivate->helpShown;
}
