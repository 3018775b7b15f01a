// convex_nearfield_test.cpp: the general convex pairs (libccd + manifold):
// a convex cube against a box in several poses, the guide's pyramid on a
// plane and on a box, cylinder-cylinder and box-cylinder by hand, both
// argument orders, random poses and degenerate cases.
#include "nearfield_support.h"

#include <random>

using namespace mcd_test;

namespace {

constexpr double kEps = 2e-4;  // single precision inputs

McdGeometryID Cube(McdFrameworkID fw, MeReal h) {
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i) MeVector3Set(c[i], (i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
  return McdConvexMeshCreateHull(fw, c, 8, 0);
}

TEST(McdConvexNearfield, CubeHullOnBoxLikeABox) {
  Framework fw;
  Placed box(McdBoxCreate(fw, 2, 2, 2), 0, 0, 0);
  Placed hull(Cube(fw, 1), 0, 0, (MeReal)1.9);  // 0.1 into the box's top face
  Hit h(hull.model, box.model);
  ASSERT_EQ(h.touch, 1);
  EXPECT_EQ(h.count(), 4);
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(h.contacts[i].separation, -0.1, kEps);
    EXPECT_NEAR(h.contacts[i].normal[2], 1, kEps);
    EXPECT_NEAR(std::fabs(h.contacts[i].position[0]), 1, kEps);
    EXPECT_NEAR(std::fabs(h.contacts[i].position[1]), 1, kEps);
    EXPECT_NEAR(h.contacts[i].position[2], 0.95, kEps);  // midway
  }
  // Side by side along x, 0.05 deep.
  hull.moveTo((MeReal)1.95, (MeReal)0.3, 0);
  Hit side(hull.model, box.model);
  ASSERT_EQ(side.touch, 1);
  EXPECT_GE(side.count(), 4);
  EXPECT_NEAR(side.deepest(), -0.05, kEps);
  EXPECT_NEAR(side.r.normal[0], 1, kEps);
  // Turned 30 degrees about z on top: the overlap is an octagon.
  hull.moveTo(0, 0, (MeReal)1.98);
  hull.rotate(0, 0, 1, (MeReal)(ME_PI / 6));
  Hit turned(hull.model, box.model);
  ASSERT_EQ(turned.touch, 1);
  EXPECT_GE(turned.count(), 4);
  EXPECT_NEAR(turned.deepest(), -0.02, kEps);
  EXPECT_NEAR(turned.r.normal[2], 1, kEps);
  // Both turned by the same rotation and stacked along their own z.
  const MeVector3 axis = {1, 2, 3};
  box.rotate(1, 2, 3, (MeReal)0.7);
  hull.rotate(1, 2, 3, (MeReal)0.7);
  const MeReal *z = box.tm->m[2];
  hull.moveTo((MeReal)1.97 * z[0], (MeReal)1.97 * z[1], (MeReal)1.97 * z[2]);
  Hit tilted(hull.model, box.model);
  ASSERT_EQ(tilted.touch, 1);
  EXPECT_EQ(tilted.count(), 4);
  EXPECT_NEAR(tilted.deepest(), -0.03, kEps);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(tilted.r.normal[k], z[k], kEps);
  (void)axis;
  // Apart by 0.01: nothing.
  hull.moveTo((MeReal)2.01 * z[0], (MeReal)2.01 * z[1], (MeReal)2.01 * z[2]);
  EXPECT_EQ(Hit(hull.model, box.model).touch, 0);
  expectMirrored(hull.model, box.model, kEps);
}

TEST(McdConvexNearfield, GuidePyramidRestsOnItsBaseCorners) {
  Framework fw;
  MeVector3 pyramid[] = {{0, 2, 0}, {-3, -1, -3}, {3, -1, -3}, {-3, -1, 3}, {3, -1, 3}};
  McdGeometryID g = McdConvexMeshCreateHull(fw, pyramid, 5, 0);
  Placed ground(McdPlaneCreate(fw), 0, 0, 0);
  ground.rotate(1, 0, 0, (MeReal)(-ME_PI / 2));  // plane normal +y
  ASSERT_NEAR(ground.tm->m[2][1], 1, 1e-6);
  Placed p(g, 5, (MeReal)0.99, 7);  // base at y = -0.01
  Hit h(p.model, ground.model);
  ASSERT_EQ(h.touch, 1);
  ASSERT_EQ(h.count(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(h.contacts[i].separation, -0.01, kEps);
    EXPECT_NEAR(h.contacts[i].normal[1], 1, kEps);
    EXPECT_NEAR(std::fabs(h.contacts[i].position[0] - 5), 3, kEps);
    EXPECT_NEAR(std::fabs(h.contacts[i].position[2] - 7), 3, kEps);
  }
  expectMirrored(p.model, ground.model, kEps);
  // On a box (the convex path): the same four corners.
  Placed slab(McdBoxCreate(fw, 20, 1, 20), 5, (MeReal)-0.5, 7);
  Hit b(p.model, slab.model);
  ASSERT_EQ(b.touch, 1);
  EXPECT_EQ(b.count(), 4);
  EXPECT_NEAR(b.deepest(), -0.01, kEps);
  EXPECT_NEAR(b.r.normal[1], 1, kEps);
  // Upside down on the apex: one contact.
  p.rotate(1, 0, 0, (MeReal)ME_PI);
  p.moveTo(5, (MeReal)1.98, 7);  // apex at y = -0.02
  Hit apex(p.model, ground.model);
  ASSERT_EQ(apex.count(), 1);
  EXPECT_NEAR(apex.contacts[0].separation, -0.02, kEps);
}

TEST(McdConvexNearfield, CylinderCylinderByHand) {
  Framework fw;
  McdGeometryID cyl = McdCylinderCreate(fw, 1, 2);
  Placed a(cyl, 0, 0, 0), b(cyl, (MeReal)0.5, 0, (MeReal)1.9);  // cap on cap, 0.1 deep
  Hit h(b.model, a.model);
  ASSERT_EQ(h.touch, 1);
  EXPECT_GE(h.count(), 4);
  EXPECT_NEAR(h.deepest(), -0.1, kEps);
  EXPECT_NEAR(h.r.normal[2], 1, kEps);
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(h.contacts[i].position[2], 0.95, kEps);
    const double x = h.contacts[i].position[0], y = h.contacts[i].position[1];
    EXPECT_LE(std::hypot(x, y), 1 + kEps);  // inside both caps
    EXPECT_LE(std::hypot(x - 0.5, y), 1 + kEps);
  }
  expectMirrored(a.model, b.model, kEps);
  // Side by side, parallel axes 1.8 apart: depth 0.2 along x, a line contact.
  b.moveTo((MeReal)1.8, 0, 0);
  Hit s(b.model, a.model);
  ASSERT_EQ(s.touch, 1);
  EXPECT_EQ(s.count(), 2);
  EXPECT_NEAR(s.deepest(), -0.2, 1e-3);
  EXPECT_NEAR(s.r.normal[0], 1, 1e-3);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(std::fabs(s.contacts[i].position[2]), 1, 1e-3);
  // Crossed: b lying along y on top of a's cap, 0.05 deep: a line across the cap.
  b.rotate(1, 0, 0, (MeReal)(ME_PI / 2));
  b.moveTo(0, 0, (MeReal)1.95);
  Hit c(b.model, a.model);
  ASSERT_EQ(c.touch, 1);
  EXPECT_GE(c.count(), 2);
  EXPECT_NEAR(c.deepest(), -0.05, 1e-3);
  EXPECT_NEAR(c.r.normal[2], 1, 1e-3);
  // Apart.
  b.moveTo(0, 0, (MeReal)2.1);
  EXPECT_EQ(Hit(b.model, a.model).touch, 0);
}

TEST(McdConvexNearfield, BoxCylinderByHand) {
  Framework fw;
  Placed box(McdBoxCreate(fw, 4, 4, 1), 0, 0, 0);
  Placed cyl(McdCylinderCreate(fw, (MeReal)0.5, 2), 1, 0, (MeReal)1.45);  // standing, 0.05 deep
  Hit h(cyl.model, box.model);
  ASSERT_EQ(h.touch, 1);
  EXPECT_EQ(h.count(), 4);  // four of the cap's 8 rim samples, spread round it
  EXPECT_NEAR(h.deepest(), -0.05, kEps);
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(h.contacts[i].normal[2], 1, kEps);
    EXPECT_NEAR(h.contacts[i].separation, -0.05, kEps);
    EXPECT_NEAR(std::hypot(h.contacts[i].position[0] - 1, h.contacts[i].position[1]), 0.5, kEps);
  }
  expectMirrored(cyl.model, box.model, kEps);
  // Lying along x on the box: a line contact of the side, 0.1 deep.
  cyl.rotate(0, 1, 0, (MeReal)(ME_PI / 2));
  cyl.moveTo(0, 0, (MeReal)0.9);
  Hit l(cyl.model, box.model);
  ASSERT_EQ(l.touch, 1);
  EXPECT_EQ(l.count(), 2);
  EXPECT_NEAR(l.deepest(), -0.1, kEps);
  EXPECT_NEAR(l.r.normal[2], 1, kEps);
  EXPECT_NEAR(std::fabs(l.contacts[0].position[0]), 1, kEps);
  // Against the box's side face.
  cyl.moveTo((MeReal)2.45, 0, 0);
  cyl.rotate(0, 0, 1, 0);
  Hit s(cyl.model, box.model);
  ASSERT_EQ(s.touch, 1);
  EXPECT_NEAR(s.deepest(), -0.05, kEps);
  EXPECT_NEAR(s.r.normal[0], 1, kEps);
  EXPECT_EQ(s.count(), 2);  // the side line clipped to the face's height
}

