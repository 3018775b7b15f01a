/* options.cpp: the viewer's command-line options (-help lists them).
 *
 * Each option is looked up in the program's options and then in the
 * override options; a value found in the overrides replaces the first. With
 * eat true, every occurrence is removed, so the program sees only its own
 * options afterwards. A malformed value fails context creation with a
 * message that names the option. */
#include "viewer_internal.h"

#include "MdtPlatform.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace karma::viewer {
namespace {

const char *const kBackendNames[] = {"-gl", "-d3d", "-null", "-bench", "-profile", "-window"};
const BackendKind kBackendKinds[] = {BackendKind::GL,    BackendKind::GL,      BackendKind::Null,
                                     BackendKind::Bench, BackendKind::Profile, BackendKind::Window};
constexpr int kBackendCount = 6;

/* Options taking a value, then flags; used for the misspelling check. */
const char *const kKnownOptions[] = {"-gl",      "-d3d",   "-null",   "-bench",  "-profile",    "-frames",
                                     "-out",     "-every", "-bmp",    "-size",   "-help",       "-keys",
                                     "-keyfile", "-video", "-window", "-record", "-screenshot", "-accuracy"};
/* Options the project's own programs read (golden runs pass them to every
 * program), never reported as unknown. The viewer reads -platform too, but
 * leaves it in place for the program. */
const char *const kProgramOptions[] = {"-platform", "-trajectory"};

bool ParseLong(const char *text, long lo, long hi, long &out) {
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(text, &end, 10);
  if (errno || end == text || *end || v < lo || v > hi) return false;
  out = v;
  return true;
}

/* "WxH", both in 16..8192. */
bool ParseSize(const char *text, int &w, int &h) {
  const char *x = std::strchr(text, 'x');
  if (!x || x == text) return false;
  const std::string ws(text, static_cast<std::size_t>(x - text));
  long lw = 0, lh = 0;
  if (!ParseLong(ws.c_str(), 16, 8192, lw) || !ParseLong(x + 1, 16, 8192, lh)) return false;
  w = static_cast<int>(lw), h = static_cast<int>(lh);
  return true;
}

/* The value of `name` (the last occurrence when eating), or nullptr. A
 * trailing option without a value sets `missing`. */
const char *Value(MeCommandLineOptions *o, const char *name, bool eat, bool &missing) {
  if (!o || !MeCommandLineOptionsCheckFor(o, name, 0)) return nullptr;
  if (!eat) {
    const char *found = MeCommandLineOptionsGetString(o, name, 0);
    if (!found) missing = true;
    return found;
  }
  const char *found = nullptr;
  while (MeCommandLineOptionsCheckFor(o, name, 0)) {
    const char *s = MeCommandLineOptionsGetString(o, name, 1);
    if (s)
      found = s;
    else
      missing = true;
  }
  return found;
}

bool Flag(MeCommandLineOptions *o, const char *name, bool eat) {
  bool any = false;
  while (o && MeCommandLineOptionsCheckFor(o, name, eat ? 1 : 0)) {
    any = true;
    if (!eat) break;
  }
  return any;
}

bool KnownPlatform(const char *name) {
  for (int i = 0; i < MdtPlatformCount(); ++i)
    if (!std::strcmp(MdtPlatformName(i), name)) return true;
  return false;
}

std::string PlatformNames() {
  std::string names;
  for (int i = 0; i < MdtPlatformCount(); ++i) names += std::string(i ? ", " : "") + MdtPlatformName(i);
  return names;
}

/* -platform NAME, never eaten (the program may read it as well); the last
 * one given counts, as for the tutorials' record (tutorial_record.h). */
bool ParsePlatform(MeCommandLineOptions *o, ViewerOptions &out, std::string &error) {
  const char *name = nullptr;
  bool missing = false;
  for (int a = 1; a < o->m_argc; ++a)
    if (!std::strcmp(o->m_argv[a], "-platform")) {
      missing = a + 1 >= o->m_argc;
      name = missing ? nullptr : o->m_argv[a + 1];
    }
  if (missing) {
    error = "-platform needs a value: one of " + PlatformNames();
    return false;
  }
  if (!name) return true;
  if (!KnownPlatform(name)) {
    error = std::string("bad value '") + name + "' for -platform: want one of " + PlatformNames();
    return false;
  }
  out.platform = name;
  return true;
}

/* Reads one options list into `out`; values present override what is there. */
bool ParseOne(MeCommandLineOptions *o, bool eat, ViewerOptions &out, std::string &error) {
  if (!o) return true;
  /* Backend: the last one named wins. */
  for (;;) {
    const int i = MeCommandLineOptionsCheckForList(o, kBackendNames, kBackendCount, eat ? 1 : 0);
    if (i < 0) break;
    out.backend = kBackendKinds[i];
    out.backendGiven = true;
    if (!eat) {
      /* Without eating the same name would be found again; take the last
       * backend option in the list instead. */
      for (int a = o->m_argc - 1; a >= 1; --a)
        for (int k = 0; k < kBackendCount; ++k)
          if (!std::strcmp(o->m_argv[a], kBackendNames[k])) {
            out.backend = kBackendKinds[k];
            a = 0;
            break;
          }
      break;
    }
  }
  if (Flag(o, "-bmp", eat)) out.bmp = true;
  if (Flag(o, "-accuracy", eat)) out.accuracy = true;
  if (Flag(o, "-help", eat) || Flag(o, "--help", eat)) out.help = true;
  if (!ParsePlatform(o, out, error)) return false;

  struct ValueOption {
    const char *name;
    const char *want;
  };
  const ValueOption values[] = {{"-frames", "a whole number of frames, 0 or more"},
                                {"-out", "a directory"},
                                {"-every", "a whole number, 1 or more"},
                                {"-size", "WxH, each 16..8192, e.g. 640x480"},
                                {"-keys", "a key script, e.g. \"10:key Return\""},
                                {"-keyfile", "a key script file"},
                                {"-video", "a video file name (.mp4 or .gif)"},
                                {"-record", "a file for the window's key script"},
                                {"-screenshot", "a PNG file name"}};
  for (const ValueOption &v : values) {
    bool missing = false;
    const char *text = Value(o, v.name, eat, missing);
    if (!text) {
      if (missing) {
        error = std::string(v.name) + " needs a value: " + v.want;
        return false;
      }
      continue;
    }
    bool ok = true;
    long n = 0;
    if (!std::strcmp(v.name, "-frames"))
      ok = ParseLong(text, 0, 2000000000L, n), out.frames = ok ? n : out.frames;
    else if (!std::strcmp(v.name, "-every"))
      ok = ParseLong(text, 1, 2000000000L, n), out.every = ok ? int(n) : out.every;
    else if (!std::strcmp(v.name, "-size"))
      ok = ParseSize(text, out.width, out.height);
    else if (!std::strcmp(v.name, "-keys"))
      out.keys = text;
    else if (!*text)
      ok = false;
    else if (!std::strcmp(v.name, "-keyfile"))
      out.keyFile = text;
    else if (!std::strcmp(v.name, "-video"))
      out.video = text;
    else if (!std::strcmp(v.name, "-record"))
      out.record = text;
    else if (!std::strcmp(v.name, "-screenshot"))
      out.screenshot = text;
    else
      out.outDir = text;
    if (!ok) {
      error = std::string("bad value '") + text + "' for " + v.name + ": want " + v.want;
      return false;
    }
  }
  return true;
}

/* Levenshtein distance, for "did you mean". */
int Distance(const char *a, const char *b) {
  const std::size_t n = std::strlen(a), m = std::strlen(b);
  std::vector<int> row(m + 1);
  for (std::size_t j = 0; j <= m; ++j) row[j] = int(j);
  for (std::size_t i = 1; i <= n; ++i) {
    int diag = row[0];
    row[0] = int(i);
    for (std::size_t j = 1; j <= m; ++j) {
      const int up = row[j];
      row[j] = std::min(std::min(row[j] + 1, row[j - 1] + 1), diag + (a[i - 1] == b[j - 1] ? 0 : 1));
      diag = up;
    }
  }
  return row[m];
}

}  // namespace

