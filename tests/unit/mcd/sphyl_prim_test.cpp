// sphyl_prim_test.cpp: sphyl against sphyl, box and plane, and cylinder
// against plane, on hand-computed poses: crossing, parallel (2 contacts),
// collinear, lying flat (2), standing (1 or 8 around the rim), tilted, edge,
// deep, separated, coincident; both argument orders.
#include <algorithm>

#include "nearfield_test_support.h"

using namespace mcd_test;
using namespace mcd_test::prim;

namespace {

const double kEps = 4e-6;
const std::array<MeReal, 3> kX = {1, 0, 0}, kY = {0, 1, 0};
const MeReal kQuarter = (MeReal)(ME_PI / 2);

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

void expectAllNormals(const Hit &h, double nx, double ny, double nz) {
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(h.c[i].normal[0], nx, kEps);
    EXPECT_NEAR(h.c[i].normal[1], ny, kEps);
    EXPECT_NEAR(h.c[i].normal[2], nz, kEps);
  }
}

TEST(McdSphylSphyl, CrossingParallelCollinearAndCoincident) {
  Framework fw;
  McdGeometryID g = McdSphylCreate(fw, (MeReal)0.5, 2);  // core [-1, 1] along z
  Placed a(g, 0, 0, 0);
  {  // b along x, 0.9 away in y: one contact midway, normal -y (b towards a)
    Placed b(g, 0, (MeReal)0.9, 0, kY, kQuarter);
    Hit h(a.model, b.model);
    ASSERT_EQ(h.count(), 1);
    EXPECT_NEAR(h.c[0].separation, -0.1, kEps);
    EXPECT_NEAR(h.c[0].position[1], 0.45, kEps);
    expectAllNormals(h, 0, -1, 0);
    expectMirrored(a.model, b.model);
  }
  {  // parallel, overlapping along z in [-0.5, 1]: two contacts at its ends
    Placed b(g, (MeReal)0.9, 0, (MeReal)0.5);
    Hit h(a.model, b.model);
    ASSERT_EQ(h.count(), 2);
    expectAllNormals(h, -1, 0, 0);
    const double z0 = std::fmin(h.c[0].position[2], h.c[1].position[2]);
    const double z1 = std::fmax(h.c[0].position[2], h.c[1].position[2]);
    EXPECT_NEAR(z0, -0.5, kEps);
    EXPECT_NEAR(z1, 1, kEps);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(h.c[i].separation, -0.1, kEps);
      EXPECT_NEAR(h.c[i].position[0], 0.45, kEps);
    }
    expectMirrored(a.model, b.model);
  }
  {  // collinear end to end: one contact at the caps
    Placed b(g, 0, 0, (MeReal)2.9);
    Hit h(a.model, b.model);
    ASSERT_EQ(h.count(), 1);
    EXPECT_NEAR(h.c[0].separation, -0.1, kEps);
    EXPECT_NEAR(h.c[0].position[2], 1.45, kEps);
    expectAllNormals(h, 0, 0, -1);
    b.move(0, 0, (MeReal)3.01);
    EXPECT_EQ(Hit(a.model, b.model).touch, 0);
  }
  {  // crossing cores (d = 0): normal a x b, s = -1
    Placed b(g, 0, 0, 0, kY, kQuarter);
    Hit h(a.model, b.model);
    ASSERT_EQ(h.count(), 1);
    EXPECT_NEAR(h.c[0].separation, -1, kEps);
    EXPECT_NEAR(std::fabs(h.c[0].normal[1]), 1, kEps);
  }
  {  // coincident: parallel and on one line; finite, unit normals
    Placed b(g, 0, 0, 0);
    Hit h(a.model, b.model);
    ASSERT_EQ(h.count(), 2);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(MeVector3Magnitude(h.c[i].normal), 1, kEps);
      EXPECT_NEAR(h.c[i].separation, -1, kEps);
    }
  }
  {  // separated sideways
    Placed b(g, (MeReal)1.01, 0, 0);
    EXPECT_EQ(Hit(a.model, b.model).touch, 0);
  }
}

