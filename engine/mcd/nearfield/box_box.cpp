// box_box.cpp: box (model1) against box (model2).
//
// Separating axes (Gottschalk's OBB test): with centres c1, c2, unit axes
// A_i, B_j, half extents a_i, b_j and T = c1 - c2, a unit axis L gives the
// separation  s_L = |T.L| - sum_i a_i |A_i.L| - sum_j b_j |B_j.L|.
// The 15 axes are the 3 + 3 face normals and the 9 edge directions A_i x B_j
// (skipped when nearly parallel). Any s_L > tolerance: no contact. Else the
// axis with the largest s_L is the minimum-translation direction (faces are
// preferred unless an edge axis is better by a small margin), n = +-L
// pointing from box 2 towards box 1, and the separation is s_L.
//  - Face axis: its box is the reference; the incident face is the other
//    box's face most opposed to the reference normal. The incident quad is
//    clipped (Sutherland-Hodgman) by the 4 side planes of the reference
//    face; every clipped point p at depth d = (p - f).m <= tolerance below
//    the reference face (centre f, outward normal m) is a contact at
//    p - d/2 m. Up to 8 points; when the buffer is shorter the deepest is
//    kept first, then repeatedly the point farthest from those kept.
//  - Edge axis A_i x B_j: the edge of box 1 along A_i furthest towards -n,
//    the edge of box 2 along B_j furthest towards +n; one contact midway
//    between their closest points.
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

struct Box {
    Frame f;
    MeVector3 h;
    explicit Box(const McdModel *m) : f(m) { McdBoxGetRadii(m->instance.geometry, h); }
    MeReal Radius(V3 L) const {
        return h[0] * std::fabs(Dot(f.axis[0], L)) + h[1] * std::fabs(Dot(f.axis[1], L)) +
               h[2] * std::fabs(Dot(f.axis[2], L));
    }
};

struct Pt {
    V3 p;
    MeReal depth;
    int dims;  // the incident feature: 0 an original corner, 1 a clipped edge point
};

// Keeps the points of poly (n of them) with plane.x <= lim; returns the count.
int ClipPlane(const Pt *in, int n, V3 axis, MeReal lim, Pt *out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const Pt &a = in[i], &b = in[(i + 1) % n];
        const MeReal da = Dot(a.p, axis) - lim, db = Dot(b.p, axis) - lim;
        if (da <= 0) out[m++] = a;
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            const MeReal t = da / (da - db);
            out[m++] = {a.p + t * (b.p - a.p), 0, 1};
        }
    }
    return m;
}

// Face contact: reference box `ref` face along axis index k with outward
// normal m; the incident box `inc`. Returns the number of points in out.
int FaceContacts(const Box &ref, int k, V3 m, const Box &inc, MeReal tol, Pt *out) {
    int ii = 0;
    MeReal best = -1;
    for (int i = 0; i < 3; ++i) {
        const MeReal d = std::fabs(Dot(inc.f.axis[i], m));
        if (d > best) { best = d; ii = i; }
    }
    const int i1 = (ii + 1) % 3, i2 = (ii + 2) % 3;
    const MeReal sign = Dot(inc.f.axis[ii], m) > 0 ? -1 : 1;
    const V3 fc = inc.f.o + sign * inc.h[ii] * inc.f.axis[ii];
    const V3 e1 = inc.h[i1] * inc.f.axis[i1], e2 = inc.h[i2] * inc.f.axis[i2];
    Pt a[16], b[16];
    a[0] = {fc + e1 + e2, 0, 0};
    a[1] = {fc - e1 + e2, 0, 0};
    a[2] = {fc - e1 - e2, 0, 0};
    a[3] = {fc + e1 - e2, 0, 0};
    int n = 4;
    // Side planes of the reference face, relative to the reference centre.
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    for (int i = 0; i < n; ++i) a[i].p = a[i].p - ref.f.o;
    n = ClipPlane(a, n, ref.f.axis[k1], ref.h[k1], b);
    n = ClipPlane(b, n, -ref.f.axis[k1], ref.h[k1], a);
    n = ClipPlane(a, n, ref.f.axis[k2], ref.h[k2], b);
    n = ClipPlane(b, n, -ref.f.axis[k2], ref.h[k2], a);
    int count = 0;
    for (int i = 0; i < n && count < 8; ++i) {
        const MeReal d = Dot(a[i].p, m) - ref.h[k];
        if (d > tol) continue;
        out[count++] = {ref.f.o + a[i].p - (MeReal)0.5 * d * m, d, a[i].dims};
    }
    return count;
}

