// sphere_prim_test.cpp: sphere against box, cylinder and sphyl on hand-
// computed poses (face, edge/rim, vertex, deep, centre inside, coincident
// centres, just touching, separated), both argument orders.
#include "nearfield_test_support.h"

using namespace mcd_test;
using namespace mcd_test::prim;

namespace {

const double kEps = 2e-6;

void expectContact(const Hit &h, double x, double y, double z, double nx, double ny, double nz, double sep, int dims) {
  ASSERT_EQ(h.touch, 1);
  ASSERT_EQ(h.count(), 1);
  const McdContact &c = h.c[0];
  EXPECT_NEAR(c.position[0], x, kEps);
  EXPECT_NEAR(c.position[1], y, kEps);
  EXPECT_NEAR(c.position[2], z, kEps);
  EXPECT_NEAR(c.normal[0], nx, kEps);
  EXPECT_NEAR(c.normal[1], ny, kEps);
  EXPECT_NEAR(c.normal[2], nz, kEps);
  EXPECT_NEAR(c.separation, sep, kEps);
  EXPECT_EQ(c.dims, (MeI16)dims);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(h.r.normal[k], c.normal[k]);
}

// The reversed query mirrors the forward one exactly.
void expectMirror(McdModelID a, McdModelID b) {
  Hit f(a, b), r(b, a);
  ASSERT_EQ(f.touch, r.touch);
  ASSERT_EQ(f.count(), r.count());
  for (int i = 0; i < f.count(); ++i) {
    EXPECT_EQ(f.c[i].separation, r.c[i].separation);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(f.c[i].position[k], r.c[i].position[k]);
      EXPECT_EQ(f.c[i].normal[k], -r.c[i].normal[k]);
    }
    EXPECT_EQ(f.c[i].dims & 0xFF, (r.c[i].dims >> 8) & 0xFF);
  }
}

TEST(McdSphereBox, FaceEdgeVertexDeepAndSeparated) {
  Framework fw;
  Placed box(McdBoxCreate(fw, 2, 4, 6), 0, 0, 0);  // half extents 1, 2, 3
  McdGeometryID r5 = McdSphereCreate(fw, (MeReal)0.5), r6 = McdSphereCreate(fw, (MeReal)0.6);
  {  // face x = 1: 0.1 deep, contact midway between x = 0.9 and 1
    Placed s(r5, (MeReal)1.4, 0, 0);
    expectContact(Hit(s.model, box.model), 0.95, 0, 0, 1, 0, 0, -0.1, 2 | (2 << 8));
    expectMirror(s.model, box.model);
  }
  {  // edge (x = 1, y = 2): d = (0.3, 0.4, 0), |d| = 0.5
    Placed s(r6, (MeReal)1.3, (MeReal)2.4, 0);
    expectContact(Hit(s.model, box.model), 0.97, 1.96, 0, 0.6, 0.8, 0, -0.1, 2 | (1 << 8));
    expectMirror(s.model, box.model);
  }
  {  // vertex (1, 2, 3): d = (0.2, 0.2, 0.1), |d| = 0.3
    Placed s(r5, (MeReal)1.2, (MeReal)2.2, (MeReal)3.1);
    const double n[3] = {2.0 / 3, 2.0 / 3, 1.0 / 3};
    // midway between c - 0.5 n and the vertex
    expectContact(Hit(s.model, box.model), (1.2 - 0.5 * n[0] + 1) / 2, (2.2 - 0.5 * n[1] + 2) / 2,
                  (3.1 - 0.5 * n[2] + 3) / 2, n[0], n[1], n[2], -0.2, 2 | (0 << 8));
  }
  {  // centre inside, nearest face x = 1 (gap 0.3): s = -0.3 - 0.5
    Placed s(r5, (MeReal)0.7, 0, (MeReal)0.5);
    expectContact(Hit(s.model, box.model), 0.6, 0, 0.5, 1, 0, 0, -0.8, 2 | (2 << 8));
    expectMirror(s.model, box.model);
  }
  {  // centre inside near face -y: midway between y = -1.4 and -2
    Placed s(r5, 0, (MeReal)-1.9, 0);
    expectContact(Hit(s.model, box.model), 0, -1.7, 0, 0, -1, 0, -0.6, 2 | (2 << 8));
  }
  {  // coincident centres: the nearest face (x, gap 1), no NaN
    Placed s(r5, 0, 0, 0);
    expectContact(Hit(s.model, box.model), 0.25, 0, 0, 1, 0, 0, -1.5, 2 | (2 << 8));
  }
  {  // just touching within tolerance, and just apart
    const MeReal tol = McdFrameworkGetContactTolerance(fw);
    Placed s(r5, (MeReal)1.5 + tol / 2, 0, 0);
    EXPECT_EQ(Hit(s.model, box.model).touch, 1);
    s.move((MeReal)1.501, 0, 0);
    EXPECT_EQ(Hit(s.model, box.model).touch, 0);
    EXPECT_EQ(Hit(box.model, s.model).touch, 0);
    s.move((MeReal)1.3, (MeReal)2.3, 0);  // near the edge: |d| = 0.424 < 0.5
    EXPECT_EQ(Hit(s.model, box.model).touch, 1);
    s.move((MeReal)1.4, (MeReal)2.4, 0);  // |d| = 0.566
    EXPECT_EQ(Hit(s.model, box.model).touch, 0);
  }
}

