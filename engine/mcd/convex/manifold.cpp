// manifold.cpp: several contacts from one normal.
//
// With n the normal (B towards A), u, v a basis of the plane normal to n
// and O a point, every world point is O + x u + y v + z n. The supporting
// features FA (of A along -n) and FB (of B along n) are projected to
// (x, y); their intersection (polygon clipping, segment overlap, or the
// point of a point feature) gives candidate (x, y). At each candidate the
// height of FA's surface zA (plane through a polygon, interpolation along a
// segment, the point's own z) and of FB's zB give the gap zA - zB along n;
// gaps <= tol become contacts at O + x u + y v + (zA + zB)/2 n. No gap is
// smaller than the shapes' separation sep0 (clamped). At most `max`
// contacts: the deepest, then each farthest from those already chosen.
#include "convex/shape.h"

#include <algorithm>

namespace karma::mcd::convex {

namespace {

struct P2 {
    double x, y;
};
double Cross2(P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

struct Flat {  // a feature projected on the contact plane
    V world[16];
    P2 p[16];
    double z[16];
    int count = 0, dims = 0;
    V planeN;  // polygon normal (Newell), for heights
};

void Project(Flat &f, V o, V u, V v, V n) {
    for (int i = 0; i < f.count; ++i) {
        const V d = f.world[i] - o;
        f.p[i] = {Dot(d, u), Dot(d, v)};
        f.z[i] = Dot(d, n);
    }
    V m;
    for (int i = 0; i < f.count; ++i) {
        const V a = f.world[i], b = f.world[(i + 1) % f.count];
        m = m + V{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    f.planeN = m;
}

// Height along n of the feature's surface above (x, y).
double Height(const Flat &f, P2 q, V o, V u, V v, V n) {
    if (f.count == 1) return f.z[0];
    if (f.count == 2) {
        const double dx = f.p[1].x - f.p[0].x, dy = f.p[1].y - f.p[0].y, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((q.x - f.p[0].x) * dx + (q.y - f.p[0].y) * dy) / l2 : 0;
        t = std::clamp(t, 0.0, 1.0);
        return f.z[0] + t * (f.z[1] - f.z[0]);
    }
    const double nm = Dot(n, f.planeN);
    if (std::fabs(nm) < 1e-6 * Len(f.planeN)) {
        double s = 0;
        for (int i = 0; i < f.count; ++i) s += f.z[i];
        return s / f.count;
    }
    const V q3 = o + q.x * u + q.y * v;
    return Dot(f.world[0] - q3, f.planeN) / nm;
}

// Sutherland-Hodgman: the points of `in` (a polygon, segment or point)
// inside the convex polygon `clip`, using the edges selected by mask.
int Clip(const P2 *in, int count, const Flat &clip, unsigned mask, double eps, P2 *out) {
    double area = 0;
    for (int i = 0; i < clip.count; ++i) area += Cross2({0, 0}, clip.p[i], clip.p[(i + 1) % clip.count]);
    const double sign = area < 0 ? -1 : 1;
    P2 buf[2][40];
    int n = std::min(count, 40);
    std::copy(in, in + n, buf[0]);
    int cur = 0;
    for (int e = 0; e < clip.count && n > 0; ++e) {
        if (!(mask & (1u << e))) continue;
        const P2 a = clip.p[e], b = clip.p[(e + 1) % clip.count];
        const double el = std::hypot(b.x - a.x, b.y - a.y);
        if (!(el > 0)) continue;
        auto side = [&](P2 p) { return sign * Cross2(a, b, p) / el + eps; };
        const P2 *src = buf[cur];
        P2 *dst = buf[1 - cur];
        int m = 0;
        if (n == 1) {
            if (side(src[0]) >= 0) dst[m++] = src[0];
        } else {
            for (int i = 0; i < n && m < 38; ++i) {
                const P2 p = src[i], q = src[(i + 1) % n];
                const double sp = side(p), sq = side(q);
                if (sp >= 0) dst[m++] = p;
                if ((sp >= 0) != (sq >= 0)) {
                    const double t = sp / (sp - sq);
                    dst[m++] = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
                }
                if (n == 2) break;  // a segment has one edge
            }
            if (n == 2 && side(src[1]) >= 0 && m < 38) dst[m++] = src[1];
        }
        n = m;
        cur = 1 - cur;
    }
    std::copy(buf[cur], buf[cur] + n, out);
    return n;
}

// Overlap of two segments (or their crossing point).
int SegmentSegment(const Flat &a, const Flat &b, double eps, P2 *out) {
    const P2 a0 = a.p[0], a1 = a.p[1], b0 = b.p[0], b1 = b.p[1];
    const double dx = a1.x - a0.x, dy = a1.y - a0.y, ex = b1.x - b0.x, ey = b1.y - b0.y;
    const double la = std::hypot(dx, dy), lb = std::hypot(ex, ey);
    if (!(la > eps) || !(lb > eps)) return 0;
    const double den = dx * ey - dy * ex;
    if (std::fabs(den) < 1e-3 * la * lb) {  // parallel: the common interval
        if (std::fabs(Cross2(a0, a1, b0)) / la > eps) return 0;
        double t0 = ((b0.x - a0.x) * dx + (b0.y - a0.y) * dy) / (la * la);
        double t1 = ((b1.x - a0.x) * dx + (b1.y - a0.y) * dy) / (la * la);
        if (t0 > t1) std::swap(t0, t1);
        t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
        if (t0 > t1) return 0;
        out[0] = {a0.x + t0 * dx, a0.y + t0 * dy};
        out[1] = {a0.x + t1 * dx, a0.y + t1 * dy};
        return 2;
    }
    const double t = ((b0.x - a0.x) * ey - (b0.y - a0.y) * ex) / den;
    const double s = ((b0.x - a0.x) * dy - (b0.y - a0.y) * dx) / den;
    const double ta = eps / la, tb = eps / lb;
    if (t < -ta || t > 1 + ta || s < -tb || s > 1 + tb) return 0;
    out[0] = {a0.x + t * dx, a0.y + t * dy};
    return 1;
}

}  // namespace

int Manifold(const Shape &a, const Shape &b, V n, double sep0, double tol, unsigned clipMaskB,
             ManifoldPoint out[], int max) {
    Flat fa, fb;
    fa.count = Feature(a, -n, fa.world, &fa.dims);
    fb.count = Feature(b, n, fb.world, &fb.dims);
    const V u = Unit(std::fabs(n.x) < 0.6 ? Cross(n, V{1, 0, 0}) : Cross(n, V{0, 1, 0}));
    const V v = Cross(n, u);
    const V o = fb.world[0];
    Project(fa, o, u, v, n);
    Project(fb, o, u, v, n);
    const double eps = 1e-7 * std::fmax(a.scale, b.scale) + tol;
    P2 cand[40];
    int nc = 0;
    if (fb.count >= 3) nc = Clip(fa.p, fa.count, fb, clipMaskB, eps, cand);
    else if (fa.count >= 3) nc = Clip(fb.p, fb.count, fa, ~0u, eps, cand);
    else if (fa.count == 2 && fb.count == 2) nc = SegmentSegment(fa, fb, eps, cand);
    else if (fa.count == 1) cand[nc++] = fa.p[0];
    else cand[nc++] = fb.p[0];

    ManifoldPoint all[40];
    int na = 0;
    for (int i = 0; i < nc; ++i) {
        const double za = Height(fa, cand[i], o, u, v, n), zb = Height(fb, cand[i], o, u, v, n);
        const double gap = za - zb;
        if (!(gap <= tol)) continue;
        ManifoldPoint m;
        m.position = o + cand[i].x * u + cand[i].y * v + (0.5 * (za + zb)) * n;
        m.separation = std::max(gap, sep0);
        m.dims1 = fa.dims, m.dims2 = fb.dims;
        bool dup = false;  // clipping repeats corners
        for (int k = 0; k < na && !dup; ++k) dup = Len(all[k].position - m.position) <= eps;
        if (!dup && Finite(m.position)) all[na++] = m;
    }
    if (na == 0) {  // the intersection missed (round-off): one contact between the supports
        const V pa = Support(a, -n), pb = Support(b, n);
        all[0].position = 0.5 * (pa + pb);
        all[0].separation = sep0;
        all[0].dims1 = fa.dims, all[0].dims2 = fb.dims;
        na = 1;
    }
    std::stable_sort(all, all + na, [](const ManifoldPoint &x, const ManifoldPoint &y) {
        return x.separation < y.separation;
    });
    max = std::min(max, 16);
    if (na <= max) {
        std::copy(all, all + na, out);
        return na;
    }
    bool used[40] = {};  // deepest, then farthest from the chosen ones
    out[0] = all[0], used[0] = true;
    for (int k = 1; k < max; ++k) {
        int pick = -1;
        double far = -1;
        for (int i = 0; i < na; ++i) {
            if (used[i]) continue;
            double d = INFINITY;
            for (int j = 0; j < k; ++j) d = std::min(d, Len(all[i].position - out[j].position));
            if (d > far) far = d, pick = i;
        }
        used[pick] = true;
        out[k] = all[pick];
    }
    std::stable_sort(out, out + max, [](const ManifoldPoint &x, const ManifoldPoint &y) {
        return x.separation < y.separation;
    });
    return max;
}

}  // namespace karma::mcd::convex
