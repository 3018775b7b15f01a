// box_plane.cpp: box (model1) against plane (model2).
//
// Each of the 8 corners k = c + sum_i sigma_i h_i a_i (a_i = box axes, rows
// of its TM; sigma_i = +-1) has height h_k = (k - o) . n over the plane
// (normal n = row 2 of the plane TM, point o = row 3). Every corner with
// h_k <= tolerance is a contact: position k - h_k/2 n (midway between the
// corner and the plane), normal +n, separation h_k, dims vertex(0)/face(2).
// A box resting flat gives its 4 lower corners; an edge 2; a corner 1. A box
// thinner than the tolerance can touch with more: 4 are kept, spread over
// the plane (ReduceToFour, contact_reduce.h, in the plane's axes). When more corners touch
// than the buffer holds, the deepest are kept. Feature id: the corner k
// (bit i set: +h_i along axis i).
#include "contact_reduce.h"
#include "feature_id.h"
#include "nearfield.h"
#include "stable_order.h"

#include <cmath>

using namespace karma::mcd;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  MeVector3 half;
  McdBoxGetRadii(p->model1->instance.geometry, half);
  const MeMatrix4Ptr box = ModelTM(p->model1), plane = ModelTM(p->model2);
  const MeReal *n = plane[2];
  const MeReal tol = ContactTolerance(p->model1->framework);
  MeVector3 corner[8];
  MeReal height[8];
  int touching[8], count = 0;
  for (int k = 0; k < 8; ++k) {
    MeVector3Copy(corner[k], box[3]);
    for (int i = 0; i < 3; ++i) MeVector3MultiplyAdd(corner[k], ((k >> i) & 1) ? half[i] : -half[i], box[i]);
    MeVector3 d;
    MeVector3Subtract(d, corner[k], plane[3]);
    height[k] = MeVector3Dot(d, n);
    if (height[k] <= tol) touching[count++] = k;
  }
  if (count == 0) return 0;
  // A thin box can touch with more than 4 corners: keep 4 spread over the
  // plane (contact_reduce.h, in the plane's axes).
  if (count > 4) {
    ReducePoint rp[8];
    for (int j = 0; j < count; ++j) {
      const int k = touching[j];
      rp[j] = {(double)MeVector3Dot(corner[k], plane[0]), (double)MeVector3Dot(corner[k], plane[1]),
               -(double)height[k]};
    }
    int keep[4];
    const MeReal thin = std::fmin(std::fmin(half[0], half[1]), half[2]);
    const MeReal slack = std::fmax(tol, (MeReal)1e-3 * thin);
    count = ReduceToFour(rp, count, slack, keep);
    for (int j = 0; j < count; ++j) touching[j] = touching[keep[j]];
  }
  // Deepest first; ties keep corner order, so the result is deterministic.
  StableOrderByKey(touching, count, height);
  for (int j = 0; j < count; ++j) {
    const int k = touching[j];
    MeVector3 pos;
    MeVector3Copy(pos, corner[k]);
    MeVector3MultiplyAdd(pos, -height[k] / 2, n);
    if (!Emit(r, pos, n, height[k], 0, 2, feature::Pack(feature::kBoxPlane, (MeU32)k))) break;
  }
  MeVector3Copy(r->normal, n);
  r->touch = 1;
  return 1;
}

}  // namespace

extern "C" void MEAPI McdBoxPlaneRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeBox, kMcdGeometryTypePlane, fns);
}
