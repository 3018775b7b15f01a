// box_box_test.cpp: box against box: resting manifolds (at the corners of
// the overlap), the 45-degree octagon, buffer reduction, deep overlap,
// corner on a face, edge-edge, separation found only on an edge axis,
// coincident boxes, both argument orders.
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>
#include <utility>

#include "nearfield_test_support.h"

using namespace mcd_test;
using namespace mcd_test::prim;

namespace {

const double kEps = 4e-6;

// The contacts' (x, y) rounded to 1e-4, as a set.
std::set<std::pair<long, long>> corners(const Hit &h) {
  std::set<std::pair<long, long>> s;
  for (int i = 0; i < h.count(); ++i)
    s.insert({std::lround(h.c[i].position[0] * 1e4), std::lround(h.c[i].position[1] * 1e4)});
  return s;
}

void expectMirrored(McdModelID a, McdModelID b) {
  Hit f(a, b), r(b, a);
  ASSERT_EQ(f.count(), r.count());
  for (int i = 0; i < f.count(); ++i) {
    EXPECT_EQ(f.c[i].separation, r.c[i].separation);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(f.c[i].position[k], r.c[i].position[k]);
      EXPECT_EQ(f.c[i].normal[k], -r.c[i].normal[k]);
    }
  }
}

TEST(McdBoxBox, BoxRestingOnBoxHasFourContactsAtTheCorners) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);  // top face z = 1, |x|, |y| <= 2
  Placed top(McdBoxCreate(fw, 2, 2, 2), (MeReal)0.5, (MeReal)0.3, (MeReal)1.99);
  Hit h(top.model, base.model);
  ASSERT_EQ(h.touch, 1);
  ASSERT_EQ(h.count(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(h.c[i].separation, -0.01, kEps);
    EXPECT_NEAR(h.c[i].normal[2], 1, kEps);
    EXPECT_NEAR(h.c[i].position[2], 0.995, kEps);
  }
  const std::set<std::pair<long, long>> want = {{-5000, -7000}, {-5000, 13000}, {15000, -7000}, {15000, 13000}};
  EXPECT_EQ(corners(h), want);
  EXPECT_NEAR(h.r.normal[2], 1, kEps);
  expectMirrored(top.model, base.model);
  // Reversed: normals down.
  Hit rev(base.model, top.model);
  ASSERT_EQ(rev.count(), 4);
  EXPECT_NEAR(rev.c[0].normal[2], -1, kEps);
  // Exactly touching still counts; lifted clear does not.
  top.move((MeReal)0.5, (MeReal)0.3, 2);
  EXPECT_EQ(Hit(top.model, base.model).count(), 4);
  top.move((MeReal)0.5, (MeReal)0.3, (MeReal)2.001);
  EXPECT_EQ(Hit(top.model, base.model).touch, 0);
}

TEST(McdBoxBox, OverhangingBoxContactsAtTheCornersOfTheOverlap) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Placed top(McdBoxCreate(fw, 2, 2, 2), (MeReal)1.5, 0, (MeReal)1.98);  // x in [0.5, 2.5]
  Hit h(top.model, base.model);
  ASSERT_EQ(h.count(), 4);
  const std::set<std::pair<long, long>> want = {{5000, -10000}, {5000, 10000}, {20000, -10000}, {20000, 10000}};
  EXPECT_EQ(corners(h), want);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(h.c[i].separation, -0.02, kEps);
  // Same-size boxes exactly stacked: the four shared corners.
  Placed twin(McdBoxCreate(fw, 4, 4, 2), 0, 0, (MeReal)1.995);
  Hit t(twin.model, base.model);
  ASSERT_EQ(t.count(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(std::fabs(t.c[i].position[0]), 2, kEps);
    EXPECT_NEAR(std::fabs(t.c[i].position[1]), 2, kEps);
    EXPECT_NEAR(t.c[i].separation, -0.005, kEps);
  }
}