TEST(McdConvexNearfield, SphereSphylAgainstHull) {
  Framework fw;
  Placed hull(Cube(fw, 1), 0, 0, 0);
  Placed ball(McdSphereCreate(fw, (MeReal)0.5), 0, 0, (MeReal)1.4);
  Hit h(ball.model, hull.model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.contacts[0].separation, -0.1, kEps);
  EXPECT_NEAR(h.contacts[0].normal[2], 1, kEps);
  EXPECT_NEAR(h.contacts[0].position[2], 0.95, kEps);
  expectMirrored(ball.model, hull.model, kEps);
  // On an edge: the hull turned 45 degrees about x, its top edge along x at
  // z = sqrt 2; the normal runs from the edge's closest point to the centre.
  hull.rotate(1, 0, 0, (MeReal)(ME_PI / 4));
  const double top = std::sqrt(2.0);
  ball.moveTo((MeReal)0.3, (MeReal)0.1, (MeReal)(top + 0.4));
  Hit e(ball.model, hull.model);
  ASSERT_EQ(e.count(), 1);
  const double dist = std::hypot(0.1, 0.4);
  EXPECT_NEAR(e.contacts[0].separation, dist - 0.5, kEps);
  EXPECT_NEAR(e.contacts[0].normal[1], 0.1 / dist, kEps);
  EXPECT_NEAR(e.contacts[0].normal[2], 0.4 / dist, kEps);
  EXPECT_NEAR(e.contacts[0].position[0], 0.3, kEps);
  hull.rotate(1, 0, 0, 0);
  Placed caps(McdSphylCreate(fw, (MeReal)0.25, 1), 0, 0, (MeReal)1.2);
  caps.rotate(0, 1, 0, (MeReal)(ME_PI / 2));  // lying along x
  Hit s(caps.model, hull.model);
  ASSERT_EQ(s.count(), 2);
  EXPECT_NEAR(s.deepest(), -0.05, kEps);
  EXPECT_NEAR(s.r.normal[2], 1, kEps);
  // Cylinder-sphyl: the sphyl lying on a standing cylinder's cap.
  Placed cyl(McdCylinderCreate(fw, 2, 1), 0, 0, 0);
  caps.moveTo(0, 0, (MeReal)0.7);
  Hit cs(cyl.model, caps.model);
  ASSERT_EQ(cs.touch, 1);
  EXPECT_EQ(cs.count(), 2);
  EXPECT_NEAR(cs.deepest(), -0.05, kEps);
  EXPECT_NEAR(cs.r.normal[2], -1, kEps);  // from the sphyl (model2) down to the cylinder
}