TEST(McdSphereBox, RotatedBox) {
  Framework fw;
  Placed box(McdBoxCreate(fw, 2, 4, 6), 1, 2, 3, {0, 0, 1}, (MeReal)0.7);
  Placed s(McdSphereCreate(fw, (MeReal)0.5), 0, 0, 0);
  // Along the box's y axis (half extent 2), 2.4 from its centre: 0.1 deep.
  const D3 ay = row(box.model, 1);
  s.move((MeReal)(1 + 2.4 * ay[0]), (MeReal)(2 + 2.4 * ay[1]), (MeReal)(3 + 2.4 * ay[2]));
  Hit h(s.model, box.model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.c[0].separation, -0.1, kEps);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(h.c[0].normal[k], ay[k], kEps);
  expectMirror(s.model, box.model);
}

TEST(McdSphereCylinder, SideCapRimDeepAndSeparated) {
  Framework fw;
  Placed cyl(McdCylinderCreate(fw, 1, 2), 0, 0, 0);  // R 1, z in [-1, 1]
  McdGeometryID r5 = McdSphereCreate(fw, (MeReal)0.5), r6 = McdSphereCreate(fw, (MeReal)0.6);
  {  // side
    Placed s(r5, (MeReal)1.4, 0, (MeReal)0.2);
    expectContact(Hit(s.model, cyl.model), 0.95, 0, 0.2, 1, 0, 0, -0.1, 2 | (2 << 8));
    expectMirror(s.model, cyl.model);
  }
  {  // cap
    Placed s(r5, (MeReal)0.3, (MeReal)0.2, (MeReal)1.3);
    expectContact(Hit(s.model, cyl.model), 0.3, 0.2, 0.9, 0, 0, 1, -0.2, 2 | (2 << 8));
  }
  {  // rim (edge): d = (0.3, 0, 0.4) from (1, 0, 1)... in the direction (0.6, 0.8) of x-y
    Placed s(r6, (MeReal)(1.3 * 0.6), (MeReal)(1.3 * 0.8), (MeReal)-1.4);
    const double n[3] = {0.6 * 0.6, 0.6 * 0.8, -0.8};
    expectContact(Hit(s.model, cyl.model), (0.78 - 0.6 * n[0] + 0.6) / 2, (1.04 - 0.6 * n[1] + 0.8) / 2,
                  (-1.4 - 0.6 * n[2] - 1) / 2, n[0], n[1], n[2], -0.1, 2 | (1 << 8));
    expectMirror(s.model, cyl.model);
  }
  {  // centre inside, nearer the side (gap 0.2) than the caps (gap 1)
    Placed s(r5, 0, (MeReal)-0.8, 0);
    expectContact(Hit(s.model, cyl.model), 0, -0.65, 0, 0, -1, 0, -0.7, 2 | (2 << 8));
  }
  {  // centre inside, nearer the bottom cap (gap 0.1)
    Placed s(r5, (MeReal)0.2, 0, (MeReal)-0.9);
    expectContact(Hit(s.model, cyl.model), 0.2, 0, -0.7, 0, 0, -1, -0.6, 2 | (2 << 8));
  }
  {  // coincident centres (rho = 0): finite, unit normal
    Placed s(r5, 0, 0, 0);
    Hit h(s.model, cyl.model);
    ASSERT_EQ(h.count(), 1);
    EXPECT_NEAR(MeVector3Magnitude(h.c[0].normal), 1, kEps);
    EXPECT_NEAR(h.c[0].separation, -1.5, kEps);
  }
  {                                             // separated beyond the rim though inside both slabs' extensions' AABB
    Placed s(r5, (MeReal)1.4, 0, (MeReal)1.4);  // |d| = 0.566
    EXPECT_EQ(Hit(s.model, cyl.model).touch, 0);
    s.move(0, 0, (MeReal)1.51);
    EXPECT_EQ(Hit(cyl.model, s.model).touch, 0);
  }
}

