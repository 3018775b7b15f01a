/* accuracy.cpp: the accuracy overlay (-accuracy) and -profile's accuracy
 * table.
 *
 * After every tick RRun reads the program's source (RRenderSetAccuracySource)
 * when -accuracy or -profile asks for it; a program that sets none is read
 * through MeGlobals' diagnostic sources (MeDiagnostics.h: every dynamics
 * world is one), several combined as the largest joint error, penetration
 * and residual and the summed energy drift. The overlay is two lines of text
 * on a dark panel to the right of the performance bar (x from 330 of the
 * 640 2D units, the bar's rows): joint error and deepest penetration in
 * millimetres, energy drift in joules and the solver's residual. Without
 * any source it says so. The -profile table splits the frames read into four
 * quarters (the run's phases) and prints, per figure, the largest
 * magnitude in each quarter and the value at the end. */
#include "viewer_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace karma::viewer {

namespace {

constexpr float kX = 330, kWidth = 300, kTop = R_2D_HEIGHT - 38, kHeight = 30;

/* The figures in the order of the table, with their names and units. */
struct FigureRow {
  const char *name;
  MeReal RAccuracyFigures::*field;
  double scale; /* to the printed unit */
  const char *unit;
};
constexpr FigureRow kRows[] = {{"joint error", &RAccuracyFigures::jointError, 1e3, "mm"},
                               {"penetration", &RAccuracyFigures::penetration, 1e3, "mm"},
                               {"energy drift", &RAccuracyFigures::energyDrift, 1, "J"},
                               {"residual", &RAccuracyFigures::residual, 1, ""}};

/* The registered diagnostic sources combined; false when there are none. */
bool ReadDiagnosticSources(RAccuracyFigures &f) {
  const int n = MeDiagnosticSourceCount();
  for (int i = 0; i < n; ++i) {
    MeDiagnosticFigures d;
    MeDiagnosticSourceRead(i, &d);
    f.jointError = std::max(f.jointError, d.jointError);
    f.penetration = std::max(f.penetration, d.penetration);
    f.energyDrift += d.energyDrift;
    f.residual = std::max(f.residual, d.residual);
  }
  return n > 0;
}

}  // namespace

void SampleAccuracy(RRender *rc) {
  RRenderPrivate *p = rc->m_pPrivate;
  AccuracyState &a = p->accuracy;
  const bool wanted = p->options.accuracy || p->options.backend == BackendKind::Profile;
  if (!wanted) return;
  RAccuracyFigures f{};
  if (a.source)
    a.source(&f, a.data);
  else if (!ReadDiagnosticSources(f))
    return;
  a.last = f;
  a.have = true;
  a.frames.push_back(f);
}

std::vector<RGraphic *> AccuracyOverlay(RRender *rc) {
  std::vector<RGraphic *> out;
  const AccuracyState &a = rc->m_pPrivate->accuracy;
  if (!rc->m_pPrivate->options.accuracy) return out;
  auto detach = [&](RGraphic *g) {
    if (g) RGraphicRemoveFromList(rc, g, 1), out.push_back(g);
  };
  const float panel[4] = {0, 0, 0, 0.6f}, white[4] = {1, 1, 1, 1};
  detach(RGraphic2DRectangleCreate(rc, kX - 4, kTop, kWidth + 8, kHeight, panel));
  char line1[128], line2[128];
  if (a.have) {
    const RAccuracyFigures &f = a.last;
    std::snprintf(line1, sizeof line1, "joint error %.3f mm  penetration %.3f mm", double(f.jointError) * 1e3,
                  double(f.penetration) * 1e3);
    std::snprintf(line2, sizeof line2, "energy drift %+.4g J  residual %.2g", double(f.energyDrift),
                  double(f.residual));
  } else {
    std::snprintf(line1, sizeof line1, "accuracy: no figures from the program");
    std::snprintf(line2, sizeof line2, "(no world, no RRenderSetAccuracySource)");
  }
  detach(RGraphicTextCreate(rc, line1, kX, kTop + 2, white));
  detach(RGraphicTextCreate(rc, line2, kX, kTop + 16, white));
  return out;
}

void PrintAccuracyReport(const AccuracyState &a, std::FILE *f) {
  const size_t n = a.frames.size();
  std::fprintf(f, "MeViewer -profile: accuracy over %zu frames (largest magnitude per quarter of the run)\n", n);
  std::fprintf(f, "  %-17s %12s %12s %12s %12s %12s\n", "figure", "1st quarter", "2nd quarter", "3rd quarter",
               "4th quarter", "at the end");
  for (const FigureRow &row : kRows) {
    std::fprintf(f, "  %-17s", (std::string(row.name) + (*row.unit ? std::string(" (") + row.unit + ")" : "")).c_str());
    for (size_t q = 0; q < 4; ++q) {
      /* Quarter q holds frames [q n / 4, (q + 1) n / 4). */
      const size_t begin = q * n / 4, end = (q + 1) * n / 4;
      double largest = 0;
      for (size_t i = begin; i < end; ++i) {
        const double v = double(a.frames[i].*row.field) * row.scale;
        if (std::fabs(v) > std::fabs(largest)) largest = v;
      }
      if (begin == end)
        std::fprintf(f, " %12s", "-");
      else
        std::fprintf(f, " %12.4g", largest);
    }
    std::fprintf(f, " %12.4g\n", double(a.frames.back().*row.field) * row.scale);
  }
}

}  // namespace karma::viewer

using namespace karma::viewer;

void MEAPI RRenderSetAccuracySource(RRender *rc, RAccuracySource source, void *data) {
  ME_REQUIRE_ARG(rc, "RRenderSetAccuracySource", "rc is NULL");
  rc->m_pPrivate->accuracy.source = source;
  rc->m_pPrivate->accuracy.data = data;
  rc->m_pPrivate->accuracy.have = false;
}

MeBool MEAPI RRenderAccuracyRequested(const RRender *rc) {
  ME_REQUIRE_ARG_RET(rc, 0, "RRenderAccuracyRequested", "rc is NULL");
  return rc->m_pPrivate->options.accuracy ? 1 : 0;
}