TEST(McdConvexNearfield, RandomPosesSaneAndMirrored) {
  Framework fw(64, 64);
  MeVector3 pts[12];
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto &p : pts) MeVector3Set(p, (MeReal)u(rng), (MeReal)u(rng), (MeReal)u(rng));
  McdGeometryID geoms[] = {Cube(fw, (MeReal)0.6),
                           McdConvexMeshCreateHull(fw, pts, 12, 0),
                           McdBoxCreate(fw, 1, (MeReal)1.5, (MeReal)0.7),
                           McdCylinderCreate(fw, (MeReal)0.5, (MeReal)1.2),
                           McdSphylCreate(fw, (MeReal)0.3, 1),
                           McdSphereCreate(fw, (MeReal)0.6)};
  ASSERT_NE(geoms[1], nullptr);
  int touching = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int i = trial % 2, j = (trial / 2) % 6;  // a hull against everything
    Placed a(geoms[i], 0, 0, 0), b(geoms[j], (MeReal)u(rng), (MeReal)u(rng), (MeReal)u(rng));
    a.rotate((MeReal)u(rng), (MeReal)u(rng), (MeReal)u(rng) + 2, (MeReal)(3 * u(rng)));
    b.rotate((MeReal)u(rng) + 2, (MeReal)u(rng), (MeReal)u(rng), (MeReal)(3 * u(rng)));
    Hit h(a.model, b.model);
    expectSane(h);
    touching += h.touch;
    if (h.touch) {
      EXPECT_GE(h.count(), 1);
      EXPECT_LE(h.deepest(), 1e-4);
    }
    expectMirrored(a.model, b.model, 1e-3);
  }
  EXPECT_GT(touching, 100);
}

