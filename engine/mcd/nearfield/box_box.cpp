// box_box.cpp: box (model1) against box (model2).
//
// Separating axes (Gottschalk's OBB test): with centres c1, c2, unit axes
// A_i, B_j, half extents a_i, b_j and T = c1 - c2, a unit axis L gives the
// separation  s_L = |T.L| - sum_i a_i |A_i.L| - sum_j b_j |B_j.L|.
// The 15 axes are the 3 + 3 face normals and the 9 edge directions A_i x B_j
// (skipped when nearly parallel). Any s_L > tolerance: no contact.
//
// Choosing the axis. The best (largest s) of each class is found: s1 over
// box 1's faces, s2 over box 2's, se over the edge axes. "x is clearly
// better than y" means  s_x > s_y + 0.05 |s_y| + 0.01 h  (h = the smallest
// half extent of the two boxes): x must be shallower (in overlap) or
// farther apart (for a speculative contact) by 5% of y's separation plus
// 1% of the box size.
//   reference face  box 2's if s2 is clearly better than s1, box 1's if s1
//                   is clearly better than s2; otherwise the larger of the
//                   two faces (box 1's on equal areas)
//   edge-edge       if se is clearly better than the chosen face's s
// ODE's and Bullet's box-box use the same 5% for edges; Box2D flips its
// reference face by a relative plus an absolute margin. Two stacked boxes
// with a small relative yaw or tilt have edge axes A_x x B_y nearly along
// the common face normal whose s differ from the face's by round-off and
// tilt terms; without the margins the choice flips between face and edge
// from step to step and the single edge contact jumps from corner to
// corner. Between the two faces, s1 - s2 ~ tilt x (width of the wider box),
// so a small box on a wide one would flip between its own face and the
// wide one's as it rocks; taking the larger face when neither is clearly
// better keeps the wide box's face, which wins anyway once the tilt grows.
// A real edge-edge touch (crossed edges) is shallower along its edge axis
// by a fraction of the size, and wins.
//  - Face axis: its box is the reference; the incident face is the other
//    box's face most opposed to the reference normal m (outward). The
//    incident quad is clipped (Sutherland-Hodgman) by the 4 side planes of
//    the reference face; every clipped point p at depth d = (p - f).m <=
//    tolerance below the reference face (centre f) is a candidate at
//    p - d/2 m with separation d. Up to 8 candidates; at most four are kept
//    by ReduceToFour (contact_reduce.h) in the reference face's axes, and
//    when the buffer is shorter still, the deepest first, then repeatedly
//    the point farthest from those kept.
//  - Edge axis A_i x B_j: the edge of box 1 along A_i furthest towards -n,
//    the edge of box 2 along B_j furthest towards +n; one contact midway
//    between their closest points.
// The normal n = +-L points from box 2 towards box 1; separation = s_L.
// Feature ids (feature_id.h): a face contact names the reference face, the
// incident face and the clipped vertex by the two lines meeting there
// (incident edges 0-3, reference side planes 4-7); an edge contact names
// the two edges.
#include "contact_reduce.h"
#include "prim_math.h"

using namespace karma::mcd;
using namespace karma::mcd::prim;

