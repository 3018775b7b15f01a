// karma-tradeoff: what accuracy costs in time. Runs scenes under a sweep of
// the accuracy knobs, measures µs per step and the errors against a
// reference run, and writes tradeoff.csv, tradeoff.md and one PNG plot per
// scene and error (docs/ACCURACY.md; karma-tradeoff --help).
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "options.h"
#include "peers.h"
#include "plot.h"
#include "report.h"
#include "sweep.h"

namespace {

using namespace karma::tradeoff;

bool MakeDirectory(const std::string &path) {
  std::string partial;
  for (size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || (path[i] == '/' && i > 0)) {
      partial = path.substr(0, i);
      if (mkdir(partial.c_str(), 0777) != 0 && errno != EEXIST) return false;
    }
  }
  return true;
}

std::string ShellQuoted(const std::string &s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string CommandLine(int argc, char **argv) {
  std::string s = "karma-tradeoff";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    s += " " + (a.find_first_of(" \"'*") == std::string::npos ? a : "\"" + a + "\"");
  }
  return s;
}

void ListScenes() {
  std::printf("%-16s %-10s %8s  %s\n", "scene", "kind", "seconds", "what");
  for (const SceneEntry &e : Catalogue())
    std::printf("%-16s %-10s %8.3g  %s\n", e.name.c_str(), e.kind.c_str(), e.seconds, e.about.c_str());
  std::printf("%-16s %-10s %8s  %s\n", "PATH.so", "user", "", "a shared library exporting KarmaTradeoffBuildScene");
}

bool ResolveScenes(const Options &o, std::vector<SceneEntry> &out) {
  for (const std::string &name : o.scenes) {
    if (name == "all") {
      out.insert(out.end(), Catalogue().begin(), Catalogue().end());
      continue;
    }
    SceneEntry e;
    std::string error;
    if (!FindScene(name, e, error)) {
      std::fprintf(stderr, "karma-tradeoff: %s\n", error.c_str());
      return false;
    }
    out.push_back(e);
  }
  return true;
}

// The other precision's sweep: its karma-tradeoff in a subprocess, same
// scenes and sweep, no plots, its CSV read back.
bool RunOtherPrecision(const Options &o, const std::string &precision, std::vector<ResultRow> &rows) {
  if (o.otherBinary.empty()) {
    std::fprintf(stderr,
                 "karma-tradeoff: this build is %s precision; for %s pass --other-binary PATH (the "
                 "karma-tradeoff of a %s build, e.g. build/double/tools/tradeoff/karma-tradeoff)\n",
                 BuildPrecision(), precision.c_str(), precision.c_str());
    return false;
  }
  const std::string dir = o.out + "/" + precision;
  std::string scenes;
  for (const std::string &s : o.scenes) scenes += (scenes.empty() ? "" : ",") + s;
  char numbers[64];
  std::string command = ShellQuoted(o.otherBinary) + " --scene " + ShellQuoted(scenes) + " --sweep " +
                        ShellQuoted(o.sweep) + " --precision " + precision + " --no-plots --out " + ShellQuoted(dir) +
                        " --repeat " + std::to_string(o.repeat);
  if (o.seconds > 0) {
    std::snprintf(numbers, sizeof numbers, " --seconds %.17g", o.seconds);
    command += numbers;
  }
  if (o.referenceStep > 0) {
    std::snprintf(numbers, sizeof numbers, " --reference-step %.17g", o.referenceStep);
    command += numbers;
  }
  std::fprintf(stderr, "karma-tradeoff: the %s sweep: %s\n", precision.c_str(), command.c_str());
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "karma-tradeoff: the %s build's sweep failed\n", precision.c_str());
    return false;
  }
  std::string error;
  std::vector<ResultRow> other;
  if (!ReadCsv(dir + "/tradeoff.csv", other, error)) {
    std::fprintf(stderr, "karma-tradeoff: %s\n", error.c_str());
    return false;
  }
  for (ResultRow &r : other) r.setting.precision = precision;
  rows.insert(rows.end(), other.begin(), other.end());
  return true;
}

// The sweep in this build's precision, then the other precision's through
// its binary; settings carry their precision only when both ran.
bool RunAllPrecisions(const Options &o, SweepPlan &plan, std::vector<ResultRow> &rows) {
  const std::string own = BuildPrecision();
  const bool both = o.precisions.size() > 1;
  const bool runOwn =
      o.precisions.empty() || std::find(o.precisions.begin(), o.precisions.end(), own) != o.precisions.end();
  plan.precision = own;
  if (both)
    for (Setting &s : plan.settings) s.precision = own;
  if (runOwn) rows = RunSweep(plan);
  for (const std::string &p : o.precisions)
    if (p != own && !RunOtherPrecision(o, p, rows)) return false;
  if (!both)
    for (ResultRow &r : rows) r.setting.precision.clear();
  return true;
}

