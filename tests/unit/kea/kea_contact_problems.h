// kea_contact_problems.h: boxed LCPs with the structure of the step's
// partitions, built from bodies and Jacobian rows as Mdt builds them
// (A = J M^-1 J^T + soft on the diagonal, CSR with both triangles), for the
// Kea tests (kea_warm_test.cpp, kea_factor_memory_test.cpp, kea_alloc_test.cpp)
// and bench/kea_bench.cpp, with two small helpers of those tests.
//
//  - Stack: `boxes` unit cubes (1 kg) on the ground, 4 corner contacts per
//    touching face, each contact a normal row [0, inf) and two friction rows
//    tied to it (mu 0.5), rows ordered pair by pair from the ground up (as
//    the bridge orders a column's contacts). Gravity loads the contacts;
//    small sideways velocities and penetrations, varied by `seed`, make the
//    friction rows work.
//  - Car: a 1000 kg chassis and four 20 kg wheels on hinges (5 bilateral
//    rows each) touching the ground (one contact each): 32 rows.
//  - Chain: `links` 1 kg rods tied end to end by ball joints (3 bilateral
//    rows each), the first to the world, swinging: a banded A.
//  - Pile: `contacts` contacts between random pairs of `bodies` unit cubes
//    (or a cube and the ground), in random order: an A whose envelope is
//    nearly full, as in a heap whose rows come in no particular order.
#ifndef KARMA_TESTS_KEA_CONTACT_PROBLEMS_H
#define KARMA_TESTS_KEA_CONTACT_PROBLEMS_H

#include "kea_lcp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace kea_test {

using Vec3 = std::array<double, 3>;

// Largest magnitude of a solution vector (the scale of its tolerances).
inline double MaxAbs(const std::vector<MeReal> &v) {
  double m = 0;
  for (MeReal x : v) m = std::max(m, std::fabs(double(x)));
  return m;
}

// A KeaWorkspace that destroys itself.
struct WorkspaceDeleter {
  void operator()(karma::kea::KeaWorkspace *w) const { karma::kea::KeaWorkspaceDestroy(w); }
};
using Workspace = std::unique_ptr<karma::kea::KeaWorkspace, WorkspaceDeleter>;

// The diagonal softness of every row: Mdt's default world epsilon for
// unit masses (0.01).
inline constexpr double kSoft = 0.01;

inline Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// One body: inverse mass, inverse (diagonal, body = world frame) inertia,
// velocity (linear, angular) and external force (linear).
struct Body {
  double invMass = 0;
  Vec3 invInertia{0, 0, 0};
  Vec3 v{0, 0, 0}, w{0, 0, 0};
  Vec3 force{0, 0, 0};
};

// One constraint row: Jacobian blocks on body0 and body1 (-1 = world),
// linear then angular.
struct JRow {
  int body0 = -1, body1 = -1;
  std::array<double, 6> j0{}, j1{};
  double bias = 0;  // added to b (error correction)
  double lo = 0, hi = 0;
  int findex = -1;
  double mu = 0;
};

// A problem owning its arrays.
struct ContactProblem {
  int n = 0;
  std::vector<int> rowStart, col, findex;
  std::vector<MeReal> val, b, lo, hi, mu;
  karma::kea::SparseLcpProblem sparse() const { return {n, rowStart, col, val, b, lo, hi, findex, mu}; }
};