namespace {

// "Clearly better" (see the top of the file): s_x > s_y + 0.05 |s_y| + 0.01 h.
constexpr MeReal kRelative = (MeReal)0.95, kAbsolute = (MeReal)0.01;

struct Box {
  Frame f;
  MeVector3 h;
  explicit Box(const McdModel *m) : f(m) { McdBoxGetRadii(m->instance.geometry, h); }
  MeReal FaceArea(int k) const { return h[(k + 1) % 3] * h[(k + 2) % 3]; }  // a quarter of it
  // The half extent along a unit axis L, from absDot[k] = |axis_k . L|.
  MeReal Radius(const MeReal absDot[3]) const { return h[0] * absDot[0] + h[1] * absDot[1] + h[2] * absDot[2]; }
  MeReal Radius(V3 L) const {
    const MeReal absDot[3] = {std::fabs(Dot(f.axis[0], L)), std::fabs(Dot(f.axis[1], L)), std::fabs(Dot(f.axis[2], L))};
    return Radius(absDot);
  }
};

// A vertex of the polygon being clipped; `out` is the line the edge from it
// to the next vertex lies on (0-3 incident edges, 4-7 reference side planes).
struct Vert {
  V3 p;
  int out;
};

// A candidate contact: position, separation, incident dims, vertex key.
struct Pt {
  V3 p;
  MeReal depth;
  int dims;  // the incident feature: 0 a corner, 1 a point of an edge, 2 inside the face
  int key;   // in-line * 8 + out-line
};

// The polygons being clipped have at most this many vertices (4 at the
// start, at most one more per clipping plane).
constexpr int kMaxClipVerts = 16;

// Keeps the part of the polygon (n vertices) with p.axis <= lim; the new
// edge along the plane gets line id `line`. Returns the count.
int ClipPlane(const Vert *in, int n, V3 axis, MeReal lim, int line, Vert *out) {
  MeReal dist[kMaxClipVerts];  // dist[i] = in[i].p . axis - lim
  for (int i = 0; i < n; ++i) dist[i] = Dot(in[i].p, axis) - lim;
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const int next = i + 1 < n ? i + 1 : 0;
    const Vert &a = in[i], &b = in[next];
    const MeReal da = dist[i], db = dist[next];
    if (da <= 0) out[m++] = a;
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const MeReal t = da / (da - db);
      out[m++] = {a.p + t * (b.p - a.p), da < 0 ? line : a.out};
    }
  }
  return m;
}

// The face index 2k + (outward normal along -axis k) of the face of box b
// along axis k whose outward normal is m.
int FaceIndex(const Box &b, int k, V3 m) { return 2 * k + (Dot(b.f.axis[k], m) < 0 ? 1 : 0); }

// Face contact: reference box `ref` face along axis index k with outward
// normal m; the incident box `inc`. Writes the candidates to out (at most
// 8) and the incident face index; returns the count.
int FaceContacts(const Box &ref, int k, V3 m, const Box &inc, MeReal tol, Pt *out, int *incFace) {
  int ii = 0;
  MeReal best = -1, facing[3];  // facing[i] = inc axis i . m
  for (int i = 0; i < 3; ++i) {
    facing[i] = Dot(inc.f.axis[i], m);
    const MeReal d = std::fabs(facing[i]);
    if (d > best) {
      best = d;
      ii = i;
    }
  }
  const int i1 = (ii + 1) % 3, i2 = (ii + 2) % 3;
  const MeReal sign = facing[ii] > 0 ? -1 : 1;
  *incFace = 2 * ii + (sign < 0 ? 1 : 0);
  const V3 fc = inc.f.o + sign * inc.h[ii] * inc.f.axis[ii] - ref.f.o;
  const V3 e1 = inc.h[i1] * inc.f.axis[i1], e2 = inc.h[i2] * inc.f.axis[i2];
  Vert a[kMaxClipVerts], b[kMaxClipVerts];
  a[0] = {fc + e1 + e2, 0};
  a[1] = {fc - e1 + e2, 1};
  a[2] = {fc - e1 - e2, 2};
  a[3] = {fc + e1 - e2, 3};
  // Side planes of the reference face, relative to the reference centre.
  const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  int n = ClipPlane(a, 4, ref.f.axis[k1], ref.h[k1], 4, b);
  n = ClipPlane(b, n, -ref.f.axis[k1], ref.h[k1], 5, a);
  n = ClipPlane(a, n, ref.f.axis[k2], ref.h[k2], 6, b);
  n = ClipPlane(b, n, -ref.f.axis[k2], ref.h[k2], 7, a);
  int count = 0;
  for (int i = 0; i < n && count < 8; ++i) {
    const MeReal d = Dot(a[i].p, m) - ref.h[k];
    if (d > tol) continue;
    const int in = a[i > 0 ? i - 1 : n - 1].out;
    const int dims = (in >= 4) + (a[i].out >= 4);  // corner, edge point, reference corner
    out[count++] = {ref.f.o + a[i].p - (MeReal)0.5 * d * m, d, dims, in * 8 + a[i].out};
  }
  return count;
}