const char *HelpText() {
  return "MeViewer options (any program that draws with MeViewer reads these):\n"
         "  -gl            draw with OpenGL, offscreen through OSMesa (the default\n"
         "                 when there is no display or -frames is given)\n"
         "  -window        draw the same frames in a window and take keys and the mouse\n"
         "                 from it (the default when $DISPLAY is set and -frames is not)\n"
         "  -d3d           the same as -gl (kept for the guide's programs)\n"
         "  -null          run the loop without drawing anything\n"
         "  -bench         as -null, and print per-frame timing statistics at exit\n"
         "  -profile       draw, and print a per-phase timing table at exit (and the\n"
         "                 accuracy figures per quarter of the run: the program's\n"
         "                 RRenderSetAccuracySource, else every dynamics world)\n"
         "  -accuracy      draw the accuracy figures beside the performance bar: joint\n"
         "                 error, deepest penetration, energy drift, solver residual\n"
         "  -frames N      stop after N frames, as if Esc had been pressed\n"
         "  -out DIR       write each frame to DIR/frame_00000.png, frame_00001.png, ...\n"
         "                 (DIR is created if needed)\n"
         "  -every K       with -out, write only frames whose number is a multiple of K\n"
         "  -bmp           with -out, write 24-bit BMP files instead of PNG\n"
         "  -size WxH      frame size in pixels (default 640x480)\n"
         "  -keys SCRIPT   press keys and move the mouse at given frames (below)\n"
         "  -keyfile FILE  the same, the script read from FILE (after -keys' events)\n"
         "  -video FILE    after the run, assemble the frames into FILE with ffmpeg\n"
         "                 (.gif: an animated GIF, otherwise H.264 MP4; 30 frames/s)\n"
         "  -record FILE   with a window, write the keys and mouse moves as a key script\n"
         "                 that replays the session (e.g. offscreen with -keyfile FILE)\n"
         "  -screenshot F  with a window, save it as the display shows it at exit (PNG)\n"
         "  -platform NAME the dynamics' platform backend (reference, sse4, avx2,\n"
         "                 avx512) for worlds created from now on; one this CPU\n"
         "                 cannot run gives a warning and the best it can\n"
         "  -help          print this list and exit\n"
         "Textures are found as NAME.bmp in: the working directory, $KARMA_DATA_DIR,\n"
         "the program's directory and its data/ and ../share/karma/ folders, the\n"
         "build tree's share/karma/, then Karma's installed share/karma/ folder.\n";
}

