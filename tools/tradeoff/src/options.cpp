// options.cpp: karma-tradeoff's command line (options.h).
#include "options.h"

#include <cstdio>
#include <cstring>
#include <sstream>

#include "MePrecision.h"
#include "settings.h"

namespace karma::tradeoff {

namespace {

std::vector<std::string> List(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

const char *BuildPrecision() { return sizeof(MeReal) == sizeof(double) ? "double" : "single"; }

std::string Usage() {
  return "usage: karma-tradeoff --scene NAME[,NAME...]|LIBRARY.so [--sweep \"KNOB=VALUES ...\"]\n"
         "                      [--precision single,double] [--repeat N] [--out DIR] [--seconds S]\n"
         "                      [--reference-step H] [--peers TABLE.md] [--plot-size WxH] [--no-plots]\n"
         "                      [--other-binary PATH] [--list]\n"
         "  --scene      built-in scenes (--list), 'all', or a shared library exporting\n"
         "               KarmaTradeoffBuildScene (karma/KarmaTradeoffScene.h)\n"
         "  --sweep      e.g. \"solver=exact,exact:8,iterative:10,iterative:50 epsilon=1e-4..1e-1 h=1/60..1/480\"\n"
         "               knobs: solver (exact, exact:N, iterative:N, budget:US), epsilon, gamma, h, tolerance, cap,\n"
         "               projection, warm (1: keep warm starts that meet tolerance/16, 0: always solve),\n"
         "               reuse (contact reuse distance, m; 0: test every pair every step);\n"
         "               values a,b,c or lo..hi (geometric: x10 between powers of ten, else x2) or lo..hi:N\n"
         "  --precision  the precisions to run; the other one runs --other-binary (default: this\n"
         "               build's only; this build is " +
         std::string(BuildPrecision()) +
         ")\n"
         "  --repeat     timed repetitions per setting, interleaved (default 3); µs/step is their median\n"
         "  --out        directory for tradeoff.csv, tradeoff.md and the plots (default tradeoff-out)\n"
         "  --seconds    simulated time per run (default: each scene's own)\n"
         "  --reference-step  the reference run's step (default: min(1/60, smallest h) / 8), exact solver\n"
         "  --peers      peer_bench's Markdown table (scripts/peers.sh): the other engines' points\n"
         "  --plot-size  PNG size in pixels (default 800x600); --no-plots writes no PNG\n";
}

bool ParseOptions(int argc, char **argv, Options &o, std::string &error) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    auto value = [&]() -> std::string { return argv[++i]; };
    double x = 0;
    if (a == "--help" || a == "-h")
      o.help = true;
    else if (a == "--list")
      o.list = true;
    else if (a == "--no-plots")
      o.plots = false;
    else if (a == "--scene" && more)
      o.scenes = List(value());
    else if (a == "--sweep" && more)
      o.sweep = value();
    else if (a == "--precision" && more)
      o.precisions = List(value());
    else if (a == "--out" && more)
      o.out = value();
    else if (a == "--peers" && more)
      o.peers = value();
    else if (a == "--other-binary" && more)
      o.otherBinary = value();
    else if (a == "--repeat" && more) {
      if (!ParseNumber(value(), x) || x < 1 || x > 1000) return error = "--repeat wants a count from 1", false;
      o.repeat = (int)x;
    } else if (a == "--seconds" && more) {
      if (!ParseNumber(value(), x) || x <= 0) return error = "--seconds wants a positive time", false;
      o.seconds = x;
    } else if (a == "--reference-step" && more) {
      if (!ParseNumber(value(), x) || x <= 0) return error = "--reference-step wants a positive step", false;
      o.referenceStep = x;
    } else if (a == "--plot-size" && more) {
      if (std::sscanf(value().c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 100 || o.height < 100 ||
          o.width > 10000 || o.height > 10000)
        return error = "--plot-size wants WxH, 100 to 10000 pixels each", false;
    } else {
      error = "unknown option or missing value: " + a;
      return false;
    }
  }
  for (const std::string &p : o.precisions)
    if (p != "single" && p != "double") return error = "--precision takes single and double", false;
  if (!o.help && !o.list && o.scenes.empty()) return error = "no --scene", false;
  return true;
}

}  // namespace karma::tradeoff