TEST(McdConvexNearfield, DegenerateTouchingAndDeepNoNaN) {
  Framework fw;
  McdGeometryID cube = Cube(fw, 1);
  Placed a(cube, 0, 0, 0), b(cube, 0, 0, 0);  // coincident
  Hit same(a.model, b.model);
  ASSERT_EQ(same.touch, 1);
  expectSane(same);
  EXPECT_NEAR(same.deepest(), -2, 1e-3);
  b.moveTo(0, 0, 2);  // exactly touching
  Hit touch(a.model, b.model);
  EXPECT_EQ(touch.touch, 1);
  expectSane(touch);
  EXPECT_NEAR(touch.deepest(), 0, kEps);
  McdGeometryID cyl = McdCylinderCreate(fw, 1, 2);
  Placed c(cyl, 0, 0, 0), d(cyl, 0, 0, 0);
  Hit cc(c.model, d.model);
  ASSERT_EQ(cc.touch, 1);
  expectSane(cc);
  d.moveTo((MeReal)1e-7, 0, (MeReal)1.9999999);
  expectSane(Hit(c.model, d.model));
  // No contact buffer room: the count stays within contactMaxCount.
  b.moveTo(0, 0, (MeReal)1.9);
  Hit one(a.model, b.model, 1);
  EXPECT_EQ(one.count(), 1);
}

}  // namespace
