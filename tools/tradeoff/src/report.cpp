// report.cpp: CSV and Markdown of a sweep (report.h).
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace karma::tradeoff {

namespace {

std::string Cell(double v, const char *format = "%.6g") {
  if (std::isnan(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string Quoted(const std::string &s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// Markdown: a value with 3 significant digits, "–" when not measured.
std::string Short(double v) {
  if (std::isnan(v)) return "–";
  return Cell(v, "%.3g");
}

// Microseconds: 3 significant digits below 1000, else whole.
std::string Micros(double us) {
  if (std::isnan(us)) return "–";
  return Cell(us, us < 1000 ? "%.3g" : "%.0f");
}

}  // namespace

const std::vector<std::string> &CsvColumns() {
  static const std::vector<std::string> columns = {"scene",
                                                   "precision",
                                                   "engine",
                                                   "setting",
                                                   "solver",
                                                   "epsilon",
                                                   "gamma",
                                                   "h",
                                                   "tolerance",
                                                   "cap",
                                                   "projection",
                                                   "warm",
                                                   "reuse",
                                                   "repeats",
                                                   "us_per_step",
                                                   "us_min",
                                                   "us_max",
                                                   "us_per_frame",
                                                   "steps",
                                                   "drift_m",
                                                   "joint_error_m",
                                                   "penetration_m",
                                                   "energy_error_J",
                                                   "momentum_error_Ns",
                                                   "residual",
                                                   "unsolved_steps",
                                                   "max_speed_mps",
                                                   "scene_error",
                                                   "held",
                                                   "front_drift",
                                                   "front_scene",
                                                   "detail"};
  return columns;
}

size_t CsvColumn(const char *name) {
  const std::vector<std::string> &columns = CsvColumns();
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) {
    std::fprintf(stderr, "karma-tradeoff: internal error: no CSV column named \"%s\"\n", name);
    std::abort();
  }
  return (size_t)(it - columns.begin());
}

void WriteCsv(std::FILE *f, const std::vector<ResultRow> &rows) {
  const auto &columns = CsvColumns();
  for (size_t i = 0; i < columns.size(); ++i) std::fprintf(f, "%s%s", i ? "," : "", columns[i].c_str());
  std::fprintf(f, "\n");
  for (const ResultRow &r : rows) {
    const Setting &s = r.setting;
    const bool peer = r.isPeer();
    const std::vector<std::string> cells = {r.scene,
                                            r.precision,
                                            r.engine,
                                            Quoted(peer ? r.engine : s.label()),
                                            peer ? "" : s.solver(),
                                            peer ? "" : Cell(s.epsilon),
                                            peer ? "" : Cell(s.gamma),
                                            Cell(s.h),
                                            peer ? "" : Cell(s.tolerance),
                                            peer || s.cap < 0 ? "" : std::to_string(s.cap),
                                            peer || s.projection < 0 ? "" : std::to_string(s.projection),
                                            peer || s.warm < 0 ? "" : std::to_string(s.warm),
                                            peer ? "" : Cell(s.reuse),
                                            std::to_string(r.micros.size()),
                                            Cell(r.median()),
                                            Cell(r.low()),
                                            Cell(r.high()),
                                            Cell(r.perFrame()),
                                            std::to_string(r.steps),
                                            Cell(r.drift),
                                            Cell(r.jointError),
                                            Cell(r.penetration),
                                            Cell(r.energyError),
                                            Cell(r.momentumError),
                                            Cell(r.residual),
                                            std::to_string(r.unsolvedSteps),
                                            Cell(r.maxSpeed),
                                            Cell(r.sceneError),
                                            r.held ? "1" : "0",
                                            r.frontDrift ? "1" : "0",
                                            r.frontScene ? "1" : "0",
                                            Quoted(r.detail)};
    for (size_t i = 0; i < cells.size(); ++i) std::fprintf(f, "%s%s", i ? "," : "", cells[i].c_str());
    std::fprintf(f, "\n");
  }
}

void WriteMarkdown(std::FILE *f, const std::vector<ResultRow> &rows, const std::vector<SceneNote> &scenes,
                   const std::string &command) {
  std::fprintf(f, "<!-- written by: %s -->\n\n", command.c_str());
  for (const SceneNote &n : scenes) {
    std::fprintf(f, "### %s\n\n%s; %.3g s simulated; errors against the reference run (%s).\n\n", n.name.c_str(),
                 n.about.c_str(), n.seconds, n.reference.c_str());
    if (!n.scenePlot.empty())
      std::fprintf(f, "![%s: scene error against µs per 1/60 s](%s)\n", n.name.c_str(), n.scenePlot.c_str());
    if (!n.driftPlot.empty())
      std::fprintf(f, "![%s: drift against µs per 1/60 s](%s)\n", n.name.c_str(), n.driftPlot.c_str());
    std::fprintf(f, "\nDrift front: %s\n\n", FrontSummary(rows, n.name, false).c_str());
    bool hasSceneError = false;
    for (const ResultRow &r : rows) hasSceneError |= r.scene == n.name && !std::isnan(r.sceneError);
    if (hasSceneError) std::fprintf(f, "Scene-error front: %s\n\n", FrontSummary(rows, n.name, true).c_str());
    std::fprintf(
        f,
        "| setting | µs per 1/60 s | µs/step median [range] | drift (m) | joint error (m) | penetration (m) | energy error (J) "
        "| momentum error (N s) | residual | scene error | held | front |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const ResultRow &r : rows) {
      if (r.scene != n.name) continue;
      std::string name = r.isPeer() ? "**" : "`";  // appended piecewise: GCC 12's -Wrestrict misfires on a + chain
      name += r.isPeer() ? r.engine : r.setting.label();
      name += r.isPeer() ? "** (peer, h=1/60)" : "`";
      std::string front = r.frontDrift ? "drift" : "";
      if (r.frontScene) front += front.empty() ? "scene" : ", scene";
      std::fprintf(f, "| %s | %s | %s [%s–%s] | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", name.c_str(),
                   Micros(r.perFrame()).c_str(), Micros(r.median()).c_str(), Micros(r.low()).c_str(),
                   Micros(r.high()).c_str(), Short(r.drift).c_str(), Short(r.jointError).c_str(),
                   Short(r.penetration).c_str(), Short(r.energyError).c_str(), Short(r.momentumError).c_str(),
                   Short(r.residual).c_str(), Short(r.sceneError).c_str(),
                   r.held ? "yes" : (std::string("**no**: ") + r.detail).c_str(), front.c_str());
    }
    std::fprintf(f, "\n");
  }
}

}  // namespace karma::tradeoff

#include <fstream>

namespace karma::tradeoff {

std::vector<std::string> SplitCsvLine(const std::string &line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      cells.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

namespace {

double Real(const std::string &cell) { return cell.empty() ? std::nan("") : std::atof(cell.c_str()); }

}  // namespace

bool ReadCsv(const std::string &path, std::vector<ResultRow> &out, std::string &error) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return error = "cannot read " + path, false;
  const std::vector<std::string> &columns = CsvColumns();
  if (SplitCsvLine(line) != columns) return error = path + " has other columns than this tool writes", false;
  const auto at = CsvColumn;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = SplitCsvLine(line);
    if (c.size() != columns.size()) continue;
    ResultRow r;
    r.scene = c[at("scene")];
    r.precision = c[at("precision")];
    r.engine = c[at("engine")];
    if (!r.isPeer()) {
      std::vector<Setting> parsed;
      std::string label = c[at("setting")], ignored;
      for (const char *p : {" single", " double"})
        if (label.size() > 7 && label.compare(label.size() - 7, 7, p) == 0) label.resize(label.size() - 7);
      if (!ParseSweep("solver=" + label, parsed, ignored) || parsed.size() != 1) continue;
      r.setting = parsed[0];
    }
    const double median = Real(c[at("us_per_step")]), low = Real(c[at("us_min")]), high = Real(c[at("us_max")]);
    r.micros = {low, median, high};  // the median and range survive
    r.steps = std::atoi(c[at("steps")].c_str());
    r.drift = Real(c[at("drift_m")]);
    r.jointError = Real(c[at("joint_error_m")]);
    r.penetration = Real(c[at("penetration_m")]);
    r.energyError = Real(c[at("energy_error_J")]);
    r.momentumError = Real(c[at("momentum_error_Ns")]);
    r.residual = Real(c[at("residual")]);
    r.unsolvedSteps = std::atoi(c[at("unsolved_steps")].c_str());
    r.maxSpeed = Real(c[at("max_speed_mps")]);
    r.sceneError = Real(c[at("scene_error")]);
    r.held = c[at("held")] == "1";
    r.detail = c[at("detail")];
    out.push_back(r);
  }
  return true;
}

}  // namespace karma::tradeoff
