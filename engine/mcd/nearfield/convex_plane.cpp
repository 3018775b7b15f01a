// convex_plane.cpp: convex mesh (model1) against plane (model2).
//
// Plane normal n = row 2 of its TM, point o = row 3. Each hull vertex
// k = t + v R (world) has height h_k = (k - o) . n; with fatness f the
// surface point below it is at height h_k - f. Every vertex with
// h_k - f <= tolerance is a contact: position k - (h_k + f)/2 n (midway
// between the surface point and the plane), normal +n, separation h_k - f,
// dims vertex/face. The guide's pyramid resting on its base gives its 4
// base corners; a face with more vertices on the plane keeps 4 spread over
// it (ReduceToFour, contact_reduce.h, in the plane's axes). Deepest first
// when the buffer is short. Feature id: the hull vertex index.
#include "contact_reduce.h"
#include "feature_id.h"
#include "nearfield.h"
#include "geometry/convex_internal.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace karma::mcd;

namespace {

// 1e-3 of the hull's extent: depth differences below it do not change
// which points are kept (contact_reduce.h).
MeReal Slack(const ConvexMesh *mesh) {
  MeReal far = 0;
  for (int i = 0; i < mesh->vertexCount; ++i)
    far = std::fmax(far, MeSqrt(MeVector3Dot(mesh->vertices[i], mesh->vertices[i])));
  return (MeReal)1e-3 * far;
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  auto *mesh = reinterpret_cast<const ConvexMesh *>(p->model1->instance.geometry);
  const MeMatrix4Ptr tm = ModelTM(p->model1), plane = ModelTM(p->model2);
  const MeReal *n = plane[2];
  const MeReal tol = ContactTolerance(p->model1->framework), f = mesh->fatness;
  struct Hit {
    MeReal h;
    MeVector3 k;
    int vertex;
  };
  std::vector<Hit> hits;
  for (int i = 0; i < mesh->vertexCount; ++i) {
    Hit hit;
    MeMatrix4TMTransform(hit.k, tm, mesh->vertices[i]);
    MeVector3 d;
    MeVector3Subtract(d, hit.k, plane[3]);
    hit.h = MeVector3Dot(d, n) - f;
    hit.vertex = i;
    if (hit.h <= tol) hits.push_back(hit);
  }
  if (hits.empty()) return 0;
  if (hits.size() > 4) {  // a face on the plane: 4 spread over it
    std::vector<ReducePoint> rp;
    for (const Hit &hit : hits)
      rp.push_back({(double)MeVector3Dot(hit.k, plane[0]), (double)MeVector3Dot(hit.k, plane[1]), -(double)hit.h});
    int keep[4];
    const int kept = ReduceToFour(rp.data(), (int)rp.size(), std::fmax(tol, Slack(mesh)), keep);
    for (int j = 0; j < kept; ++j) hits[j] = hits[keep[j]];
    hits.resize(kept);
  }
  std::stable_sort(hits.begin(), hits.end(), [](const Hit &a, const Hit &b) { return a.h < b.h; });
  for (const Hit &hit : hits) {
    MeVector3 pos;
    MeVector3Copy(pos, hit.k);
    MeVector3MultiplyAdd(pos, -(hit.h + 2 * f) / 2, n);
    const MeU32 id = feature::Pack24(feature::kConvexPlane, (MeU32)hit.vertex);
    if (!Emit(r, pos, n, hit.h, 0, 2, id)) break;
  }
  MeVector3Copy(r->normal, n);
  r->touch = 1;
  return 1;
}

}  // namespace

extern "C" void MEAPI McdConvexMeshPlaneRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeConvexMesh, kMcdGeometryTypePlane, fns);
}
