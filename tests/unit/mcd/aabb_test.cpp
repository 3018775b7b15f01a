// aabb_test.cpp: world AABBs of every geometry, at rest and rotated, cached
// by McdModelUpdate.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

struct Box3 {
  MeVector3 mn, mx;
};

Box3 ModelBox(McdGeometryID g, TM &tm) {
  McdModelID m = McdModelCreate(g);
  McdModelSetTransformPtr(m, tm);
  McdModelUpdate(m);
  Box3 b;
  McdModelGetAABB(m, b.mn, b.mx);
  McdModelDestroy(m);
  return b;
}

void ExpectBox(const Box3 &b, MeReal x0, MeReal y0, MeReal z0, MeReal x1, MeReal y1, MeReal z1, double eps = tol(10)) {
  EXPECT_NEAR(b.mn[0], x0, eps);
  EXPECT_NEAR(b.mn[1], y0, eps);
  EXPECT_NEAR(b.mn[2], z0, eps);
  EXPECT_NEAR(b.mx[0], x1, eps);
  EXPECT_NEAR(b.mx[1], y1, eps);
  EXPECT_NEAR(b.mx[2], z1, eps);
}

const MeVector3 kX = {1, 0, 0}, kY = {0, 1, 0}, kZ = {0, 0, 1};

TEST(McdAabb, SphereIgnoresRotation) {
  Framework fw;
  TM tm(1, 2, 3);
  tm.rotate(kX, (MeReal)0.7);
  ExpectBox(ModelBox(McdSphereCreate(fw, 2), tm), -1, 0, 1, 3, 4, 5);
}

TEST(McdAabb, BoxRotatedAboutZ) {
  Framework fw;
  McdGeometryID box = McdBoxCreate(fw, 2, 1, 3);
  TM tm(10, 0, 0);
  ExpectBox(ModelBox(box, tm), 9, -0.5f, -1.5f, 11, 0.5f, 1.5f);
  tm.rotate(kZ, ME_PI / 2);  // x and y extents swap
  ExpectBox(ModelBox(box, tm), 9.5f, -1, -1.5f, 10.5f, 1, 1.5f, tol(10, 256));
  tm.rotate(kZ, ME_PI / 4);  // half diagonal of the 2 x 1 face: (2 + 1)/(2 sqrt 2)
  const MeReal e = (MeReal)(3 / (2 * std::sqrt(2.0)));
  ExpectBox(ModelBox(box, tm), 10 - e, -e, -1.5f, 10 + e, e, 1.5f, tol(10, 256));
}

TEST(McdAabb, CylinderAndSphylTiltedAboutX) {
  Framework fw;
  TM tm;
  ExpectBox(ModelBox(McdCylinderCreate(fw, 1, 4), tm), -1, -1, -2, 1, 1, 2);
  ExpectBox(ModelBox(McdSphylCreate(fw, 1, 4), tm), -1, -1, -3, 1, 1, 3);
  tm.rotate(kX, ME_PI / 2);  // the axis now lies along -y
  ExpectBox(ModelBox(McdCylinderCreate(fw, 1, 4), tm), -1, -2, -1, 1, 2, 1, tol(10, 256));
  ExpectBox(ModelBox(McdSphylCreate(fw, 1, 4), tm), -1, -3, -1, 1, 3, 1, tol(10, 256));
  tm.rotate(kX, ME_PI / 4);  // axis (0, -s, s) with s = 1/sqrt 2
  const double s = 1 / std::sqrt(2.0);
  const MeReal cy = (MeReal)(2 * s + s);  // |a_y| h/2 + r sqrt(1 - a_y^2)
  ExpectBox(ModelBox(McdCylinderCreate(fw, 1, 4), tm), -1, -cy, -cy, 1, cy, cy, tol(10, 256));
}

TEST(McdAabb, PlaneIsUnboundedExceptBelow) {
  Framework fw;
  TM tm(0, 0, 2);
  Box3 b = ModelBox(McdPlaneCreate(fw), tm);
  EXPECT_EQ(b.mn[0], -MEINFINITY);
  EXPECT_EQ(b.mx[1], MEINFINITY);
  EXPECT_EQ(b.mn[2], -MEINFINITY);
  EXPECT_EQ(b.mx[2], 2);
  tm.rotate(kX, (MeReal)0.3);  // tilted: unbounded everywhere
  b = ModelBox(McdPlaneCreate(fw), tm);
  EXPECT_EQ(b.mx[2], MEINFINITY);
}

TEST(McdAabb, ConvexTriangleListAndAggregate) {
  Framework fw;
  MeVector3 cube[8];
  for (int k = 0; k < 8; ++k) MeVector3Set(cube[k], (k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
  TM tm(0, 0, 5);
  tm.rotate(kY, ME_PI / 4);
  const MeReal r2 = (MeReal)std::sqrt(2.0);
  ExpectBox(ModelBox(McdConvexMeshCreateHull(fw, cube, 8, 0), tm), -r2, -1, 5 - r2, r2, 1, 5 + r2, tol(10, 256));
  ExpectBox(ModelBox(McdConvexMeshCreateHull(fw, cube, 8, (MeReal)0.5), tm), -r2 - 0.5f, -1.5f, 4.5f - r2, r2 + 0.5f,
            1.5f, 5.5f + r2, tol(10, 256));
  // A triangle list's box [0,2]x[0,4]x[-1,1], moved by (1, 1, 1).
  MeVector3 mn = {0, 0, -1}, mx = {2, 4, 1};
  auto cb = [](McdModelPair *, McdUserTriangle *, MeVector3, MeReal, int) -> int { return 0; };
  TM shift(1, 1, 1);
  ExpectBox(ModelBox(McdTriangleListCreate(fw, mn, mx, 8, cb), shift), 1, 1, 0, 3, 5, 2);
  // An aggregate of two spheres at x = +-2: the union.
  static TM left(-2, 0, 0), right(2, 0, 0);
  McdGeometryID agg = McdAggregateCreate(fw, 2);
  McdGeometryID ball = McdSphereCreate(fw, 1);
  McdAggregateAddElement(agg, ball, left);
  McdAggregateAddElement(agg, ball, right);
  TM up(0, 0, 1);
  up.rotate(kZ, ME_PI / 2);  // the pair now lies along y
  ExpectBox(ModelBox(agg, up), -1, -3, 0, 1, 3, 2, tol(10, 256));
}

TEST(McdAabb, GeometryAabbWithoutAModel) {
  Framework fw;
  TM tm(1, 1, 1);
  MeVector3 mn, mx;
  McdGeometryGetAABB(McdBoxCreate(fw, 2, 2, 2), tm, mn, mx);
  EXPECT_EQ(mn[0], 0);
  EXPECT_EQ(mx[2], 2);
}

}  // namespace