// The peers' points of the swept scenes (not peer_bench's own Karma rows:
// this sweep measured Karma).
bool AddPeers(const std::string &table, const SweepPlan &plan, std::vector<ResultRow> &rows) {
  std::vector<ResultRow> peers;
  std::string error;
  if (!ReadPeerTable(table, peers, error)) {
    std::fprintf(stderr, "karma-tradeoff: %s\n", error.c_str());
    return false;
  }
  for (ResultRow &p : peers) {
    const bool swept =
        std::any_of(plan.scenes.begin(), plan.scenes.end(), [&](const SceneEntry &e) { return e.name == p.scene; });
    if (swept && p.engine != "karma") rows.push_back(p);
  }
  return true;
}

// A scene's two plots (drift; scene error when it has one); their file
// names go into the note.
void PlotScene(const Options &o, const std::string &gnuplot, const SceneEntry &e, const std::vector<ResultRow> &rows,
               SceneNote &n) {
  std::string error;
  PlotRequest q;
  q.scene = e.name;
  q.width = o.width;
  q.height = o.height;
  q.title = e.name + ": drift from the reference run against the cost of 1/60 s simulated";
  q.yLabel = "drift from the reference (m, largest RMS over the bodies)";
  q.path = o.out + "/" + e.name + "-drift.png";
  if (Plot(gnuplot, q, rows, error))
    n.driftPlot = e.name + "-drift.png";
  else
    std::fprintf(stderr, "karma-tradeoff: %s\n", error.c_str());
  const bool hasSceneError = std::any_of(
      rows.begin(), rows.end(), [&](const ResultRow &r) { return r.scene == e.name && std::isfinite(r.sceneError); });
  if (!hasSceneError) return;
  q.sceneError = true;
  q.title = e.name + ": the scene's own error against the cost of 1/60 s simulated";
  q.yLabel = "scene error (m; see ACCURACY.md)";
  q.path = o.out + "/" + e.name + "-scene.png";
  if (Plot(gnuplot, q, rows, error))
    n.scenePlot = e.name + "-scene.png";
  else
    std::fprintf(stderr, "karma-tradeoff: %s\n", error.c_str());
}

bool WriteReports(const Options &o, const std::vector<ResultRow> &rows, const std::vector<SceneNote> &notes,
                  const std::string &command) {
  const std::string csv = o.out + "/tradeoff.csv", md = o.out + "/tradeoff.md";
  std::FILE *f = std::fopen(csv.c_str(), "w");
  std::FILE *g = std::fopen(md.c_str(), "w");
  if (f) WriteCsv(f, rows), std::fclose(f);
  if (g) WriteMarkdown(g, rows, notes, command), std::fclose(g);
  if (!f || !g) {
    std::fprintf(stderr, "karma-tradeoff: cannot write %s or %s\n", csv.c_str(), md.c_str());
    return false;
  }
  std::fprintf(stderr, "karma-tradeoff: wrote %s, %s and the plots\n", csv.c_str(), md.c_str());
  return true;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  std::string error;
  if (!ParseOptions(argc, argv, o, error)) {
    std::fprintf(stderr, "karma-tradeoff: %s\n%s", error.c_str(), Usage().c_str());
    return 2;
  }
  if (o.help) return std::printf("%s", Usage().c_str()), 0;
  if (o.list) return ListScenes(), 0;
  SweepPlan plan;
  if (!ParseSweep(o.sweep, plan.settings, error)) {
    std::fprintf(stderr, "karma-tradeoff: --sweep: %s\n", error.c_str());
    return 2;
  }
  if (!ResolveScenes(o, plan.scenes)) return 2;
  std::string gnuplot;
  if (o.plots && (gnuplot = FindGnuplot()).empty()) {
    std::fprintf(stderr,
                 "karma-tradeoff: gnuplot not found: install the Debian package gnuplot-nox "
                 "(scripts/install-deps.sh does), set KARMA_GNUPLOT to its path, or pass --no-plots\n");
    return 3;
  }
  if (!MakeDirectory(o.out)) {
    std::fprintf(stderr, "karma-tradeoff: cannot make %s: %s\n", o.out.c_str(), std::strerror(errno));
    return 2;
  }
  plan.repeat = o.repeat;
  plan.seconds = o.seconds;
  plan.referenceStep = o.referenceStep;
  std::vector<ResultRow> rows;
  if (!RunAllPrecisions(o, plan, rows)) return 1;
  if (!o.peers.empty() && !AddPeers(o.peers, plan, rows)) return 2;
  std::vector<SceneNote> notes;
  for (const SceneEntry &e : plan.scenes) {
    MarkFronts(rows, e.name);
    SceneNote n{e.name, e.about, o.seconds > 0 ? o.seconds : e.seconds, ReferenceSetting(plan).label(), "", ""};
    if (o.plots) PlotScene(o, gnuplot, e, rows, n);
    notes.push_back(n);
  }
  return WriteReports(o, rows, notes, CommandLine(argc, argv)) ? 0 : 2;
}
