// contact_reduce.h: at most four contacts out of the points of a face-face
// touch, chosen by a rule that gives the same points step after step for
// a resting pair.
//
// The candidates are points (x, y) of the contact area in a 2D frame fixed
// to the reference face (its own axes, so the choice turns with the body),
// each with a depth (penetration, larger is deeper).
//  1. Spread: for each of the four directions w_k = (cos a_k, sin a_k),
//     a_k = 22.5 + 90 k degrees, the candidate with the largest (x, y).w_k is
//     kept (the first in input order on an exact tie; a point chosen twice
//     counts once). These span the area: a rectangle's corners; for the
//     octagon left when two equal squares are turned by theta, four
//     alternate vertices. The octagon is symmetric about the lines at
//     theta/2 + 45 j degrees, and a direction along such a line would make a
//     mirror pair of vertices tie (diagonal directions tie at theta ~ 0,
//     exactly the near-aligned stacks that must stay put); at 22.5 degrees
//     the extreme vertex lies on the line itself, so no yaw gives a tie.
//  2. Deepest: when the deepest candidate was not kept and is deeper than
//     every kept point by more than `slack`, it replaces the kept point
//     nearest to it. A tilted touch so keeps its deepest point; a resting
//     one, whose depths differ by round-off, keeps step 1's choice.
// The choice depends only on the geometry, never on depth order below
// `slack`, so small motions of a resting pair do not change it.
#pragma once

#include <cmath>

namespace karma::mcd {

struct ReducePoint {
  double x, y, depth;
};

// Writes the indices of the kept candidates (at most 4, increasing) to
// keep[] and returns their count; n <= 4 keeps all.
inline int ReduceToFour(const ReducePoint *pts, int n, double slack, int keep[4]) {
  if (n <= 4) {
    for (int i = 0; i < n; ++i) keep[i] = i;
    return n;
  }
  static constexpr double kC = 0.92387953251128674, kS = 0.38268343236508978;  // 22.5 deg
  static constexpr double kDir[4][2] = {{kC, kS}, {-kS, kC}, {-kC, -kS}, {kS, -kC}};
  bool chosen[64] = {};
  int count = 0;
  for (const auto &w : kDir) {
    int pick = 0;
    double best = -INFINITY;
    for (int i = 0; i < n && i < 64; ++i) {
      const double s = pts[i].x * w[0] + pts[i].y * w[1];
      if (s > best) best = s, pick = i;
    }
    if (!chosen[pick]) chosen[pick] = true, ++count;
  }
  int deepest = 0;
  for (int i = 1; i < n && i < 64; ++i)
    if (pts[i].depth > pts[deepest].depth) deepest = i;
  if (!chosen[deepest]) {
    double keptDepth = -INFINITY, near = INFINITY;
    int nearest = -1;
    for (int i = 0; i < n && i < 64; ++i) {
      if (!chosen[i]) continue;
      keptDepth = std::fmax(keptDepth, pts[i].depth);
      const double d = std::hypot(pts[i].x - pts[deepest].x, pts[i].y - pts[deepest].y);
      if (d < near) near = d, nearest = i;
    }
    if (pts[deepest].depth > keptDepth + slack) chosen[nearest] = false, chosen[deepest] = true;
  }
  int k = 0;
  for (int i = 0; i < n && i < 64; ++i)
    if (chosen[i]) keep[k++] = i;
  return k;
}

}  // namespace karma::mcd
