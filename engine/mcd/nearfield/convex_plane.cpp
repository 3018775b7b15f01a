// convex_plane.cpp: convex mesh (model1) against plane (model2).
//
// Plane normal n = row 2 of its TM, point o = row 3. Each hull vertex
// k = t + v R (world) has height h_k = (k - o) . n; with fatness f the
// surface point below it is at height h_k - f. Every vertex with
// h_k - f <= tolerance is a contact: position k - (h_k + f)/2 n (midway
// between the surface point and the plane), normal +n, separation h_k - f,
// dims vertex/face. The guide's pyramid resting on its base gives its 4
// base corners. Deepest first when the buffer is short.
#include "nearfield.h"
#include "geometry/convex_internal.h"

#include <algorithm>
#include <vector>

using namespace karma::mcd;

namespace {

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
    auto *mesh = reinterpret_cast<const ConvexMesh *>(p->model1->instance.geometry);
    const MeMatrix4Ptr tm = ModelTM(p->model1), plane = ModelTM(p->model2);
    const MeReal *n = plane[2];
    const MeReal tol = ContactTolerance(p->model1->framework), f = mesh->fatness;
    struct Hit {
        MeReal h;
        MeVector3 k;
    };
    std::vector<Hit> hits;
    for (int i = 0; i < mesh->vertexCount; ++i) {
        Hit hit;
        MeMatrix4TMTransform(hit.k, tm, mesh->vertices[i]);
        MeVector3 d;
        MeVector3Subtract(d, hit.k, plane[3]);
        hit.h = MeVector3Dot(d, n) - f;
        if (hit.h <= tol) hits.push_back(hit);
    }
    if (hits.empty()) return 0;
    std::stable_sort(hits.begin(), hits.end(), [](const Hit &a, const Hit &b) { return a.h < b.h; });
    for (const Hit &hit : hits) {
        MeVector3 pos;
        MeVector3Copy(pos, hit.k);
        MeVector3MultiplyAdd(pos, -(hit.h + 2 * f) / 2, n);
        if (!Emit(r, pos, n, hit.h, 0, 2)) break;
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
