// penetration.cpp: the least-penetration normal of two convex shapes.
//
// libccd (double precision, as Debian builds it; MeReal converts at the
// boundary in shape.h) runs GJK+EPA on A grown by tol, so shapes within tol
// of touching overlap. EPA's answer is then checked against exact support
// evaluations: for a unit n (from B towards A) the gap along n is
//   s(n) = -h_A(-n) - h_B(n),   h_X(d) = max_{x in X} x . d,
// and for convex shapes the signed distance is max over n of s(n). The
// face normals of both shapes (exact for face contacts) and the EPA
// direction (either sign) are candidates; the largest s(n) wins, except
// that between two flat-faced shapes (neither a sphere nor a sphyl) the
// rule of box_box.cpp applies, "x clearly better than y" meaning
// s_x > s_y + 0.05 |s_y| + 0.01 size (size = half the smaller shape's scale):
//   the face      A's best face normal or B's, whichever is clearly better,
//                 else the one whose supporting polygon has the larger area
//                 (A's on a tie)
//   other         an edge-edge or EPA direction only when clearly better
// so a resting pair keeps one reference face and one normal step after
// step instead of flipping to edge-edge directions that differ from the
// face's by round-off (stacked boxes turned by a small yaw), or between the
// two faces as a small body rocks on a wide one.
#include "convex/shape.h"

#include <ccd/ccd.h>

#include <vector>

