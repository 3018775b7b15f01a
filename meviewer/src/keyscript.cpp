/* keyscript.cpp: key names and the key-script language of -keys / -keyfile.
 *
 * A script is a list of events separated by ';' or new lines; '#' starts a
 * comment running to the end of its line; blanks around the parts are
 * ignored. Each event is FRAME:VERB [ARGUMENT]:
 *
 *   12:press KEY       KEY goes down at the start of frame 12 (its callback runs)
 *   12:release KEY     KEY comes up
 *   12:key KEY         press and release within frame 12
 *   12:action N        runs action N's callback directly (N in 0..5)
 *   12:mouse X,Y[,B]   the pointer moves to pixel (X, Y) with buttons B held
 *                      (bit 0 left, bit 1 middle, bit 2 right; default 0)
 *   12:quit            as if Escape were pressed
 *
 * KEY is one printable character (a, 7, +) or a name, in any case: Up Down
 * Left Right Return Escape Tab Space F1..F12, and Semicolon and Hash for the
 * two characters the grammar uses (KeyName writes those two by name). Frames count from 0 like the
 * output files; events of one frame happen in the order written, before
 * that frame's tick. */
#include "viewer_internal.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace karma::viewer {
namespace {

struct Named {
  const char *name;
  int key;
};
const Named kNames[] = {{"Up", kKeyUp},         {"Down", kKeyDown},     {"Left", kKeyLeft}, {"Right", kKeyRight},
                        {"Return", kKeyReturn}, {"Escape", kKeyEscape}, {"Tab", kKeyTab},   {"Space", kKeySpace},
                        {"Semicolon", ';'},     {"Hash", '#'}};

std::string Trim(const std::string &s) {
  const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

bool ParseLong(const std::string &text, long lo, long hi, long &out) {
  if (text.empty()) return false;
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno || *end || v < lo || v > hi) return false;
  out = v;
  return true;
}

bool SameNoCase(const std::string &a, const char *b) {
  if (a.size() != std::strlen(b)) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace

std::string KeyName(int key) {
  for (const Named &n : kNames)
    if (n.key == key) return n.name;
  if (key >= kKeyF1 && key <= kKeyF12) {
    std::string name = "F"; /* appended, not "F" + ...: GCC 12 warns falsely (-Wrestrict) */
    name += std::to_string(key - kKeyF1 + 1);
    return name;
  }
  if (key > 32 && key < 127) return std::string(1, char(key));
  return "?";
}

int ParseKeyName(const std::string &name) {
  if (name.size() == 1 && name[0] > 32 && name[0] < 127) return name[0];
  for (const Named &n : kNames)
    if (SameNoCase(name, n.name)) return n.key;
  if (name.size() >= 2 && (name[0] == 'F' || name[0] == 'f')) {
    long f = 0;
    if (ParseLong(name.substr(1), 1, 12, f)) return kKeyF1 + int(f) - 1;
  }
  return -1;
}

bool ParseKeyScript(const std::string &text, std::vector<KeyEvent> &out, std::string &error) {
  out.clear();
  /* Split into events: comments end at a new line; ';' and new lines separate. */
  std::vector<std::string> events;
  std::string current;
  bool comment = false;
  for (char c : text) {
    if (c == '\n') comment = false;
    if (comment) continue;
    if (c == '#') {
      comment = true;
      continue;
    }
    if (c == ';' || c == '\n') {
      events.push_back(current), current.clear();
    } else {
      current += c;
    }
  }
  events.push_back(current);
  int number = 0;
  for (const std::string &raw : events) {
    const std::string e = Trim(raw);
    if (e.empty()) continue;
    ++number;
    auto fail = [&](const std::string &why) {
      error = "key script event " + std::to_string(number) + " '" + e + "': " + why;
      return false;
    };
    const std::size_t colon = e.find(':');
    if (colon == std::string::npos) return fail("want FRAME:VERB, e.g. 10:key Return");
    KeyEvent ev;
    if (!ParseLong(Trim(e.substr(0, colon)), 0, 2000000000L, ev.frame))
      return fail("the frame must be a whole number >= 0");
    const std::string rest = Trim(e.substr(colon + 1));
    const std::size_t space = rest.find_first_of(" \t");
    const std::string verb = rest.substr(0, space), arg = space == std::string::npos ? "" : Trim(rest.substr(space));
    if (verb == "press" || verb == "release" || verb == "key") {
      ev.kind = verb == "press" ? KeyEvent::Press : verb == "release" ? KeyEvent::Release : KeyEvent::Tap;
      ev.key = ParseKeyName(arg);
      if (ev.key < 0)
        return fail("unknown key '" + arg +
                    "' (a printable character, or Up Down Left Right Return Escape Tab Space "
                    "Semicolon Hash F1..F12)");
    } else if (verb == "action") {
      long n = 0;
      if (!ParseLong(arg, 0, R_MAX_ACTIONS - 1, n))
        return fail("the action number must be 0.." + std::to_string(R_MAX_ACTIONS - 1));
      ev.kind = KeyEvent::Action, ev.action = int(n);
    } else if (verb == "mouse") {
      std::vector<std::string> parts;
      std::size_t start = 0;
      for (std::size_t comma; (comma = arg.find(',', start)) != std::string::npos; start = comma + 1)
        parts.push_back(Trim(arg.substr(start, comma - start)));
      parts.push_back(Trim(arg.substr(start)));
      long x = 0, y = 0, b = 0;
      if (parts.size() < 2 || parts.size() > 3 || !ParseLong(parts[0], -100000, 100000, x) ||
          !ParseLong(parts[1], -100000, 100000, y) || (parts.size() == 3 && !ParseLong(parts[2], 0, 7, b)))
        return fail("want mouse X,Y or mouse X,Y,BUTTONS (buttons 0..7)");
      ev.kind = KeyEvent::Mouse, ev.x = int(x), ev.y = int(y), ev.buttons = int(b);
    } else if (verb == "quit") {
      if (!arg.empty()) return fail("quit takes no argument");
      ev.kind = KeyEvent::Quit;
    } else {
      return fail("unknown verb '" + verb + "' (press, release, key, action, mouse, quit)");
    }
    out.push_back(ev);
  }
  std::stable_sort(out.begin(), out.end(), [](const KeyEvent &a, const KeyEvent &b) { return a.frame < b.frame; });
  return true;
}

const char *KeyScriptHelp() {
  return "Key scripts (-keys \"SCRIPT\" or -keyfile FILE) drive the program's controls:\n"
         "  events separated by ';' or new lines, '#' comments; each is FRAME:VERB [ARGUMENT]\n"
         "    12:press KEY  12:release KEY  12:key KEY (press and release)  12:action N\n"
         "    12:mouse X,Y[,BUTTONS]  12:quit\n"
         "  KEY: a printable character or Up Down Left Right Return Escape Tab Space F1..F12\n"
         "  Controls: Up/Down/Left/Right = arrow keys, Up2/Down2/Left2/Right2 = w s a d,\n"
         "  actions 0..5 = Space Tab Return x c v, Escape quits (or closes a menu),\n"
         "  F1 shows or hides the help (and pauses or resumes the simulation),\n"
         "  Action1's key opens the default menu when the program has no Action1 callback.\n"
         "  Example: -keys \"10:key Return; 20:press Up; 30:release Up; 40:mouse 320,240,1\"\n";
}

}  // namespace karma::viewer