// A = J M^-1 J^T + soft I in CSR; b = bias - J v - h J M^-1 f.
inline ContactProblem Assemble(const std::vector<Body> &bodies, const std::vector<JRow> &rows, double h, double soft,
                               bool friction) {
  ContactProblem p;
  p.n = static_cast<int>(rows.size());
  const auto n = rows.size();
  auto minvJ = [&](const JRow &r, int side) {
    const int bi = side == 0 ? r.body0 : r.body1;
    const auto &j = side == 0 ? r.j0 : r.j1;
    std::array<double, 6> out{};
    if (bi < 0) return out;
    const Body &b = bodies[static_cast<std::size_t>(bi)];
    for (int d = 0; d < 3; ++d) {
      out[static_cast<std::size_t>(d)] = b.invMass * j[static_cast<std::size_t>(d)];
      out[static_cast<std::size_t>(d + 3)] =
          b.invInertia[static_cast<std::size_t>(d)] * j[static_cast<std::size_t>(d + 3)];
    }
    return out;
  };
  p.rowStart.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k) {
      double a = 0;
      bool shares = false;
      for (int si = 0; si < 2; ++si)
        for (int sk = 0; sk < 2; ++sk) {
          const int bi = si == 0 ? rows[i].body0 : rows[i].body1;
          const int bk = sk == 0 ? rows[k].body0 : rows[k].body1;
          if (bi < 0 || bi != bk) continue;
          shares = true;
          const auto &ji = si == 0 ? rows[i].j0 : rows[i].j1;
          const auto mk = minvJ(rows[k], sk);
          for (std::size_t d = 0; d < 6; ++d) a += ji[d] * mk[d];
        }
      if (i == k) {
        a += soft;
        shares = true;
      }
      if (!shares) continue;
      p.col.push_back(static_cast<int>(k));
      p.val.push_back(static_cast<MeReal>(a));
    }
    p.rowStart.push_back(static_cast<int>(p.col.size()));
  }
  for (const JRow &r : rows) {
    double b = r.bias;
    for (int side = 0; side < 2; ++side) {
      const int bi = side == 0 ? r.body0 : r.body1;
      if (bi < 0) continue;
      const Body &body = bodies[static_cast<std::size_t>(bi)];
      const auto &j = side == 0 ? r.j0 : r.j1;
      for (std::size_t d = 0; d < 3; ++d)
        b -= j[d] * (body.v[d] + h * body.invMass * body.force[d]) + j[d + 3] * body.w[d];
    }
    p.b.push_back(static_cast<MeReal>(b));
    p.lo.push_back(static_cast<MeReal>(r.lo));
    p.hi.push_back(static_cast<MeReal>(r.hi));
    if (friction) {
      p.findex.push_back(r.findex);
      p.mu.push_back(static_cast<MeReal>(r.mu));
    }
  }
  return p;
}

// A deterministic value in [-1, 1) from a seed and an index.
inline double Jitter(unsigned seed, unsigned i) {
  std::uint32_t x = seed * 2654435761u + i * 2246822519u + 1u;
  x ^= x >> 15;
  x *= 2246822519u;
  x ^= x >> 13;
  return static_cast<double>(x % 20001u) / 10000.0 - 1.0;
}

