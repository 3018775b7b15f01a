// plot.cpp: the gnuplot script and data of a trade-off plot (plot.h).
#include "plot.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#ifndef KARMA_GNUPLOT
#  define KARMA_GNUPLOT "gnuplot"
#endif

namespace karma::tradeoff {

namespace {

bool Executable(const std::string &path) { return !path.empty() && access(path.c_str(), X_OK) == 0; }

std::string OnPath(const std::string &name) {
  const char *path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && Executable(dir + "/" + name)) return dir + "/" + name;
  return "";
}

std::string ShellQuoted(const std::string &s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// gnuplot's single-quoted strings: '' is a quote.
std::string GnuplotQuoted(const std::string &s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

struct Point {
  double cost, error;
  std::string label;
};

// A named gnuplot data block: "cost error label" lines.
void WriteBlock(std::FILE *f, const char *name, const std::vector<Point> &points) {
  std::fprintf(f, "$%s << EOD\n", name);
  for (const Point &p : points) {
    std::string label;
    for (char c : p.label) label += c == '"' ? '\'' : c;
    std::fprintf(f, "%.9g %.9g \"%s\"\n", p.cost, std::max(p.error, kErrorFloor), label.c_str());
  }
  std::fprintf(f, "EOD\n");
}

}  // namespace

std::string FindGnuplot() {
  if (const char *env = std::getenv("KARMA_GNUPLOT"); env && *env) return Executable(env) ? env : "";
  const std::string configured = KARMA_GNUPLOT;
  if (configured.find('/') != std::string::npos && Executable(configured)) return configured;
  return OnPath("gnuplot");
}

bool Plot(const std::string &gnuplot, const PlotRequest &q, const std::vector<ResultRow> &rows, std::string &error) {
  // Blocks: settings off the front, the front (by cost), failed runs, peers.
  std::vector<Point> blocks[4];
  for (const ResultRow &r : rows) {
    if (r.scene != q.scene) continue;
    const double e = q.sceneError ? r.sceneError : r.drift;
    if (!std::isfinite(e) || !std::isfinite(r.perFrame())) continue;
    if (r.isPeer()) {
      if (q.sceneError) blocks[3].push_back({r.perFrame(), e, r.engine + (r.held ? "" : " (failed)")});
      continue;
    }
    const bool front = q.sceneError ? r.frontScene : r.frontDrift;
    blocks[!r.held ? 2 : front ? 1 : 0].push_back({r.perFrame(), e, r.setting.label()});
  }
  std::sort(blocks[1].begin(), blocks[1].end(), [](const Point &a, const Point &b) { return a.cost < b.cost; });
  const std::string script = q.path + ".gp";
  std::FILE *s = std::fopen(script.c_str(), "w");
  if (!s) {
    error = "cannot write " + script;
    return false;
  }
  const char *names[4] = {"settings", "front", "failed", "peers"};
  for (int i = 0; i < 4; ++i) WriteBlock(s, names[i], blocks[i]);
  std::fprintf(s, "set terminal pngcairo size %d,%d noenhanced font 'DejaVu Sans,9'\n", q.width, q.height);
  std::fprintf(s, "set output %s\n", GnuplotQuoted(q.path).c_str());
  std::fprintf(
      s,
      "set title %s\nset logscale xy\nset format x '%%g'\nset format y '%%.0e'\nset grid xtics ytics mxtics mytics lc rgb '#dddddd'\n",
      GnuplotQuoted(q.title).c_str());
  std::fprintf(
      s, "set xlabel 'µs per 1/60 s simulated (median of the repetitions; µs per step x (1/60) / h)'\nset ylabel %s\n",
      GnuplotQuoted(q.yLabel).c_str());
  std::fprintf(s, "set bmargin 6\nset key at screen 0.5, screen 0.02 center bottom horizontal\n");
  std::fprintf(s, "set offsets graph 0.08, graph 0.35, graph 0.1, graph 0.1\n");
  std::vector<std::string> parts;
  if (!blocks[0].empty())
    parts.push_back("$settings using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'setting'");
  if (!blocks[1].empty()) {
    parts.push_back("$front using 1:2 with linespoints pt 7 ps 1.3 lw 2 lc rgb '#2ca02c' title 'Pareto front'");
    parts.push_back("$front using 1:2:3 with labels left offset 0.7,0.5 font ',7' tc rgb '#1a6e1a' notitle");
  }
  if (!blocks[2].empty()) {
    parts.push_back(
        "$failed using 1:2 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'failed (check or stability)'");
  }
  if (!blocks[3].empty()) {
    parts.push_back("$peers using 1:2 with points pt 5 ps 1.3 lc rgb '#9467bd' title 'peers (h = 1/60)'");
    parts.push_back("$peers using 1:2:3 with labels left offset 0.7,0 font ',8' tc rgb '#6a3d9a' notitle");
  }
  if (parts.empty()) {
    std::fclose(s);
    error = "no finite point to plot for " + q.scene;
    return false;
  }
  std::fprintf(s, "plot ");
  for (size_t i = 0; i < parts.size(); ++i) std::fprintf(s, "%s%s", i ? ", \\\n     " : "", parts[i].c_str());
  std::fprintf(s, "\n");
  std::fclose(s);
  const std::string command = ShellQuoted(gnuplot) + " " + ShellQuoted(script) + " 2>" + ShellQuoted(q.path + ".log");
  if (std::system(command.c_str()) != 0) {
    error = "gnuplot failed on " + script + " (its messages: " + q.path + ".log)";
    return false;
  }
  std::remove((q.path + ".log").c_str());
  return true;
}

}  // namespace karma::tradeoff