TEST(McdSphylPlane, FlatStandingTiltedAndDeep) {
  Framework fw;
  Placed ground(McdPlaneCreate(fw), 0, 0, 0);
  McdGeometryID g = McdSphylCreate(fw, (MeReal)0.5, 2);
  Placed s(g, 3, 4, (MeReal)0.49, kY, kQuarter);  // lying along x, 0.01 deep
  Hit h(s.model, ground.model);
  ASSERT_EQ(h.count(), 2);
  expectAllNormals(h, 0, 0, 1);
  const double x0 = std::fmin(h.c[0].position[0], h.c[1].position[0]);
  const double x1 = std::fmax(h.c[0].position[0], h.c[1].position[0]);
  EXPECT_NEAR(x0, 2, kEps);
  EXPECT_NEAR(x1, 4, kEps);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(h.c[i].separation, -0.01, kEps);
    EXPECT_NEAR(h.c[i].position[1], 4, kEps);
    EXPECT_NEAR(h.c[i].position[2], -0.005, kEps);
  }
  expectMirrored(s.model, ground.model);
  // Standing: one contact under the lower end.
  s.turn(kY, 0);
  s.move(0, 0, (MeReal)1.49);
  Hit st(s.model, ground.model);
  ASSERT_EQ(st.count(), 1);
  EXPECT_NEAR(st.c[0].separation, -0.01, kEps);
  EXPECT_NEAR(st.c[0].position[2], -0.005, kEps);
  // Tilted 0.5 rad: the lower end only, height 0.8 - cos(0.5) - 0.5 below.
  s.turn(kY, (MeReal)0.5);
  s.move(0, 0, (MeReal)0.8);
  Hit t(s.model, ground.model), one(s.model, ground.model, 1);
  ASSERT_EQ(t.count(), 1);
  EXPECT_NEAR(t.c[0].separation, 0.8 - std::cos(0.5) - 0.5, kEps);
  // Sunk: both ends, the deeper first; a buffer of 1 keeps it.
  s.move(0, 0, (MeReal)-0.5);  // ends at -0.5 -+ cos 0.5
  Hit both(s.model, ground.model), first(s.model, ground.model, 1);
  ASSERT_EQ(both.count(), 2);
  EXPECT_LT(both.c[0].separation, both.c[1].separation);
  ASSERT_EQ(first.count(), 1);
  EXPECT_EQ(first.c[0].separation, both.c[0].separation);
  s.move(0, 0, (MeReal)1.6);  // clear
  EXPECT_EQ(Hit(s.model, ground.model).touch, 0);
}