// A contact between body `upper` and body `lower` (-1 = ground) at point
// `at`, normal +z: rows appended (normal, then friction x and y when
// `friction`).
inline void AddContact(std::vector<JRow> &rows, const std::vector<Vec3> &centres, int upper, int lower, const Vec3 &at,
                       double depth, double mu, bool friction) {
  const Vec3 axes[3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  const int normalRow = static_cast<int>(rows.size());
  for (int k = 0; k < (friction ? 3 : 1); ++k) {
    JRow r;
    r.body0 = upper;
    r.body1 = lower;
    const Vec3 &d = axes[k];
    auto fill = [&](std::array<double, 6> &j, int body, double sign) {
      if (body < 0) return;
      const Vec3 &c = centres[static_cast<std::size_t>(body)];
      const Vec3 arm{at[0] - c[0], at[1] - c[1], at[2] - c[2]};
      const Vec3 t = Cross(arm, d);
      for (std::size_t q = 0; q < 3; ++q) {
        j[q] = sign * d[q];
        j[q + 3] = sign * t[q];
      }
    };
    fill(r.j0, upper, 1);
    fill(r.j1, lower, -1);
    if (k == 0) {
      r.lo = 0;
      r.hi = MEINFINITY;
      r.bias = 0.2 * 60 * depth;  // gamma / h * depth
    } else {
      r.findex = normalRow;
      r.mu = mu;
    }
    rows.push_back(r);
  }
}

inline ContactProblem Stack(int boxes, unsigned seed, bool friction = true) {
  const double h = 1.0 / 60, g = 9.81;
  std::vector<Body> bodies(static_cast<std::size_t>(boxes));
  std::vector<Vec3> centres;
  for (int k = 0; k < boxes; ++k) {
    Body &b = bodies[static_cast<std::size_t>(k)];
    b.invMass = 1;
    b.invInertia = {6, 6, 6};  // unit cube, 1 kg: I = 1/6
    b.force = {0, 0, -g};
    b.v = {0.01 * Jitter(seed, 3u * unsigned(k)), 0.01 * Jitter(seed, 3u * unsigned(k) + 1), 0};
    b.w = {0, 0, 0.02 * Jitter(seed, 3u * unsigned(k) + 2)};
    centres.push_back({0.02 * Jitter(seed + 7, unsigned(k)), 0, 0.5 + k});
  }
  std::vector<JRow> rows;
  unsigned c = 0;
  for (int k = 0; k < boxes; ++k)
    for (int corner = 0; corner < 4; ++corner, ++c) {
      const Vec3 at{centres[static_cast<std::size_t>(k)][0] + ((corner & 1) ? 0.5 : -0.5), (corner & 2) ? 0.5 : -0.5,
                    double(k)};
      const double depth = 0.001 * (1 + Jitter(seed + 11, c)) / 2;
      AddContact(rows, centres, k, k - 1, at, depth, 0.5, friction);
    }
  return Assemble(bodies, rows, h, kSoft, friction);
}

inline ContactProblem Car(unsigned seed) {
  const double h = 1.0 / 60, g = 9.81;
  std::vector<Body> bodies(5);
  std::vector<Vec3> centres{{0, 0, 0.6}, {1.3, 0.8, 0.35}, {1.3, -0.8, 0.35}, {-1.3, 0.8, 0.35}, {-1.3, -0.8, 0.35}};
  bodies[0].invMass = 1.0 / 1000;
  bodies[0].invInertia = {1.0 / 400, 1.0 / 1200, 1.0 / 1400};
  bodies[0].v = {10, 0, 0};
  for (std::size_t k = 1; k < 5; ++k) {
    bodies[k].invMass = 1.0 / 20;
    bodies[k].invInertia = {1.0 / 1.2, 1.0 / 1.5, 1.0 / 1.2};
    bodies[k].force = {0, 0, -20 * g};
    bodies[k].v = {10 + 0.05 * Jitter(seed, unsigned(k)), 0, 0};
    bodies[k].w = {0, 10 / 0.35, 0};
  }
  bodies[0].force = {0, 0, -1000 * g};
  std::vector<JRow> rows;
  for (int wheel = 1; wheel <= 4; ++wheel) {
    // Hinge about y: 3 linear rows at the wheel centre, 2 angular (x, z).
    const Vec3 &at = centres[static_cast<std::size_t>(wheel)];
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 5; ++k) {
      JRow r;
      r.body0 = wheel;
      r.body1 = 0;
      r.lo = -MEINFINITY;
      r.hi = MEINFINITY;
      if (k < 3) {
        const Vec3 &d = axes[k];
        const Vec3 arm{at[0] - centres[0][0], at[1] - centres[0][1], at[2] - centres[0][2]};
        const Vec3 t = Cross(arm, d);
        for (std::size_t q = 0; q < 3; ++q) {
          r.j0[q] = d[q];
          r.j1[q] = -d[q];
          r.j1[q + 3] = -t[q];
        }
        r.bias = 0.2 * 60 * 0.0005 * Jitter(seed + 3, unsigned(wheel * 5 + k));
      } else {
        const Vec3 &d = axes[k == 3 ? 0 : 2];
        for (std::size_t q = 0; q < 3; ++q) {
          r.j0[q + 3] = d[q];
          r.j1[q + 3] = -d[q];
        }
      }
      rows.push_back(r);
    }
    AddContact(rows, centres, wheel, -1, {at[0], at[1], 0}, 0.001 * (1 + Jitter(seed + 5, unsigned(wheel))) / 2, 1.0,
               true);
  }
  return Assemble(bodies, rows, h, kSoft, true);
}

