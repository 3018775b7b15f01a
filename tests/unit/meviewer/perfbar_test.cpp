// perfbar_test.cpp: the performance bar: one per context, its segments
// from MeProfile's last frame under a hand-driven clock.
#include "viewer_internal.h"
#include "viewer_test_support.h"

using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

double gNow = 0;
double MEAPI Clock(void *) { return gNow; }

TEST(PerformanceBar, OnePerContextAndSegmentsFromTheLastFrame) {
  RRender *rc = MakeContext("prog -null");
  EXPECT_TRUE(karma::viewer::PerformanceBarOverlay(rc).empty());
  RPerformanceBar *bar = RPerformanceBarCreate(rc);
  ASSERT_NE(bar, nullptr);
  EXPECT_EQ(RPerformanceBarCreate(rc), bar);

  MeProfileReset();
  MeProfileSetClock(Clock, nullptr);
  gNow = 0;
  MeProfileStartFrame();
  MeProfileStartSection("collision"), gNow += 3, MeProfileEndSection("collision");
  MeProfileStartSection("dynamics"), gNow += 5, MeProfileEndSection("dynamics");
  MeProfileStartSection("render"), gNow += 1, MeProfileEndSection("render");
  MeProfileEndFrame();
  std::vector<RGraphic *> g = karma::viewer::PerformanceBarOverlay(rc);
  // frame, collision, dynamics, render, idle, legend
  ASSERT_EQ(g.size(), 6u);
  auto width = [](const RGraphic *r) {
    float lo = 1e9f, hi = -1e9f;
    for (int i = 0; i < r->m_pObject->m_nNumVertices; ++i)
      lo = std::min(lo, r->m_pVertices[i].m_X), hi = std::max(hi, r->m_pVertices[i].m_X);
    return hi - lo;
  };
  const float perMs = 300.0f / (1000.0f / 60.0f);  // the bar is 300 units for 1/60 s
  EXPECT_NEAR(width(g[1]), 3 * perMs, 1e-3);
  EXPECT_NEAR(width(g[2]), 5 * perMs, 1e-3);
  EXPECT_NEAR(width(g[3]), 1 * perMs, 1e-3);
  EXPECT_NEAR(width(g[1]) + width(g[2]) + width(g[3]) + width(g[4]), 300, 1e-3);
  for (RGraphic *x : g) RGraphicDestroy(x);
  EXPECT_EQ(rc->m_pRG_First2D, nullptr);
  MeProfileSetClock(nullptr, nullptr);
  MeProfileReset();
  RRenderContextDestroy(rc);
}

TEST(PerformanceBar, NullContextWarns) {
  Messages m;
  EXPECT_EQ(RPerformanceBarCreate(nullptr), nullptr);
  EXPECT_TRUE(Messages::Warned("RPerformanceBarCreate"));
}

}  // namespace