TEST(McdSphereCylinder, TiltedCylinderCap) {
  Framework fw;
  Placed cyl(McdCylinderCreate(fw, 1, 2), 1, 1, 1, {1, 2, 0}, (MeReal)0.9);
  const D3 a = row(cyl.model, 2);
  Placed s(McdSphereCreate(fw, (MeReal)0.5), (MeReal)(1 - 1.3 * a[0]), (MeReal)(1 - 1.3 * a[1]),
           (MeReal)(1 - 1.3 * a[2]));
  Hit h(s.model, cyl.model);
  ASSERT_EQ(h.count(), 1);
  EXPECT_NEAR(h.c[0].separation, -0.2, 4 * kEps);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(h.c[0].normal[k], -a[k], kEps);
}

TEST(McdSphereSphyl, SideEndTouchingInsideAndSeparated) {
  Framework fw;
  Placed cap(McdSphylCreate(fw, (MeReal)0.5, 2), 0, 0, 0);  // core z in [-1, 1]
  McdGeometryID r5 = McdSphereCreate(fw, (MeReal)0.5);
  {  // side
    Placed s(r5, (MeReal)0.9, 0, (MeReal)0.3);
    expectContact(Hit(s.model, cap.model), 0.45, 0, 0.3, 1, 0, 0, -0.1, 2 | (2 << 8));
    expectMirror(s.model, cap.model);
  }
  {  // end
    Placed s(r5, 0, 0, (MeReal)1.9);
    expectContact(Hit(s.model, cap.model), 0, 0, 1.45, 0, 0, 1, -0.1, 2 | (2 << 8));
  }
  {  // beyond the end, obliquely: |d| = |(0.6, 0, 0.8)| = 1 = r1 + r2, just touching
    Placed s(r5, (MeReal)0.6, 0, (MeReal)1.8);
    Hit h(s.model, cap.model);
    ASSERT_EQ(h.count(), 1);
    EXPECT_NEAR(h.c[0].separation, 0, kEps);
    EXPECT_NEAR(h.c[0].normal[0], 0.6, kEps);
    EXPECT_NEAR(h.c[0].normal[2], 0.8, kEps);
    s.move((MeReal)0.6, 0, (MeReal)1.81);
    EXPECT_EQ(Hit(s.model, cap.model).touch, 0);
  }
  {  // centre on the core: normal the sphyl's x axis, s = -1
    Placed s(r5, 0, 0, (MeReal)0.5);
    expectContact(Hit(s.model, cap.model), 0, 0, 0.5, 1, 0, 0, -1, 2 | (2 << 8));
    expectMirror(s.model, cap.model);
  }
  {  // zero-length sphyl: a sphere
    Placed ball(McdSphylCreate(fw, (MeReal)0.5, 0), 0, 0, 0);
    Placed s(r5, 0, (MeReal)0.8, 0);
    expectContact(Hit(s.model, ball.model), 0, 0.4, 0, 0, 1, 0, -0.2, 2 | (2 << 8));
  }
}

}  // namespace
