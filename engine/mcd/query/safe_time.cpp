// safe_time.cpp: McdSafeTime by sampled conservative advancement.
//
// Each model moves rigidly: position p(t) = p0 + v t, orientation turned by
// the angle |w| t about w (through the model's origin). Any point of model
// k at most R_k from its origin therefore moves at most |v_k| t + |w_k| R_k t,
// so the two models' points approach each other by at most
//   s t,   s = |v1 - v2| + |w1| R1 + |w2| R2.
// Sampling every dt = thickness / (2 s), thickness the smaller model's
// thinnest dimension, cannot step over a model entirely; the first sample
// that touches (McdIntersect's `touch`) is refined by bisection, and the
// last time found clear is the safe time.
#include <algorithm>
#include <cmath>
#include <limits>

#include "MeMessage.h"
#include "McdSafeTime.h"
#include "mcd_internal.h"

namespace {

constexpr int kMaxSamples = 4096;
constexpr int kBisections = 40;

struct Motion {
  McdModel *model;
  MeMatrix4 start;  // the TM at time 0
  MeMatrix4 moved;  // the TM at the sampled time
  MeVector3 v = {0, 0, 0}, w = {0, 0, 0};
  MeReal reach = 0;  // largest distance of a point from the origin
  MeReal thickness = 0;

  void place(MeReal t) {
    const MeReal speed = MeVector3Magnitude(w);
    const MeReal angle = speed * t;
    MeVector3 k = {0, 0, 0};
    if (speed > 0) MeVector3MultiplyScalar(k, w, 1 / speed);
    const MeReal c = std::cos(angle), s = std::sin(angle);
    for (int row = 0; row < 3; ++row) {  // Rodrigues on each axis row
      const MeReal *r = start[row];
      MeVector3 kxr;
      MeVector3Cross(kxr, k, r);
      const MeReal kr = MeVector3Dot(k, r);
      for (int i = 0; i < 3; ++i) moved[row][i] = r[i] * c + kxr[i] * s + k[i] * kr * (1 - c);
      moved[row][3] = 0;
    }
    for (int i = 0; i < 3; ++i) moved[3][i] = start[3][i] + v[i] * t;
    moved[3][3] = 1;
  }
};

// Reach and thickness of the supported shapes; false for the others.
bool Extent(const McdGeometry *g, MeReal &reach, MeReal &thickness) {
  McdGeometry *gg = const_cast<McdGeometry *>(g);
  switch (g->m_type) {
    case kMcdGeometryTypeSphere:
      reach = thickness = McdSphereGetRadius(gg);
      return true;
    case kMcdGeometryTypeBox: {
      MeVector3 h;
      McdBoxGetRadii(gg, h);
      reach = MeVector3Magnitude(h);
      thickness = std::min(h[0], std::min(h[1], h[2]));
      return true;
    }
    case kMcdGeometryTypeCylinder: {
      const MeReal r = McdCylinderGetRadius(gg), hz = McdCylinderGetHeight(gg) / 2;
      reach = std::sqrt(r * r + hz * hz);
      thickness = std::min(r, hz);
      return true;
    }
    case kMcdGeometryTypePlane:  // unbounded: only its translation counts
      reach = 0;
      thickness = std::numeric_limits<MeReal>::infinity();
      return true;
    default:
      return false;
  }
}

bool SupportedPair(int a, int b) {
  auto solid = [](int t) {
    return t == kMcdGeometryTypeSphere || t == kMcdGeometryTypeBox || t == kMcdGeometryTypeCylinder;
  };
  auto planeable = [](int t) { return t == kMcdGeometryTypeSphere || t == kMcdGeometryTypeBox; };
  if (solid(a) && solid(b)) return true;
  return (a == kMcdGeometryTypePlane && planeable(b)) || (b == kMcdGeometryTypePlane && planeable(a));
}

bool Touching(McdModelPair *pair) {
  McdContact contacts[16];
  McdIntersectResult r{};
  r.contacts = contacts;
  r.contactMaxCount = 16;
  karma::mcd::IntersectWithoutReuse(pair, &r);
  return r.touch != 0;
}

}  // namespace

MeBool MEAPI McdSafeTime(McdModelPair *pair, MeReal maxTime, McdSafeTimeResult *result) {
  static const char *fn = "McdSafeTime";
  if (!pair || !result || !pair->model1 || !pair->model2) {
    MeWarning(0, "%s: NULL pair, result or model", fn);
    return 0;
  }
  result->pair = pair;
  result->time = maxTime;
  if (!(maxTime >= 0) || !std::isfinite(maxTime)) {
    MeWarning(0, "%s: maxTime must be finite and >= 0 (got %g)", fn, (double)maxTime);
    result->time = 0;
    return 0;
  }
  if (!pair->m_helloed) {
    MeWarning(0, "%s: call McdHello on the pair first", fn);
    return 0;
  }
  McdModel *models[2] = {pair->model1, pair->model2};
  const McdGeometry *g0 = models[0]->instance.geometry, *g1 = models[1]->instance.geometry;
  if (!g0 || !g1 || !pair->m_interaction ||
      !SupportedPair(g0->m_type, g1->m_type) || !models[0]->instance.tm ||
      !models[1]->instance.tm)
    return 0;

  Motion m[2];
  MeReal spin = 0, thickness = std::numeric_limits<MeReal>::infinity();
  for (int k = 0; k < 2; ++k) {
    m[k].model = models[k];
    MeMatrix4Copy(m[k].start, models[k]->instance.tm);
    if (models[k]->linearVelocity) MeVector3Copy(m[k].v, models[k]->linearVelocity);
    if (models[k]->angularVelocity) MeVector3Copy(m[k].w, models[k]->angularVelocity);
    Extent(models[k]->instance.geometry, m[k].reach, m[k].thickness);
    spin += MeVector3Magnitude(m[k].w) * m[k].reach;
    thickness = std::min(thickness, m[k].thickness);
  }
  MeVector3 dv;
  MeVector3Subtract(dv, m[0].v, m[1].v);
  const MeReal approach = MeVector3Magnitude(dv) + spin;

  // Point both models at their moving TMs for the duration of the search.
  MeMatrix4Ptr saved[2] = {models[0]->instance.tm, models[1]->instance.tm};
  for (int k = 0; k < 2; ++k) models[k]->instance.tm = m[k].moved;
  auto touchingAt = [&](MeReal t) {
    m[0].place(t);
    m[1].place(t);
    return Touching(pair);
  };

  MeReal safe = maxTime;
  if (touchingAt(0)) {
    safe = 0;
  } else if (approach > 0 && maxTime > 0) {
    const MeReal reachable = approach * maxTime;
    int samples = (int)std::min((MeReal)kMaxSamples, std::ceil(2 * reachable / thickness));
    samples = std::max(samples, 1);
    MeReal clear = 0;
    for (int i = 1; i <= samples; ++i) {
      const MeReal t = maxTime * (MeReal)i / (MeReal)samples;
      if (!touchingAt(t)) {
        clear = t;
        continue;
      }
      MeReal lo = clear, hi = t;
      for (int b = 0; b < kBisections && hi - lo > 0; ++b) {
        const MeReal mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi) break;
        (touchingAt(mid) ? hi : lo) = mid;
      }
      safe = lo;
      break;
    }
  }
  for (int k = 0; k < 2; ++k) models[k]->instance.tm = saved[k];
  result->time = safe;
  return 1;
}