// Moves the chosen `keep` points to the front: the deepest, then each time
// the one farthest from all already kept.
void Reduce(Pt *pts, int n, int keep) {
    for (int j = 0; j < keep && j < n; ++j) {
        int pick = j;
        MeReal best = -1;
        for (int i = j; i < n; ++i) {
            MeReal score = -pts[i].depth;
            if (j > 0) {
                score = Dot(pts[i].p - pts[0].p, pts[i].p - pts[0].p);
                for (int q = 1; q < j; ++q)
                    score = std::fmin(score, Dot(pts[i].p - pts[q].p, pts[i].p - pts[q].p));
            }
            if (j == 0 ? (i == j || score > best) : score > best) { best = score; pick = i; }
        }
        std::swap(pts[j], pts[pick]);
    }
}

int Test(const McdModel *m1, const McdModel *m2, McdIntersectResult *r) {
    const Box b1(m1), b2(m2);
    const MeReal tol = ContactTolerance(m1->framework);
    const V3 T = b1.f.o - b2.f.o;
    MeReal bestFace = -MEINFINITY, bestEdge = -MEINFINITY;
    int faceAxis = 0, edgeAxis = -1;
    V3 faceL, edgeL;
    auto test = [&](V3 L, int id, bool edge) {
        const MeReal s = std::fabs(Dot(T, L)) - b1.Radius(L) - b2.Radius(L);
        MeReal &best = edge ? bestEdge : bestFace;
        if (s > best) {
            best = s;
            (edge ? edgeAxis : faceAxis) = id;
            (edge ? edgeL : faceL) = L;
        }
        return s <= tol;
    };
    for (int i = 0; i < 3; ++i)
        if (!test(b1.f.axis[i], i, false)) return 0;
    for (int j = 0; j < 3; ++j)
        if (!test(b2.f.axis[j], 3 + j, false)) return 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const V3 L = Cross(b1.f.axis[i], b2.f.axis[j]);
            const MeReal len = Norm(L);
            if (len < (MeReal)1e-4) continue;
            if (!test((1 / len) * L, 3 * i + j, true)) return 0;
        }
    const MeReal hmin = std::fmin(std::fmin(std::fmin(b1.h[0], b1.h[1]), b1.h[2]),
                                  std::fmin(std::fmin(b2.h[0], b2.h[1]), b2.h[2]));
    const bool edge = edgeAxis >= 0 && bestEdge > bestFace + (MeReal)1e-3 * hmin;
    V3 n = edge ? edgeL : faceL;
    if (Dot(n, T) < 0) n = -n;
    if (edge) {
        const int i = edgeAxis / 3, j = edgeAxis % 3;
        V3 c1 = b1.f.o, c2 = b2.f.o;
        for (int k = 0; k < 3; ++k) {
            if (k != i) c1 = c1 - (Dot(b1.f.axis[k], n) > 0 ? 1 : -1) * b1.h[k] * b1.f.axis[k];
            if (k != j) c2 = c2 + (Dot(b2.f.axis[k], n) > 0 ? 1 : -1) * b2.h[k] * b2.f.axis[k];
        }
        const V3 d1 = b1.h[i] * b1.f.axis[i], d2 = b2.h[j] * b2.f.axis[j];
        MeReal u, v;
        ClosestSegmentSegment(c1 - d1, c1 + d1, c2 - d2, c2 + d2, u, v);
        const V3 P = c1 - d1 + (2 * u) * d1, Q = c2 - d2 + (2 * v) * d2;
        EmitV(r, (MeReal)0.5 * (P + Q), n, bestEdge, 1, 1);
        return Finish(r, n);
    }
    Pt pts[8];
    const bool refIs1 = faceAxis < 3;
    const int count = refIs1 ? FaceContacts(b1, faceAxis, -n, b2, tol, pts)
                             : FaceContacts(b2, faceAxis - 3, n, b1, tol, pts);
    const int keep = count < r->contactMaxCount ? count : r->contactMaxCount;
    if (keep < count) Reduce(pts, count, keep);
    for (int i = 0; i < keep; ++i)
        EmitV(r, pts[i].p, n, pts[i].depth, refIs1 ? 2 : pts[i].dims, refIs1 ? pts[i].dims : 2);
    if (r->contactCount == 0) {
        // Clipping lost every point (the deepest corner lies outside the
        // reference face): one contact on the line through box 2's centre
        // along n, midway between the two boxes' support planes.
        EmitV(r, b2.f.o + (b2.Radius(n) + (MeReal)0.5 * bestFace) * n, n, bestFace, 2, 2);
    }
    return Finish(r, n);
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
    return OrderedSameType(p, r, Test);
}

}  // namespace

extern "C" void MEAPI McdBoxBoxRegisterInteraction(McdFrameworkID fw) {
    McdInteractions fns{};
    fns.intersectFn = Intersect;
    RegisterInteractionQuietly(fw, kMcdGeometryTypeBox, kMcdGeometryTypeBox, fns);
}