TEST(McdSphylBox, FlatOnAFaceOverhangingStandingEdgeDeepAndSeparated) {
  Framework fw;
  Placed box(McdBoxCreate(fw, 4, 4, 2), 0, 0, 0);  // top face z = 1, |x|, |y| <= 2
  McdGeometryID g = McdSphylCreate(fw, (MeReal)0.5, 2);
  Placed s(g, 0, (MeReal)0.5, (MeReal)1.49, kY, kQuarter);  // along x, 0.01 deep
  Hit h(s.model, box.model);
  ASSERT_EQ(h.count(), 2);
  expectAllNormals(h, 0, 0, 1);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(std::fabs(h.c[i].position[0]), 1, kEps);
    EXPECT_NEAR(h.c[i].position[1], 0.5, kEps);
    EXPECT_NEAR(h.c[i].position[2], 0.995, kEps);
    EXPECT_NEAR(h.c[i].separation, -0.01, kEps);
  }
  expectMirrored(s.model, box.model);
  // Overhanging the x = 2 edge: clipped to x in [0.5, 2].
  s.move((MeReal)1.5, 0, (MeReal)1.49);
  Hit o(s.model, box.model);
  ASSERT_EQ(o.count(), 2);
  EXPECT_NEAR(std::fmin(o.c[0].position[0], o.c[1].position[0]), 0.5, kEps);
  EXPECT_NEAR(std::fmax(o.c[0].position[0], o.c[1].position[0]), 2, kEps);
  // Standing on its end: one contact.
  s.turn(kY, 0);
  s.move((MeReal)0.3, 0, (MeReal)2.49);
  Hit st(s.model, box.model);
  ASSERT_EQ(st.count(), 1);
  EXPECT_NEAR(st.c[0].separation, -0.01, kEps);
  EXPECT_NEAR(st.c[0].position[0], 0.3, kEps);
  EXPECT_NEAR(st.c[0].position[2], 0.995, kEps);
  // Along y past the edge x = 2, z = 1: d = (0.3, 0, 0.4), s = 0.5 - 0.5 - ...
  Placed e(McdSphylCreate(fw, (MeReal)0.6, 1), (MeReal)2.3, 0, (MeReal)1.4, kX, kQuarter);
  Hit eh(e.model, box.model);
  ASSERT_EQ(eh.count(), 1);
  EXPECT_NEAR(eh.c[0].separation, -0.1, kEps);
  EXPECT_NEAR(eh.c[0].normal[0], 0.6, kEps);
  EXPECT_NEAR(eh.c[0].normal[2], 0.8, kEps);
  EXPECT_NEAR(eh.c[0].position[0], 1.97, kEps);
  EXPECT_NEAR(eh.c[0].position[2], 0.96, kEps);
  expectMirrored(e.model, box.model);
  // Core inside the box, along x at z = 0.8: least overlap up, s = -0.2 - 0.5.
  s.turn(kY, kQuarter);
  s.move(0, 0, (MeReal)0.8);
  Hit d(s.model, box.model);
  ASSERT_EQ(d.count(), 2);
  expectAllNormals(d, 0, 0, 1);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(d.c[i].separation, -0.7, kEps);
  // Separated above, and beside.
  s.move(0, 0, (MeReal)1.51);
  EXPECT_EQ(Hit(s.model, box.model).touch, 0);
  s.move((MeReal)3.6, 0, 0);
  EXPECT_EQ(Hit(box.model, s.model).touch, 0);
}

TEST(McdCylinderPlane, StandingLyingTiltedAndSeparated) {
  Framework fw;
  Placed ground(McdPlaneCreate(fw), 0, 0, 0);
  Placed c(McdCylinderCreate(fw, 1, 2), 1, 2, (MeReal)0.99);  // on its end, 0.01 deep
  Hit h(c.model, ground.model);
  ASSERT_GE(h.count(), 4);
  EXPECT_EQ(h.count(), 8);
  expectAllNormals(h, 0, 0, 1);
  for (int i = 0; i < h.count(); ++i) {
    EXPECT_NEAR(std::hypot(h.c[i].position[0] - 1, h.c[i].position[1] - 2), 1, kEps);
    EXPECT_NEAR(h.c[i].position[2], -0.005, kEps);
    EXPECT_NEAR(h.c[i].separation, -0.01, kEps);
    EXPECT_EQ(h.c[i].dims, (MeI16)(1 | (2 << 8)));
  }
  expectMirrored(c.model, ground.model);
  EXPECT_EQ(Hit(c.model, ground.model, 4).count(), 4);
  // Lying on its side along x: one contact under each rim.
  c.turn(kY, kQuarter);
  Hit l(c.model, ground.model);
  ASSERT_EQ(l.count(), 2);
  EXPECT_NEAR(std::fmin(l.c[0].position[0], l.c[1].position[0]), 0, kEps);
  EXPECT_NEAR(std::fmax(l.c[0].position[0], l.c[1].position[0]), 2, kEps);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(l.c[i].position[1], 2, kEps);
    EXPECT_NEAR(l.c[i].separation, -0.01, kEps);
  }
  // Tilted 0.3 rad: the lowest rim point, cos 0.3 + sin 0.3 below the centre.
  const double lowest = std::cos(0.3) + std::sin(0.3);
  c.turn(kX, (MeReal)0.3);
  c.move(0, 0, (MeReal)(lowest - 0.02));
  Hit t(c.model, ground.model);
  ASSERT_EQ(t.count(), 1);
  EXPECT_NEAR(t.c[0].separation, -0.02, kEps);
  EXPECT_NEAR(t.c[0].position[2], -0.01, kEps);
  c.move(0, 0, (MeReal)(lowest + 0.001));
  EXPECT_EQ(Hit(c.model, ground.model).touch, 0);
  EXPECT_EQ(Hit(ground.model, c.model).touch, 0);
}

}  // namespace