TEST(McdBoxBox, TurnedBoxGivesFourOfTheOctagonAndReducesToTheBuffer) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  // Half side 1.8 turned 45 degrees: corners at 2.55 along x and y, clipped
  // by |x|, |y| <= 2 into an octagon with vertices (+-2, +-0.546) and
  // (+-0.546, +-2). Four alternate vertices are kept (contact_reduce.h):
  // the square of circumradius |(2, 0.546)| = 2.073, area 2 * 2.073^2 = 8.6.
  Placed top(McdBoxCreate(fw, (MeReal)3.6, (MeReal)3.6, 2), 0, 0, (MeReal)1.99, {0, 0, 1}, (MeReal)(ME_PI / 4));
  Hit h(top.model, base.model);
  ASSERT_EQ(h.count(), 4);
  double angle[4];
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(std::fmax(std::fabs(h.c[i].position[0]), std::fabs(h.c[i].position[1])), 2, 1e-5);
    EXPECT_NEAR(std::hypot(h.c[i].position[0], h.c[i].position[1]), 2.0732, 1e-3);
    EXPECT_NEAR(h.c[i].separation, -0.01, kEps);
    angle[i] = std::atan2(h.c[i].position[1], h.c[i].position[0]);
  }
  // One per quadrant of turn: sorted angles 90 degrees apart.
  std::sort(angle, angle + 4);
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(angle[i] - angle[i - 1], ME_PI / 2, 1e-3);
  // A shorter buffer keeps the deepest, then the farthest: two opposite ones.
  Hit two(top.model, base.model, 2);
  ASSERT_EQ(two.count(), 2);
  EXPECT_NEAR(std::hypot(two.c[0].position[0] - two.c[1].position[0], two.c[0].position[1] - two.c[1].position[1]),
              2 * 2.0732, 2e-3);
  // Small turned box fully on the face: its 4 corners.
  Placed small(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)1.99, {0, 0, 1}, (MeReal)(ME_PI / 4));
  Hit s(small.model, base.model);
  ASSERT_EQ(s.count(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(std::hypot(s.c[i].position[0], s.c[i].position[1]), std::sqrt(2.0), 1e-5);
}

TEST(McdBoxBox, DeepOverlapAndTiltedOntoAnEdge) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);
  Placed top(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)1.5);  // 0.5 deep
  Hit h(top.model, base.model);
  ASSERT_EQ(h.count(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(h.c[i].separation, -0.5, kEps);
  EXPECT_NEAR(h.r.normal[2], 1, kEps);
  // Tilted 0.3 rad about y: the lowest edge 0.03 below z = 1 gives 2 contacts.
  const double c = std::cos(0.3), s = std::sin(0.3);
  top.turn({0, 1, 0}, (MeReal)0.3);
  top.move(0, 0, (MeReal)(1 - 0.03 + c + s));
  Hit e(top.model, base.model);
  ASSERT_EQ(e.count(), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(e.c[i].separation, -0.03, 1e-5);
    EXPECT_NEAR(std::fabs(e.c[i].position[1]), 1, 1e-5);
    EXPECT_NEAR(e.c[i].normal[2], 1, kEps);
  }
  expectMirrored(top.model, base.model);
}

TEST(McdBoxBox, CornerOnAFaceGivesOneContact) {
  Framework fw;
  Placed base(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);  // top face z = 1
  // A unit-half cube turned about (1, -1, 0) by acos(1/sqrt 3): a body
  // diagonal vertical, so a corner sqrt 3 below the centre, 0.01 deep.
  const double r3 = std::sqrt(3.0);
  Placed cube(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)(1 + r3 - 0.01), {1, -1, 0}, (MeReal)std::acos(1 / r3));
  Hit h(cube.model, base.model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.c[0].separation, -0.01, 1e-5);
  EXPECT_NEAR(h.c[0].normal[2], 1, kEps);
  EXPECT_NEAR(h.c[0].position[0], 0, 1e-5);
  EXPECT_NEAR(h.c[0].position[1], 0, 1e-5);
  EXPECT_NEAR(h.c[0].position[2], 0.995, 1e-5);
  EXPECT_EQ(h.c[0].dims, (MeI16)(0 | (2 << 8)));  // cube corner on the base's face
  expectMirrored(cube.model, base.model);
  cube.move(0, 0, (MeReal)(1 + r3 + 0.01));
  EXPECT_EQ(Hit(cube.model, base.model).touch, 0);
}