inline ContactProblem Chain(int links, unsigned seed) {
  const double h = 1.0 / 60, g = 9.81;
  std::vector<Body> bodies(static_cast<std::size_t>(links));
  std::vector<Vec3> centres;
  for (int k = 0; k < links; ++k) {
    Body &b = bodies[static_cast<std::size_t>(k)];
    b.invMass = 1;
    b.invInertia = {12, 12, 12};
    b.force = {0, 0, -g};
    b.v = {0, 0.1 * Jitter(seed, unsigned(k)), 0};
    centres.push_back({0.5 + k, 0, 0});
  }
  std::vector<JRow> rows;
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < links; ++k) {
    const Vec3 at{double(k), 0, 0};
    for (int q = 0; q < 3; ++q) {
      JRow r;
      r.body0 = k;
      r.body1 = k - 1;
      r.lo = -MEINFINITY;
      r.hi = MEINFINITY;
      for (int side = 0; side < 2; ++side) {
        const int body = side == 0 ? k : k - 1;
        if (body < 0) continue;
        const Vec3 &c = centres[static_cast<std::size_t>(body)];
        const Vec3 t = Cross({at[0] - c[0], at[1] - c[1], at[2] - c[2]}, axes[q]);
        auto &j = side == 0 ? r.j0 : r.j1;
        const double sign = side == 0 ? 1 : -1;
        for (std::size_t d = 0; d < 3; ++d) {
          j[d] = sign * axes[q][d];
          j[d + 3] = sign * t[d];
        }
      }
      rows.push_back(r);
    }
  }
  return Assemble(bodies, rows, h, kSoft, false);
}

inline ContactProblem Pile(int contacts, int bodies, unsigned seed) {
  const double h = 1.0 / 60, g = 9.81;
  std::vector<Body> all(static_cast<std::size_t>(bodies));
  std::vector<Vec3> centres;
  for (int k = 0; k < bodies; ++k) {
    Body &b = all[static_cast<std::size_t>(k)];
    b.invMass = 1;
    b.invInertia = {6, 6, 6};
    b.force = {0, 0, -g};
    b.v = {0.05 * Jitter(seed, 2u * unsigned(k)), 0.05 * Jitter(seed, 2u * unsigned(k) + 1), -0.1};
    centres.push_back({3 * Jitter(seed + 1, unsigned(k)), 3 * Jitter(seed + 2, unsigned(k)), 0.5 + k % 4});
  }
  std::vector<JRow> rows;
  for (int c = 0; c < contacts; ++c) {
    const auto u = static_cast<unsigned>(c);
    const int upper = static_cast<int>((Jitter(seed + 3, u) + 1) / 2 * (bodies - 1) + 0.5);
    int lower = static_cast<int>((Jitter(seed + 4, u) + 1) / 2 * bodies - 0.5);  // -1 .. bodies-1
    if (lower == upper) lower = -1;
    const Vec3 &cu = centres[static_cast<std::size_t>(upper)];
    const Vec3 at{cu[0] + 0.5 * Jitter(seed + 5, u), cu[1] + 0.5 * Jitter(seed + 6, u), cu[2] - 0.5};
    AddContact(rows, centres, upper, lower, at, 0.001 * (1 + Jitter(seed + 7, u)) / 2, 0.5, true);
  }
  return Assemble(all, rows, h, kSoft, true);
}

}  // namespace kea_test

#endif