// Keeps at most four candidates spread over the face (contact_reduce.h),
// in the reference face's axes k1, k2; returns the new count.
int SpreadFour(Pt *pts, int n, const Box &ref, int k, MeReal slack) {
  if (n <= 4) return n;
  const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  ReducePoint rp[8];
  for (int i = 0; i < n; ++i) {
    const V3 d = pts[i].p - ref.f.o;
    rp[i] = {Dot(d, ref.f.axis[k1]), Dot(d, ref.f.axis[k2]), -(double)pts[i].depth};
  }
  int keep[4];
  const int m = ReduceToFour(rp, n, slack, keep);
  for (int i = 0; i < m; ++i) pts[i] = pts[keep[i]];
  return m;
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
        for (int q = 1; q < j; ++q) score = std::fmin(score, Dot(pts[i].p - pts[q].p, pts[i].p - pts[q].p));
      }
      if (j == 0 ? (i == j || score > best) : score > best) {
        best = score;
        pick = i;
      }
    }
    std::swap(pts[j], pts[pick]);
  }
}

// The edge-edge contact on axis A_i x B_j (unit n from box 2 to box 1).
void EdgeContact(const Box &b1, const Box &b2, int i, int j, V3 n, MeReal s, McdIntersectResult *r) {
  V3 c1 = b1.f.o, c2 = b2.f.o;
  MeU32 bits = 0;
  for (int q = 1; q < 3; ++q) {
    const int k1 = (i + q) % 3, k2 = (j + q) % 3;
    const bool up1 = Dot(b1.f.axis[k1], n) > 0, up2 = Dot(b2.f.axis[k2], n) > 0;
    c1 = c1 - (up1 ? 1 : -1) * b1.h[k1] * b1.f.axis[k1];
    c2 = c2 + (up2 ? 1 : -1) * b2.h[k2] * b2.f.axis[k2];
    bits |= (up1 ? 1u : 0u) << (q - 1) | (up2 ? 1u : 0u) << (q + 1);
  }
  const V3 d1 = b1.h[i] * b1.f.axis[i], d2 = b2.h[j] * b2.f.axis[j];
  MeReal u, v;
  ClosestSegmentSegment(c1 - d1, c1 + d1, c2 - d2, c2 + d2, u, v);
  const V3 P = c1 - d1 + (2 * u) * d1, Q = c2 - d2 + (2 * v) * d2;
  EmitV(r, (MeReal)0.5 * (P + Q), n, s, 1, 1, feature::Pack(feature::kBoxEdge, (MeU32)(3 * i + j), bits));
}