TEST(McdBoxBox, EdgeAgainstEdgeGivesOneContact) {
  Framework fw;
  const double r2 = std::sqrt(2.0);
  // Lower box turned 45 degrees about y: top edge along y at z = sqrt 2.
  // Upper box turned 45 degrees about x: bottom edge along x at z - sqrt 2.
  Placed low(McdBoxCreate(fw, 2, 2, 2), 0, 0, 0, {0, 1, 0}, (MeReal)(ME_PI / 4));
  Placed up(McdBoxCreate(fw, 2, 2, 2), 0, 0, (MeReal)(2 * r2 - 0.01), {1, 0, 0}, (MeReal)(ME_PI / 4));
  Hit h(up.model, low.model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.c[0].separation, -0.01, 1e-5);
  EXPECT_NEAR(h.c[0].normal[2], 1, 1e-5);
  EXPECT_NEAR(h.c[0].position[0], 0, 1e-5);
  EXPECT_NEAR(h.c[0].position[1], 0, 1e-5);
  EXPECT_NEAR(h.c[0].position[2], r2 - 0.005, 1e-5);
  EXPECT_EQ(h.c[0].dims, (MeI16)(1 | (1 << 8)));
  expectMirrored(up.model, low.model);
  // Lifted 0.01 clear: only the edge axis x cross y separates them.
  up.move(0, 0, (MeReal)(2 * r2 + 0.01));
  EXPECT_EQ(Hit(up.model, low.model).touch, 0);
  EXPECT_EQ(Hit(low.model, up.model).touch, 0);
}

TEST(McdBoxBox, CoincidentAndParallelBoxesGiveFiniteResults) {
  Framework fw;
  McdGeometryID g = McdBoxCreate(fw, 1, 2, 3);
  Placed a(g, 1, 1, 1), b(g, 1, 1, 1);
  Hit h(a.model, b.model);
  ASSERT_EQ(h.touch, 1);
  ASSERT_GE(h.count(), 1);
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(MeVector3Magnitude(h.c[i].normal), 1, kEps);
    EXPECT_TRUE(std::isfinite(h.c[i].separation));
    EXPECT_NEAR(h.c[i].separation, -1, kEps);  // the thinnest direction, x: 0.5 + 0.5
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(h.c[i].position[k]));
  }
  // Same orientation, offset along x only: face contacts, s = 1 - 1.
  b.move((MeReal)1.99, 1, 1);
  Hit p(b.model, a.model);
  ASSERT_EQ(p.count(), 4);
  EXPECT_NEAR(p.c[0].separation, -0.01, kEps);
  EXPECT_NEAR(p.c[0].normal[0], 1, kEps);
}

