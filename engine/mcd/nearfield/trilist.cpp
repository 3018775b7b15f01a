// trilist.cpp: sphere, box, cylinder, sphyl and convex mesh (model1)
// against a triangle list (model2). Aggregates reach it child by child.
//
// The triangles come from McdTriangleListGetTriangles with the sphere
// enclosing model1's AABB (grown by the tolerance), in the list's frame;
// corners and normals go to world as p R + t. Each triangle T (corners
// v0 v1 v2, face normal f, edge i from v_i to v_i+1) is tested alone:
//  - sphere, centre c, radius r: q = the point of T closest to c. When q is
//    on an edge or corner (c's projection outside T) whose edge(s) are not
//    flagged UseEdge, T makes no contact (a smooth neighbour does); else
//    n = (c - q)/|c - q| with UseSmallestPenetration, f otherwise (signed
//    to c's side when TwoSided); s = (c - q) . n - r.
//  - others: libccd gives the least-penetration normal n0 (convex/). An
//    edge or corner normal of an unflagged edge becomes the face normal, as
//    does any normal without UseSmallestPenetration.
//  - one-sided (TwoSided clear): a normal with n . f < 0 is reversed, and
//    the separation recomputed along it.
// Contacts (normal from T towards model1) come from the manifold builder,
// T's polygon clipping only along flagged edges, so a box on a smooth
// floor keeps its 4 corners across the triangles. Contacts of different
// triangles within 1e-3 of model1's size with normals within ~2.5 degrees
// are one (the first triangle's, with the deeper separation). When more
// than four remain and all their normals agree within ~2.5 degrees (a face
// resting on the list), four are kept, spread over the contact area
// (ReduceToFour, contact_reduce.h, in model1's axes). element2.ptr = the
// McdUserTriangle.
// Feature id (feature_id.h): Mix(triangle key, id against the triangle),
// the key a hash of the triangle's three corners in the list's frame (so it
// does not depend on the order the callback returns triangles in), the id
// Manifold's, or a constant for a sphere.
#include "contact_reduce.h"
#include "convex_common.h"
#include "feature_id.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace karma::mcd;
using namespace karma::mcd::convex;

namespace {

struct Tri {
  V v[3], f;
  int flags;
  bool EdgeSharp(int i) const { return (flags & (kMcdTriangleUseEdge0 << i)) != 0; }
};

// Closest point of the triangle to p; *edge = -1 inside, else the sharpness
// of the edge or corner it lies on is reported through *sharp.
V Closest(const Tri &t, V p, bool *inside, bool *sharp) {
  *sharp = false;
  const V ab = t.v[1] - t.v[0], ac = t.v[2] - t.v[0];
  const V n = Cross(ab, ac);
  const double nn = Dot(n, n);
  const V w = p - t.v[0];
  const double b1 = Dot(Cross(w, ac), n) / nn, b2 = Dot(Cross(ab, w), n) / nn, b0 = 1 - b1 - b2;
  const double eps = 1e-9;
  if (b0 >= -eps && b1 >= -eps && b2 >= -eps) {
    *inside = true, *sharp = true;
    return p - (Dot(w, n) / nn) * n;
  }
  *inside = false;
  double best = INFINITY;
  V q;
  for (int i = 0; i < 3; ++i) {
    const V a = t.v[i], b = t.v[(i + 1) % 3], e = b - a;
    double s = Dot(p - a, e) / Dot(e, e);
    s = std::clamp(s, 0.0, 1.0);
    const V c = a + s * e;
    const double d = Len(p - c);
    if (d < best) {
      best = d, q = c;
      if (s <= 0)
        *sharp = t.EdgeSharp(i) || t.EdgeSharp((i + 2) % 3);
      else if (s >= 1)
        *sharp = t.EdgeSharp(i) || t.EdgeSharp((i + 1) % 3);
      else
        *sharp = t.EdgeSharp(i);
    }
  }
  return q;
}

// Which feature of T supports along n: face (true), else sharpness of the
// edge or corner.
bool SharpAlong(const Tri &t, V n, double scale) {
  double top = -INFINITY;
  for (const V &v : t.v) top = std::max(top, Dot(v, n));
  int on[3], k = 0;
  for (int i = 0; i < 3; ++i)
    if (Dot(t.v[i], n) >= top - 1e-6 * scale) on[k++] = i;
  if (k == 3) return true;
  if (k == 2) {
    const int i = (on[1] == on[0] + 1) ? on[0] : on[1];  // edge on[0]-on[1]
    return t.EdgeSharp(i);
  }
  return t.EdgeSharp(on[0]) || t.EdgeSharp((on[0] + 2) % 3);
}

// A hash of the triangle's corners (their bits, in the list's frame).
MeU32 TriangleKey(const McdUserTriangle &ut) {
  MeU32 h = 0x2545F491u;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const MeReal x = (*ut.vertices[k])[i];
      unsigned char bytes[sizeof(MeReal)];
      std::memcpy(bytes, &x, sizeof x);
      MeU32 w = 0;
      for (std::size_t b = 0; b < sizeof x; ++b) w = w * 131u + bytes[b];
      h = feature::Mix(h, w);
    }
  return h;
}