bool DisplayPresent() {
  const char *display = std::getenv("DISPLAY");
  return display && *display;
}

/* Without a backend option, a program with no frame limit opens a window
 * when there is a display to show it on. */
bool ParseViewerOptions(MeCommandLineOptions *options, MeCommandLineOptions *overrides, bool eat, ViewerOptions &out,
                        std::string &error) {
  out = ViewerOptions{};
  if (!ParseOne(options, eat, out, error) || !ParseOne(overrides, eat, out, error)) return false;
  if (!out.backendGiven && out.frames < 0 && DisplayPresent()) out.backend = BackendKind::Window;
  return true;
}

void ApplyPlatformOption(const std::string &name) {
  if (name.empty()) return;
  const char *resolved = MdtPlatformIsSupported(name.c_str()) ? name.c_str() : MdtPlatformGetBestName();
  if (std::strcmp(MdtPlatformGetDefaultName(), resolved) != 0) MdtPlatformSetDefault(name.c_str());
}

void ReportUnknownOptions(const MeCommandLineOptions *options) {
  if (!options) return;
  for (int i = 1; i < options->m_argc; ++i) {
    const char *a = options->m_argv[i];
    if (a[0] != '-' || !a[1] || (a[1] >= '0' && a[1] <= '9') || a[1] == '.') continue;
    bool program = false;
    for (const char *p : kProgramOptions)
      if (!std::strcmp(a, p)) program = true;
    if (program) {
      ++i; /* skip its value */
      continue;
    }
    const char *best = nullptr;
    int bestDistance = 3;
    for (const char *k : kKnownOptions) {
      const int d = Distance(a, k);
      if (d < bestDistance) bestDistance = d, best = k;
    }
    if (best)
      MeWarning(0, "MeViewer: unknown option '%s' (did you mean %s? '-help' lists the viewer's options)", a, best);
    else
      MeInfo(0, "MeViewer: '%s' is not a viewer option; it is left to the program ('-help' lists the viewer's options)",
             a);
  }
}

}  // namespace karma::viewer
