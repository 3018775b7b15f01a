// convex_hull.cpp: the convex hull of a point cloud through Qhull (the
// reentrant libqhull_r). Qhull merges coplanar facets by default, so a
// cube's hull has 6 square faces; points inside, on faces or on edges, and
// repeated points, are not hull vertices.
//
// Degeneracy is checked first with our own test, so the message is ours:
// from the cloud's extent D, pick the farthest pair (a, b), the point c
// farthest from line ab and the point d farthest from plane abc; the cloud
// spans a volume when dist(d, abc) > 1e-6 D (in double).
#include "convex_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace karma::mcd {
namespace {

Vec3d Sub(const Vec3d &a, const Vec3d &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double Dot(const Vec3d &a, const Vec3d &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d Cross(const Vec3d &a, const Vec3d &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double Norm(const Vec3d &a) { return std::sqrt(Dot(a, a)); }

bool SpansVolume(const std::vector<Vec3d> &p, std::string &why) {
  const std::size_t n = p.size();
  std::size_t a = 0, b = 0;
  for (std::size_t i = 1; i < n; ++i)  // farthest from p[0], then farthest from that
    if (Norm(Sub(p[i], p[0])) > Norm(Sub(p[a], p[0]))) a = i;
  for (std::size_t i = 0; i < n; ++i)
    if (Norm(Sub(p[i], p[a])) > Norm(Sub(p[b], p[a]))) b = i;
  const double D = Norm(Sub(p[b], p[a]));
  if (!(D > 0)) {
    why = "all the points coincide";
    return false;
  }
  const Vec3d ab = Sub(p[b], p[a]);
  std::size_t c = a;
  double best = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = Norm(Cross(ab, Sub(p[i], p[a]))) / D;
    if (d > best) best = d, c = i;
  }
  if (best <= 1e-6 * D) {
    why = "the points lie on one line";
    return false;
  }
  Vec3d normal = Cross(ab, Sub(p[c], p[a]));
  const double len = Norm(normal);
  best = 0;
  for (std::size_t i = 0; i < n; ++i) best = std::max(best, std::fabs(Dot(normal, Sub(p[i], p[a]))) / len);
  if (best <= 1e-6 * D) {
    why = "the points lie in one plane";
    return false;
  }
  return true;
}

// Orders a face's vertex loop counter-clockwise about its outward normal.
void OrderLoop(std::vector<int> &loop, const std::vector<Vec3d> &v, const Vec3d &n) {
  Vec3d c{0, 0, 0};
  for (int i : loop)
    for (int k = 0; k < 3; ++k) c[k] += v[i][k] / (double)loop.size();
  Vec3d u = Sub(v[loop[0]], c);
  const double ul = Norm(u);
  for (double &x : u) x /= ul;
  const Vec3d w = Cross(n, u);  // u -> w is counter-clockwise seen from +n
  std::vector<std::pair<double, int>> keyed;
  for (int i : loop) {
    const Vec3d d = Sub(v[i], c);
    keyed.emplace_back(std::atan2(Dot(d, w), Dot(d, u)), i);
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < loop.size(); ++k) loop[k] = keyed[k].second;
}

}  // namespace

bool BuildHull(const MeVector3 *points, int count, Hull &hull, std::string &why) {
  if (count < 4) {
    why = "a hull needs at least 4 points, got " + std::to_string(count);
    return false;
  }
  std::vector<Vec3d> p((std::size_t)count);
  for (int i = 0; i < count; ++i) {
    if (!MeVector3AllFinite(points[i])) {
      why = "point " + std::to_string(i) + " is not finite";
      return false;
    }
    p[(std::size_t)i] = {(double)points[i][0], (double)points[i][1], (double)points[i][2]};
  }
  if (!SpansVolume(p, why)) return false;

  std::vector<coordT> coords(p.size() * 3);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) coords[i * 3 + (std::size_t)k] = p[i][(std::size_t)k];
  char messages[512] = {0};
  FILE *err = fmemopen(messages, sizeof messages - 1, "w");
  qhT qh_qh;
  qhT *qh = &qh_qh;
  qh_zero(qh, err);
  char options[] = "qhull";
  const int exitcode = qh_new_qhull(qh, 3, count, coords.data(), False, options, nullptr, err);
  bool ok = exitcode == 0;
  if (ok) {
    std::vector<int> map((std::size_t)count, -1);  // input index -> hull vertex
    vertexT *vertex, **vertexp;
    facetT *facet;
    std::vector<int> ids;
    FORALLvertices ids.push_back(qh_pointid(qh, vertex->point));
    std::sort(ids.begin(), ids.end());
    for (int id : ids) {
      map[(std::size_t)id] = (int)hull.vertices.size();
      hull.vertices.push_back(p[(std::size_t)id]);
    }
    Vec3d centre{0, 0, 0};
    for (const Vec3d &v : hull.vertices)
      for (int k = 0; k < 3; ++k) centre[k] += v[k] / (double)hull.vertices.size();
    FORALLfacets {
      std::vector<int> loop;
      FOREACHvertex_(facet->vertices) loop.push_back(map[(std::size_t)qh_pointid(qh, vertex->point)]);
      Vec3d n{facet->normal[0], facet->normal[1], facet->normal[2]};
      if (Dot(n, Sub(hull.vertices[(std::size_t)loop[0]], centre)) < 0)
        for (double &x : n) x = -x;
      OrderLoop(loop, hull.vertices, n);
      hull.faces.push_back(std::move(loop));
      hull.normals.push_back(n);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (err) std::fclose(err);
  if (!ok) {
    why = std::string("Qhull failed: ") + messages;
    hull = Hull{};
  }
  return ok;
}

// For the tetrahedron (o, a, b, c) with a, b, c relative to o and
// det = a . (b x c) (six times its signed volume):
//   volume  det / 6,  centroid o + (a + b + c) / 4,
//   integral of x x^T = det/120 (a a^T + b b^T + c c^T + s s^T), s = a+b+c.
// Summed over the fans of outward-oriented faces, the signs cancel outside
// the body. Then C about the centre of mass: C - V d d^T (d = com - o), and
// the inertia tensor I = trace(C) E - C.
void PolyhedronMass(const Hull &hull, double &volume, Vec3d &com, double inertia[3][3]) {
  Vec3d o{0, 0, 0};
  for (const Vec3d &v : hull.vertices)
    for (int k = 0; k < 3; ++k) o[k] += v[k] / (double)hull.vertices.size();
  double C[3][3] = {};
  Vec3d first{0, 0, 0};
  volume = 0;
  for (const std::vector<int> &f : hull.faces) {
    const Vec3d a = Sub(hull.vertices[(std::size_t)f[0]], o);
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const Vec3d b = Sub(hull.vertices[(std::size_t)f[i]], o);
      const Vec3d c = Sub(hull.vertices[(std::size_t)f[i + 1]], o);
      const double det = Dot(a, Cross(b, c));
      volume += det / 6;
      const Vec3d s{a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};
      for (int k = 0; k < 3; ++k) first[k] += det / 24 * s[k];
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) C[r][q] += det / 120 * (a[r] * a[q] + b[r] * b[q] + c[r] * c[q] + s[r] * s[q]);
    }
  }
  Vec3d d{first[0] / volume, first[1] / volume, first[2] / volume};
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) C[r][q] -= volume * d[r] * d[q];
  const double trace = C[0][0] + C[1][1] + C[2][2];
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) inertia[r][q] = (r == q ? trace : 0) - C[r][q];
  for (int k = 0; k < 3; ++k) com[k] = o[k] + d[k];
}

}  // namespace karma::mcd
