/* stats.cpp: the timing reports printed at exit by -bench and -profile.
 *
 * -bench: per-frame wall time (the whole loop body) as count, mean, median,
 * minimum, maximum and standard deviation, and the tick's mean.
 * -profile: one row per loop phase (input, tick, render, output) with mean
 * and maximum milliseconds and the phase's share of the total; then any
 * MeProfile sections the program timed itself (collision, dynamics, ...);
 * and the platform backend the dynamics ran on. */
#include "viewer_internal.h"

#include "MdtPlatform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace karma::viewer {
namespace {

struct Summary {
  double mean = 0, median = 0, min = 0, max = 0, stddev = 0, sum = 0;
};

Summary Summarise(std::vector<double> v) {
  Summary s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  for (double x : v) s.sum += x;
  const double n = double(v.size());
  s.mean = s.sum / n;
  s.min = v.front();
  s.max = v.back();
  s.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  double sq = 0;
  for (double x : v) sq += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(sq / n);
  return s;
}

}  // namespace

std::string PlatformReport() {
  std::vector<std::string> seen;
  for (int i = 0; i < MeDiagnosticSourceCount(); ++i) {
    MeDiagnosticFigures d;
    if (MeDiagnosticSourceRead(i, &d) && d.platform &&
        std::find(seen.begin(), seen.end(), std::string(d.platform)) == seen.end())
      seen.emplace_back(d.platform);
  }
  if (seen.empty())
    return std::string(MdtPlatformGetDefaultName()) + " (the process default: no dynamics world to ask)";
  std::string text;
  for (std::size_t i = 0; i < seen.size(); ++i) text += (i ? (i + 1 == seen.size() ? " and " : ", ") : "") + seen[i];
  return text;
}

void PrintBenchReport(const FrameTimes &t, std::FILE *f) {
  const Summary total = Summarise(t.total), tick = Summarise(t.tick);
  std::fprintf(f, "MeViewer -bench: %zu frames\n", t.total.size());
  if (t.total.empty()) return;
  std::fprintf(f, "  frame time (ms): mean %.4f  median %.4f  min %.4f  max %.4f  stddev %.4f\n", total.mean,
               total.median, total.min, total.max, total.stddev);
  std::fprintf(f, "  tick time  (ms): mean %.4f  (%.1f%% of the frame)\n", tick.mean,
               total.sum > 0 ? 100.0 * tick.sum / total.sum : 0.0);
  std::fprintf(f, "  frames per second: %.1f\n", total.mean > 0 ? 1000.0 / total.mean : 0.0);
}

void PrintProfileReport(const FrameTimes &t, std::FILE *f) {
  std::fprintf(f, "MeViewer -profile: %zu frames\n", t.total.size());
  std::fprintf(f, "  platform backend: %s\n", PlatformReport().c_str());
  if (t.total.empty()) return;
  const Summary total = Summarise(t.total);
  std::fprintf(f, "  %-10s %12s %12s %8s\n", "phase", "mean ms", "max ms", "share");
  const struct {
    const char *name;
    const std::vector<double> *v;
  } rows[] = {{"input", &t.input}, {"tick", &t.tick}, {"render", &t.render}, {"output", &t.output}};
  for (const auto &r : rows) {
    const Summary s = Summarise(*r.v);
    std::fprintf(f, "  %-10s %12.4f %12.4f %7.1f%%\n", r.name, s.mean, s.max,
                 total.sum > 0 ? 100.0 * s.sum / total.sum : 0.0);
  }
  std::fprintf(f, "  %-10s %12.4f %12.4f %7.1f%%\n", "frame", total.mean, total.max, 100.0);
  if (MeProfileGetFrameCount() > 0) {
    std::fprintf(f, "  MeProfile sections timed by the program (mean ms per frame):\n");
    for (int i = 0; i < MeProfileGetSectionCount(); ++i) {
      const char *name = MeProfileGetSectionName(i);
      std::fprintf(f, "    %-16s %10.4f\n", name, double(MeProfileGetSectionAverage(name)));
    }
  }
}

}  // namespace karma::viewer
