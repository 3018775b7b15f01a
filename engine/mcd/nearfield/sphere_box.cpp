// sphere_box.cpp: sphere (model1) against box (model2).
//
// In the box frame (axes a_i = rows of its TM, half extents h_i) the sphere
// centre is q. Outside the box: the closest box point is k_i = clamp(q_i,
// -h_i, h_i); d = |q - k|, normal n = (q - k)/d, separation s = d - r. The
// box feature is a face, an edge or a vertex as 1, 2 or 3 coordinates were
// clamped. Centre inside (q == k): the nearest face i minimises h_i - |q_i|;
// n = sign(q_i) a_i (+ for q_i = 0), s = -(h_i - |q_i|) - r, and the box
// point is q moved onto that face. One contact midway between the sphere's
// deepest point c - r n and the box point.
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const MeReal radius = McdSphereGetRadius(p->model1->instance.geometry);
  MeVector3 half;
  McdBoxGetRadii(p->model2->instance.geometry, half);
  const Frame box(p->model2);
  const V3 c(ModelTM(p->model1)[3]);
  const V3 q = box.ToLocal(c);
  V3 k;
  int clamped = 0;
  for (int i = 0; i < 3; ++i) {
    k[i] = Clamp(q[i], -half[i], half[i]);
    if (k[i] != q[i]) ++clamped;
  }
  V3 n, onBox;
  MeReal s;
  int boxDims = 2;
  if (clamped > 0) {
    const V3 d = q - k;
    const MeReal dist = Norm(d);
    s = dist - radius;
    if (s > ContactTolerance(p->model1->framework)) return 0;
    n = box.Dir((1 / dist) * d);
    onBox = box.ToWorld(k);
    boxDims = 3 - clamped;  // 1 clamped: face (2), 2: edge (1), 3: vertex (0)
  } else {
    int face = 0;
    MeReal best = half[0] - std::fabs(q[0]);
    for (int i = 1; i < 3; ++i) {
      const MeReal gap = half[i] - std::fabs(q[i]);
      if (gap < best) {
        best = gap;
        face = i;
      }
    }
    const MeReal sign = q[face] < 0 ? -1 : 1;
    n = sign * box.axis[face];
    k[face] = sign * half[face];
    onBox = box.ToWorld(k);
    s = -best - radius;
  }
  EmitV(r, (MeReal)0.5 * ((c - radius * n) + onBox), n, s, 2, boxDims,
        feature::Pack(feature::kSingle, feature::kSphereBox));
  return Finish(r, n);
}

}  // namespace

extern "C" void MEAPI McdSphereBoxRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox, fns);
}
