/* perfbar.cpp: the performance bar.
 *
 * The bar is R_BAR_WIDTH 2D units for one frame budget of 1/60 s (16.7 ms),
 * or for the frame's total when that is longer. Its segments, left to
 * right: collision (red), dynamics (green), rendering (blue), then idle
 * (grey) = budget - (collision + dynamics + rendering), never negative.
 * Times are MeProfile's for the last completed frame; a legend under the
 * bar prints them in milliseconds. */
#include "viewer_internal.h"

#include <algorithm>
#include <cstdio>

struct RPerformanceBar {
  RRender *rc = nullptr;
};

namespace karma::viewer {

std::vector<RGraphic *> PerformanceBarOverlay(RRender *rc) {
  std::vector<RGraphic *> out;
  if (!rc->m_pPrivate->bar) return out;
  constexpr float kBudget = 1000.0f / 60.0f, kWidth = 300, kHeight = 10, x0 = 10, y0 = R_2D_HEIGHT - 36;
  const float t[4] = {float(MeProfileGetSectionTime("collision")), float(MeProfileGetSectionTime("dynamics")),
                      float(MeProfileGetSectionTime("render")), 0};
  const float busy = t[0] + t[1] + t[2];
  const float times[4] = {t[0], t[1], t[2], std::max(0.0f, kBudget - busy)};
  const float scale = kWidth / std::max(kBudget, busy);
  const float colours[4][4] = {
      {0.9f, 0.25f, 0.2f, 1}, {0.3f, 0.85f, 0.3f, 1}, {0.3f, 0.5f, 1, 1}, {0.5f, 0.5f, 0.5f, 0.8f}};
  auto detach = [&](RGraphic *g) {
    if (g) RGraphicRemoveFromList(rc, g, 1), out.push_back(g);
  };
  const float frame[4] = {0, 0, 0, 0.6f};
  detach(RGraphic2DRectangleCreate(rc, x0 - 2, y0 - 2, kWidth + 4, kHeight + 4, frame));
  float x = x0;
  for (int i = 0; i < 4; ++i) {
    const float w = times[i] * scale;
    if (w > 0) detach(RGraphic2DRectangleCreate(rc, x, y0, w, kHeight, colours[i]));
    x += w;
  }
  char legend[160];
  std::snprintf(legend, sizeof legend, "collision %.2f  dynamics %.2f  render %.2f  idle %.2f ms", double(times[0]),
                double(times[1]), double(times[2]), double(times[3]));
  const float white[4] = {1, 1, 1, 1};
  detach(RGraphicTextCreate(rc, legend, x0, y0 + kHeight + 4, white));
  return out;
}

}  // namespace karma::viewer

RPerformanceBar *MEAPI RPerformanceBarCreate(RRender *rc) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RPerformanceBarCreate", "rc is NULL");
  RRenderPrivate *p = rc->m_pPrivate;
  if (!p->bar) {
    p->bar = new RPerformanceBar;
    p->bar->rc = rc;
  }
  return p->bar;
}

namespace karma::viewer {
void DestroyPerformanceBar(RRender *rc) {
  delete rc->m_pPrivate->bar;
  rc->m_pPrivate->bar = nullptr;
}
}  // namespace karma::viewer