// Keeps four of a face-face touch's contacts (see the top of the file).
void SpreadFour(std::vector<McdContact> &out, const Shape &obj, double tol) {
  if (out.size() <= 4) return;
  const V n = FromMe(out[0].normal);
  for (const McdContact &c : out)
    if (Dot(FromMe(c.normal), n) <= 0.999) return;
  V u = obj.axis[0] - Dot(obj.axis[0], n) * n;
  if (Len(u) < 0.5) u = obj.axis[1] - Dot(obj.axis[1], n) * n;
  u = Unit(u);
  const V v = Cross(n, u);
  std::vector<ReducePoint> rp;
  for (const McdContact &c : out) {
    const V d = FromMe(c.position) - obj.t;
    rp.push_back({Dot(d, u), Dot(d, v), -(double)c.separation});
  }
  int keep[4];
  const double slack = std::fmax(tol, 1e-3 * obj.scale);
  const int kept = ReduceToFour(rp.data(), (int)rp.size(), slack, keep);
  for (int i = 0; i < kept; ++i) out[i] = out[keep[i]];
  out.resize(kept);
}

void Add(std::vector<McdContact> &out, V pos, V n, double s, int d1, int d2, void *tri, MeU32 id, double merge) {
  for (McdContact &c : out) {
    const V cn = FromMe(c.normal);
    if (Len(FromMe(c.position) - pos) <= merge && Dot(cn, n) > 0.999) {
      if (s < c.separation) c.separation = (MeReal)s;
      return;
    }
  }
  McdContact c{};
  ToMe(c.position, pos);
  ToMe(c.normal, n);
  c.separation = (MeReal)s;
  c.dims = (MeI16)((d1 & 0xFF) | ((d2 & 0xFF) << 8));
  c.element2.ptr = tri;
  c.feature = id;
  out.push_back(c);
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const McdModel *m1 = p->model1, *m2 = p->model2;
  const double tol = ContactTolerance(m1->framework);
  Shape obj;
  if (!MakeShape(m1->instance.geometry, ModelTM(m1), obj)) return 0;
  const MeMatrix4Ptr tm = ModelTM(m2);
  // The sphere round model1's AABB, in the list's frame.
  MeVector3 centre, local;
  MeReal radius = 0;
  for (int k = 0; k < 3; ++k) {
    centre[k] = (m1->instance.aabbMin[k] + m1->instance.aabbMax[k]) / 2;
    const MeReal e = (m1->instance.aabbMax[k] - m1->instance.aabbMin[k]) / 2;
    radius += e * e;
  }
  radius = MeSqrt(radius) + (MeReal)tol;
  MeVector3 d;
  MeVector3Subtract(d, centre, tm[3]);
  for (int k = 0; k < 3; ++k) local[k] = MeVector3Dot(d, tm[k]);
  McdUserTriangle *tris = nullptr;
  const int count = McdTriangleListGetTriangles(m2->instance.geometry, p, local, radius, &tris);
  std::vector<McdContact> out;
  const double merge = 1e-3 * obj.scale;
  auto toWorld = [&](const MeReal *v, bool point) {
    V w = point ? FromMe(tm[3]) : V{};
    for (int i = 0; i < 3; ++i) w = w + (double)v[i] * FromMe(tm[i]);
    return w;
  };
  for (int i = 0; i < count; ++i) {
    const McdUserTriangle &ut = tris[i];
    if (!ut.vertices[0] || !ut.vertices[1] || !ut.vertices[2]) continue;
    Tri t;
    for (int k = 0; k < 3; ++k) t.v[k] = toWorld(*ut.vertices[k], true);
    t.flags = ut.flags;
    t.f = ut.normal ? Unit(toWorld(*ut.normal, false)) : Unit(Cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
    if (!(Len(Cross(t.v[1] - t.v[0], t.v[2] - t.v[0])) > 0) || !Finite(t.f)) continue;
    const bool smallest = (t.flags & kMcdTriangleUseSmallestPenetration) != 0;
    const bool twoSided = (t.flags & kMcdTriangleTwoSided) != 0;
    Shape ts;
    MakeTriangle(t.v[0], t.v[1], t.v[2], ts);
    ts.triN = t.f;
    V n;
    double s;
    if (obj.kind == Kind::Sphere) {
      bool inside, sharp;
      const V q = Closest(t, obj.t, &inside, &sharp);
      if (!sharp) continue;
      const double dist = Len(obj.t - q);
      if (dist - obj.margin > tol) continue;
      const double side = Dot(obj.t - q, t.f);
      n = (smallest && dist > 1e-9 * obj.scale) ? (1 / dist) * (obj.t - q) : (twoSided && side < 0 ? -t.f : t.f);
      if (!twoSided && Dot(n, t.f) < 0) n = -n;
      s = Dot(obj.t - q, n) - obj.margin;
      Add(out, q + (0.5 * s) * n, n, s, 2, inside ? 2 : 1, tris + i,
          feature::Mix(TriangleKey(ut), feature::Pack(feature::kSingle, feature::kSphereTriangle)), merge);
      continue;
    }
    if (!Penetration(obj, ts, tol, &n, &s)) continue;
    if (!smallest || !SharpAlong(t, n, ts.scale)) n = (twoSided && Dot(n, t.f) < 0) ? -t.f : t.f;
    if (!twoSided && Dot(n, t.f) < 0) n = -n;
    s = SeparationAlong(obj, ts, n);
    if (!(s <= tol)) continue;
    unsigned mask = 0;
    for (int k = 0; k < 3; ++k)
      if (t.EdgeSharp(k)) mask |= 1u << k;
    ManifoldPoint pts[16];
    const int np = Manifold(obj, ts, n, s, tol, mask, pts, 4);
    const MeU32 key = TriangleKey(ut);
    for (int k = 0; k < np; ++k)
      Add(out, pts[k].position, n, pts[k].separation, pts[k].dims1, pts[k].dims2, tris + i,
          feature::Mix(key, pts[k].feature), merge);
  }
  if (out.empty()) return 0;
  SpreadFour(out, obj, tol);
  std::stable_sort(out.begin(), out.end(),
                   [](const McdContact &a, const McdContact &b) { return a.separation < b.separation; });
  const int n = std::min((int)out.size(), r->contactMaxCount);
  const int first = r->contactCount;
  for (int k = 0; k < n; ++k) r->contacts[r->contactCount++] = out[k];
  feature::MakeDistinct(r->contacts, first, r->contactCount);
  MeVector3Copy(r->normal, out[0].normal);
  r->touch = 1;
  return 1;
}

void Register(McdFrameworkID fw, int a) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  RegisterInteractionQuietly(fw, a, kMcdGeometryTypeTriangleList, fns);
}

}  // namespace

extern "C" {

void MEAPI McdSphereTriangleListRegisterInteraction(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeSphere); }
void MEAPI McdBoxTriangleListRegisterInteraction(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeBox); }
void MEAPI McdCylinderTriangleListRegisterInteraction(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeCylinder); }
void MEAPI McdSphylTriangleListRegisterInteraction(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeSphyl); }
void MEAPI McdConvexMeshTriangleListRegisterInteraction(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeConvexMesh); }

}  // extern "C"