namespace karma::mcd::convex {

namespace {

struct CcdObject {
  const Shape *shape;
  double grow;
};

V FromCcd(const ccd_vec3_t *v) { return {v->v[0], v->v[1], v->v[2]}; }

void CcdSupport(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out) {
  const auto *o = static_cast<const CcdObject *>(obj);
  const V d = FromCcd(dir);
  V p = Support(*o->shape, d);
  if (o->grow > 0) p = p + o->grow * Unit(d);
  ccdVec3Set(out, p.x, p.y, p.z);
}

void CcdCentre(const void *obj, ccd_vec3_t *out) {
  const V c = Centre(*static_cast<const CcdObject *>(obj)->shape);
  ccdVec3Set(out, c.x, c.y, c.z);
}

// Direction of B towards A from libccd; false when the shapes do not meet.
bool CcdNormal(const Shape &a, const Shape &b, double tol, V *n, bool *met) {
  CcdObject oa{&a, tol}, ob{&b, 0};
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = CcdSupport;
  ccd.support2 = CcdSupport;
  ccd.center1 = CcdCentre;
  ccd.center2 = CcdCentre;
  ccd.max_iterations = 200;
  const double L = std::fmax(a.scale, b.scale);
  ccd.epa_tolerance = 1e-8 * L * L;
  ccd.mpr_tolerance = 1e-9 * L;
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  ccdVec3Set(&dir, 0, 0, 0);
  const int r = ccdGJKPenetration(&oa, &ob, &ccd, &depth, &dir, &pos);
  *met = r != -1;
  if (r == 0 && Finite(FromCcd(&dir)) && Len(FromCcd(&dir)) > 0.5) {
    *n = -FromCcd(&dir);  // libccd's dir moves obj2 (B) out of obj1 (A)
    return true;
  }
  if (r == -1) return false;
  ccdVec3Set(&dir, 0, 0, 0);
  if (ccdMPRPenetration(&oa, &ob, &ccd, &depth, &dir, &pos) == 0 && Finite(FromCcd(&dir)) && Len(FromCcd(&dir)) > 0.5) {
    *n = -FromCcd(&dir);
    return true;
  }
  return false;
}

// The point of a feature (polygon, segment or point, as Feature gives it)
// closest to p.
V ClosestOnFeature(const V *f, int k, V p) {
  auto onSegment = [](V a, V b, V x) {
    const V e = b - a;
    const double l2 = Dot(e, e);
    const double t = l2 > 0 ? std::fmin(1.0, std::fmax(0.0, Dot(x - a, e) / l2)) : 0;
    return a + t * e;
  };
  if (k == 1) return f[0];
  if (k == 2) return onSegment(f[0], f[1], p);
  const V n = Unit(Cross(f[1] - f[0], f[2] - f[0]));
  const V q = p - Dot(p - f[0], n) * n;
  bool inside = true;
  for (int i = 0; i < k && inside; ++i) inside = Dot(Cross(f[(i + 1) % k] - f[i], q - f[i]), n) >= 0;
  if (inside) return q;
  V best = f[0];
  for (int i = 0; i < k; ++i) {
    const V c = onSegment(f[i], f[(i + 1) % k], p);
    if (Len(c - p) < Len(best - p)) best = c;
  }
  return best;
}

// The area of the shape's supporting polygon along d (0 for an edge or a
// point), by Newell's formula.
double FeatureArea(const Shape &s, V d) {
  V f[16];
  int dims;
  const int k = Feature(s, d, f, &dims);
  if (k < 3) return 0;
  V m;
  for (int i = 0; i < k; ++i) m = m + Cross(f[i], f[(i + 1) % k]);
  return 0.5 * Len(m);
}

// The point of a sphere's or sphyl's core segment closest to x.
V CoreClosest(const Shape &s, V x) {
  if (s.kind == Kind::Sphere) return s.t;
  const V a = s.t + s.hh * s.axis[2], b = s.t - s.hh * s.axis[2], e = b - a;
  const double l2 = Dot(e, e);
  const double t = l2 > 0 ? std::fmin(1.0, std::fmax(0.0, Dot(x - a, e) / l2)) : 0;
  return a + t * e;
}

}  // namespace

bool Penetration(const Shape &a, const Shape &b, double tol, V *n, double *sep) {
  V guess;
  bool met = false;
  const bool haveGuess = CcdNormal(a, b, tol, &guess, &met);
  if (!met) return false;
  double best = -INFINITY;
  V bestN{0, 0, 1};
  double classBest[3] = {-INFINITY, -INFINITY, -INFINITY};  // A's faces, B's faces, others
  V classN[3];
  auto consider = [&](V c, int cls = 2) {
    if (!Finite(c) || !(Len(c) > 0)) return;
    c = Unit(c);
    const double s = SeparationAlong(a, b, c);
    if (s > best + 1e-12 * a.scale) best = s, bestN = c;
    if (s > classBest[cls] + 1e-12 * a.scale) classBest[cls] = s, classN[cls] = c;
  };
  // Face normals first, so that a tie keeps the exact face direction.
  std::vector<V> faces(FaceCount(a) + FaceCount(b) + 1);
  const int na = FaceNormals(a, faces.data(), (int)faces.size());
  for (int i = 0; i < na; ++i) consider(-faces[i], 0);  // A's face rests on B
  const int nb = FaceNormals(b, faces.data(), (int)faces.size());
  for (int i = 0; i < nb; ++i) consider(faces[i], 1);
  if (haveGuess) consider(guess), consider(-guess);
  consider(Centre(a) - Centre(b));
  // Edge-edge directions of the two supporting features (exact for
  // polyhedral edges crossing, and for segments of sphyls and cylinders).
  for (int pass = 0; pass < 2; ++pass) {
    V fa[16], fb[16];
    int da, db;
    const V n0 = bestN;
    const int ka = Feature(a, -n0, fa, &da), kb = Feature(b, n0, fb, &db);
    for (int i = 0; i + 1 < ka + (ka > 2); ++i)
      for (int j = 0; j + 1 < kb + (kb > 2); ++j) {
        const V c = Cross(fa[(i + 1) % ka] - fa[i], fb[(j + 1) % kb] - fb[j]);
        if (Len(c) < 1e-9 * a.scale * b.scale) continue;
        consider(Dot(c, n0) < 0 ? -c : c);
      }
  }
  // A rounded core (sphere, sphyl) against the other's supporting feature:
  // the normal runs through the closest points (a few refinements).
  const bool roundA = a.kind == Kind::Sphere || a.kind == Kind::Sphyl;
  const bool roundB = b.kind == Kind::Sphere || b.kind == Kind::Sphyl;
  for (int it = 0; it < 3 && (roundA || roundB); ++it) {
    V f[16];
    int dims;
    const V n0 = bestN;
    if (roundA) {
      const int k = Feature(b, n0, f, &dims);
      const V q = ClosestOnFeature(f, k, CoreClosest(a, Support(b, n0)));
      consider(CoreClosest(a, q) - q);
    }
    if (roundB) {
      const int k = Feature(a, -n0, f, &dims);
      const V q = ClosestOnFeature(f, k, CoreClosest(b, Support(a, -n0)));
      consider(q - CoreClosest(b, q));
    }
  }
  if (!(best <= tol) || !std::isfinite(best)) return false;
  const bool flat = !(roundA || roundB) && classBest[0] > -INFINITY && classBest[1] > -INFINITY;
  if (flat) {
    const double size = 0.5 * std::fmin(a.scale, b.scale);
    auto clearlyBetter = [&](double x, double y) { return x > y + 0.05 * std::fabs(y) + 0.01 * size; };
    int face = FeatureArea(b, classN[1]) > FeatureArea(a, -classN[0]) ? 1 : 0;
    if (clearlyBetter(classBest[1], classBest[0]))
      face = 1;
    else if (clearlyBetter(classBest[0], classBest[1]))
      face = 0;
    const bool other = clearlyBetter(classBest[2], classBest[face]);
    const int cls = other ? 2 : face;
    bestN = classN[cls], best = classBest[cls];
  }
  *n = bestN;
  *sep = best;
  return true;
}

}  // namespace karma::mcd::convex