int Test(const McdModel *m1, const McdModel *m2, McdIntersectResult *r) {
  const Box b1(m1), b2(m2);
  const MeReal tol = ContactTolerance(m1->framework);
  const V3 T = b1.f.o - b2.f.o;
  MeReal best[3] = {-MEINFINITY, -MEINFINITY, -MEINFINITY};  // box 1 faces, box 2 faces, edges
  int axis[3] = {0, 0, -1};
  V3 bestL[3];
  // Records separation s along axis L; false when it separates the boxes.
  auto record = [&](MeReal s, V3 L, int id, int cls) {
    if (s > best[cls]) best[cls] = s, axis[cls] = id, bestL[cls] = L;
    return s <= tol;
  };
  // The face axes need the nine |A_i . B_j| in both boxes' radii (B_j . A_i
  // is A_i . B_j bit for bit: the products commute and the sum keeps its
  // order); row i is computed with axis A_i.
  MeReal absDot[3][3];
  for (int i = 0; i < 3; ++i) {
    const V3 L = b1.f.axis[i];
    for (int j = 0; j < 3; ++j) absDot[i][j] = std::fabs(Dot(L, b2.f.axis[j]));
    if (!record(std::fabs(Dot(T, L)) - b1.Radius(L) - b2.Radius(absDot[i]), L, i, 0)) return 0;
  }
  for (int j = 0; j < 3; ++j) {
    const V3 L = b2.f.axis[j];
    const MeReal column[3] = {absDot[0][j], absDot[1][j], absDot[2][j]};
    if (!record(std::fabs(Dot(T, L)) - b1.Radius(column) - b2.Radius(L), L, j, 1)) return 0;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const V3 C = Cross(b1.f.axis[i], b2.f.axis[j]);
      const MeReal len = Norm(C);
      if (len < (MeReal)1e-4) continue;
      const V3 L = (1 / len) * C;
      if (!record(std::fabs(Dot(T, L)) - b1.Radius(L) - b2.Radius(L), L, 3 * i + j, 2)) return 0;
    }
  const MeReal hmin =
      std::fmin(std::fmin(std::fmin(b1.h[0], b1.h[1]), b1.h[2]), std::fmin(std::fmin(b2.h[0], b2.h[1]), b2.h[2]));
  auto clearlyBetter = [&](MeReal x, MeReal y) { return x > y + (1 - kRelative) * std::fabs(y) + kAbsolute * hmin; };
  int face = b2.FaceArea(axis[1]) > b1.FaceArea(axis[0]) ? 1 : 0;
  if (clearlyBetter(best[1], best[0]))
    face = 1;
  else if (clearlyBetter(best[0], best[1]))
    face = 0;
  const bool edge = axis[2] >= 0 && clearlyBetter(best[2], best[face]);
  const int cls = edge ? 2 : face;
  V3 n = bestL[cls];
  if (Dot(n, T) < 0) n = -n;
  if (edge) {
    EdgeContact(b1, b2, axis[2] / 3, axis[2] % 3, n, best[2], r);
    return Finish(r, n);
  }
  Pt pts[8];
  const Box &ref = face == 0 ? b1 : b2, &inc = face == 0 ? b2 : b1;
  const int k = axis[face];
  const V3 m = face == 0 ? -n : n;
  int incFace = 0;
  int count = FaceContacts(ref, k, m, inc, tol, pts, &incFace);
  count = SpreadFour(pts, count, ref, k, std::fmax(tol, (MeReal)1e-3 * hmin));
  const int keep = count < r->contactMaxCount ? count : r->contactMaxCount;
  if (keep < count) Reduce(pts, count, keep);
  const MeU32 kind = face == 0 ? feature::kBoxFace1 : feature::kBoxFace2;
  const MeU32 refFace = (MeU32)FaceIndex(ref, k, m);
  for (int i = 0; i < keep; ++i) {
    const int incDims = pts[i].dims;
    EmitV(r, pts[i].p, n, pts[i].depth, face == 0 ? 2 : incDims, face == 0 ? incDims : 2,
          feature::Pack(kind, refFace, (MeU32)incFace, (MeU32)pts[i].key));
  }
  if (r->contactCount == 0) {
    // Clipping lost every point (the deepest corner lies outside the
    // reference face): one contact on the line through box 2's centre
    // along n, midway between the two boxes' support planes.
    EmitV(r, b2.f.o + (b2.Radius(n) + (MeReal)0.5 * best[face]) * n, n, best[face], 2, 2,
          feature::Pack(feature::kSingle, feature::kBoxBoxFallback));
  }
  return Finish(r, n);
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) { return OrderedSameType(p, r, Test); }

}  // namespace

extern "C" void MEAPI McdBoxBoxRegisterInteraction(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, kMcdGeometryTypeBox, kMcdGeometryTypeBox, fns);
}