// Two unit cubes stacked 1 mm into each other, the upper turned by every
// yaw from 0 to 45 degrees (pile1000's columns): face contacts on the
// common face (3 or 4 of them, normal along z, separation = the overlap),
// never a single edge-edge contact.
TEST(McdBoxBox, StackedCubesAtEveryYawGiveFaceContacts) {
  Framework fw;
  McdGeometryID g = McdBoxCreate(fw, 1, 1, 1);
  Placed low(g, 0, 0, 0);
  const double overlap = 1e-3;
  for (int deg = 0; deg <= 45; ++deg) {
    Placed up(g, 0, 0, (MeReal)(1 - overlap), {0, 0, 1}, (MeReal)(deg * ME_PI / 180));
    for (const bool upFirst : {true, false}) {
      Hit h = upFirst ? Hit(up.model, low.model) : Hit(low.model, up.model);
      const double sign = upFirst ? 1 : -1;
      ASSERT_GE(h.count(), 3) << deg << " degrees";
      EXPECT_LE(h.count(), 4) << deg << " degrees";
      for (int i = 0; i < h.count(); ++i) {
        const McdContact &c = h.c[i];
        EXPECT_NEAR(sign * c.normal[2], 1, 1e-3) << deg << " degrees";
        EXPECT_NEAR(c.separation, -overlap, 1e-5) << deg << " degrees";
        EXPECT_NEAR(c.position[2], 0.5 - overlap / 2, 1e-5) << deg << " degrees";
        // On both squares' common area.
        const double x = c.position[0], y = c.position[1], t = deg * ME_PI / 180;
        EXPECT_LE(std::fmax(std::fabs(x), std::fabs(y)), 0.5 + 1e-5);
        EXPECT_LE(
            std::fmax(std::fabs(x * std::cos(t) + y * std::sin(t)), std::fabs(-x * std::sin(t) + y * std::cos(t))),
            0.5 + 1e-5);
        // One side is the reference face (dims 2), never edge on edge (1, 1).
        EXPECT_TRUE((c.dims & 0xFF) == 2 || ((c.dims >> 8) & 0xFF) == 2) << deg << " degrees";
      }
      // Spread: the kept points enclose at least half the common area (the
      // octagon's area is at least 0.828 of the unit square's).
      double area = 0;
      std::vector<std::pair<double, double>> p;
      for (int i = 0; i < h.count(); ++i) p.push_back({h.c[i].position[0], h.c[i].position[1]});
      std::sort(p.begin(), p.end(),
                [](auto a, auto b) { return std::atan2(a.second, a.first) < std::atan2(b.second, b.first); });
      for (std::size_t i = 0; i < p.size(); ++i) {
        const auto &a = p[i], &b = p[(i + 1) % p.size()];
        area += 0.5 * (a.first * b.second - a.second * b.first);
      }
      EXPECT_GT(area, 0.5) << deg << " degrees";
    }
  }
}

// The same stacks with the upper cube also tilted by 0.02 degrees about x
// and y (0.35 mm across the face, less than the overlap): still 3-4 face
// contacts with the normal of one of the two faces.
TEST(McdBoxBox, SlightlyTiltedStacksKeepFaceContacts) {
  Framework fw;
  McdGeometryID g = McdBoxCreate(fw, 1, 1, 1);
  Placed low(g, 0, 0, 0);
  const double overlap = 1e-3, tilt = 0.02 * ME_PI / 180;
  for (int deg = 0; deg <= 45; ++deg) {
    Placed up(g, 0, 0, (MeReal)(1 - overlap));
    MeMatrix3 yaw, tx, ty, a, r;
    const MeVector3 ez = {0, 0, 1}, ex = {1, 0, 0}, ey = {0, 1, 0};
    MeMatrix3FromAxisAngle(yaw, ez, (MeReal)(deg * ME_PI / 180));
    MeMatrix3FromAxisAngle(tx, ex, (MeReal)tilt);
    MeMatrix3FromAxisAngle(ty, ey, (MeReal)tilt);
    MeMatrix3Multiply(a, yaw, tx);
    MeMatrix3Multiply(r, a, ty);
    MeMatrix4TMSetRotation(up.tm.m, r);
    McdModelUpdate(up.model);
    Hit h(up.model, low.model);
    ASSERT_GE(h.count(), 3) << deg << " degrees";
    EXPECT_LE(h.count(), 4) << deg << " degrees";
    for (int i = 0; i < h.count(); ++i) {
      const McdContact &c = h.c[i];
      const bool lowFace = std::fabs(c.normal[2] - 1) < 1e-6;
      const bool upFace =
          std::fabs(c.normal[0] + r[2][0]) < 1e-6 && std::fabs(c.normal[1] + r[2][1]) < 1e-6;  // up's -z axis, negated
      EXPECT_TRUE(lowFace || upFace) << deg << " degrees";
      EXPECT_NEAR(c.normal[2], 1, 1e-3) << deg << " degrees";
      EXPECT_LE(c.separation, 0) << deg << " degrees";
      EXPECT_GE(c.separation, -overlap - 0.5 * std::sqrt(2.0) * 2 * tilt) << deg << " degrees";
    }
  }
}

}  // namespace
