// The tutorials' height field (tutorials/common/heightfield.h): the surface
// formula, the triangles it serves to collision, the generated terrain2.bmp,
// and a sphere resting on it through Mst at the height the formula gives.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Mst.h"
#include "heightfield.h"

namespace {

// 3 x 3 points, spacing 2, origin (-2, -2): a ridge along z at ix = 1.
struct Small {
  HeightField hf{};
  Small() {
    const MeReal h[9] = {0, 1, 0, 0, 1, 0, 0, 1, 0};
    EXPECT_EQ(HeightFieldCreate(&hf, 3, 3, 2, -2, -2, h), 1);
  }
  ~Small() { HeightFieldDestroy(&hf); }
};

}  // namespace

TEST(HeightField, SurfaceMatchesGridPointsAndIsPlanarInEachTriangle) {
  Small s;
  EXPECT_FLOAT_EQ(HeightFieldHeightAt(&s.hf, 0, 0), 1);        // (1, 1), on the ridge
  EXPECT_FLOAT_EQ(HeightFieldHeightAt(&s.hf, -2, 2), 0);       // (0, 2)
  EXPECT_FLOAT_EQ(HeightFieldHeightAt(&s.hf, -1, -1.5), 0.5);  // half-way up the ridge's side
  EXPECT_FLOAT_EQ(HeightFieldHeightAt(&s.hf, 1, 0.5), 0.5);
  EXPECT_FLOAT_EQ(HeightFieldHeightAt(&s.hf, -50, 0), 0);  // clamped to the edge
  MeVector3 mn, mx;
  HeightFieldGetBounds(&s.hf, mn, mx);
  EXPECT_EQ(mn[0], -2);
  EXPECT_EQ(mx[0], 2);
  EXPECT_EQ(mn[1], 0);
  EXPECT_EQ(mx[1], 1);
}

TEST(HeightField, TrianglesNearAPointFaceUpAndContainIt) {
  Small s;
  McdUserTriangle t[8];
  const MeVector3 p = {(MeReal)-1, 5, (MeReal)-1.5};
  const int n = HeightFieldTrianglesNear(&s.hf, p, (MeReal)0.1, t, 8);
  ASSERT_EQ(n, 2);  // one cell
  for (int i = 0; i < n; ++i) {
    const MeReal *nn = *t[i].normal;
    EXPECT_NEAR(MeVector3Magnitude(nn), 1, 1e-6);
    EXPECT_GT(nn[1], 0);
    // Normal agrees with the winding: (b - a) x (c - a) along it.
    MeVector3 u, v, c;
    MeVector3Subtract(u, *t[i].vertices[1], *t[i].vertices[0]);
    MeVector3Subtract(v, *t[i].vertices[2], *t[i].vertices[0]);
    MeVector3Cross(c, u, v);
    EXPECT_GT(MeVector3Dot(c, nn), 0);
  }
  // Cell (0, 0) climbs to the ridge: of its lower triangle (00, 11, 10)
  // only the edge 11-10, on the ridge, is a crest (the far side falls
  // away); the diagonal and the seam toward z = 0 are flat, the rest rim.
  EXPECT_EQ(t[0].flags, kMcdTriangleUseEdge1);
  EXPECT_EQ(t[1].flags, 0);
  // A wide query covers all 4 cells; the limit keeps the nearest first.
  EXPECT_EQ(HeightFieldTrianglesNear(&s.hf, p, 10, t, 8), 8);
  EXPECT_EQ(HeightFieldTrianglesNear(&s.hf, p, 10, t, 3), 3);
  EXPECT_EQ((*t[0].vertices[0])[0], -2);  // the cell containing p
  EXPECT_EQ((*t[0].vertices[0])[2], -2);
  const MeVector3 far = {100, 0, 100};
  EXPECT_EQ(HeightFieldTrianglesNear(&s.hf, far, 1, t, 8), 0);
}

// A valley (the ridge turned upside down) has no crest: every edge stays
// smooth, so a sphere rolls through it without snagging.
TEST(HeightField, AValleyHasNoSharpEdges) {
  HeightField hf{};
  const MeReal h[9] = {1, 0, 1, 1, 0, 1, 1, 0, 1};
  ASSERT_EQ(HeightFieldCreate(&hf, 3, 3, 2, -2, -2, h), 1);
  McdUserTriangle t[8];
  const MeVector3 p = {0, 5, 0};
  ASSERT_EQ(HeightFieldTrianglesNear(&hf, p, 10, t, 8), 8);
  for (const McdUserTriangle &tri : t) EXPECT_EQ(tri.flags, 0);
  HeightFieldDestroy(&hf);
}

TEST(HeightField, BadInputIsRefused) {
  HeightField hf{};
  const MeReal h[4] = {0, 0, 0, 0};
  EXPECT_EQ(HeightFieldCreate(&hf, 1, 4, 1, 0, 0, h), 0);
  EXPECT_EQ(HeightFieldCreate(&hf, 2, 2, 0, 0, 0, h), 0);
  EXPECT_EQ(HeightFieldFromBMP(&hf, "no-such-terrain", 15), 0);
  EXPECT_EQ(hf.heights, nullptr);
  HeightFieldDestroy(&hf);  // empty: fine
}

TEST(HeightField, Terrain2IsTheGeneratedMap) {
  HeightField hf{};
  ASSERT_EQ(HeightFieldFromBMP(&hf, "terrain2", 15), 1);
  EXPECT_EQ(hf.countX, 64);
  EXPECT_EQ(hf.countZ, 64);
  EXPECT_EQ(hf.spacing, 2);
  EXPECT_EQ(hf.originX, -63);
  // The flat start area at 2 m (one grey level is 15/255 = 0.059 m).
  for (MeReal x = -4; x <= 4; x += 1) EXPECT_NEAR(HeightFieldHeightAt(&hf, x, x / 2), 2, 0.06) << x;
  // Hills inside, a rim outside; slopes inside the rim below 25 degrees.
  MeVector3 mn, mx;
  HeightFieldGetBounds(&hf, mn, mx);
  EXPECT_LT(mn[1], 1);
  EXPECT_GT(mx[1], 11);
  double steepest = 0;
  for (int iz = 0; iz + 1 < hf.countZ; ++iz)
    for (int ix = 0; ix + 1 < hf.countX; ++ix) {
      const double x = hf.originX + ix * hf.spacing, z = hf.originZ + iz * hf.spacing;
      if (std::fabs(x) > 48 || std::fabs(z) > 48) continue;
      for (int k = 0; k < 2; ++k)
        steepest = std::max(steepest, std::acos((double)hf.normals[2 * (iz * (hf.countX - 1) + ix) + k][1]));
    }
  std::printf("terrain2: heights %.2f..%.2f m, steepest triangle inside the rim %.1f deg\n", (double)mn[1],
              (double)mx[1], steepest * 180 / M_PI);
  EXPECT_LT(steepest * 180 / M_PI, 25);
  HeightFieldDestroy(&hf);
}

namespace {
HeightField *gField = nullptr;
int MEAPI FieldTriangles(McdModelPair *, McdUserTriangle *t, MeVector3 pos, MeReal radius, int max) {
  return HeightFieldTrianglesNear(gField, pos, radius, t, max);
}
}  // namespace

TEST(HeightField, ASphereRestsOnTheTerrainAtTheFormulasHeight) {
  HeightField hf{};
  ASSERT_EQ(HeightFieldFromBMP(&hf, "terrain2", 15), 1);
  gField = &hf;
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  MstUniverseID u = MstUniverseCreate(&sizes);
  MdtWorldID world = MstUniverseGetWorld(u);
  MdtWorldSetGravity(world, 0, -(MeReal)9.81, 0);
  MeVector3 mn, mx;
  HeightFieldGetBounds(&hf, mn, mx);
  McdGeometryID tl = McdTriangleListCreate(MstUniverseGetFramework(u), mn, mx, 50, FieldTriangles);
  MeMatrix4 tm;
  MeMatrix4TMMakeIdentity(tm);
  ASSERT_NE(MstFixedModelCreate(u, tl, tm), nullptr);
  // Spheres dropped on the flat start area and on a slope, run for 4 s.
  const MeReal r = (MeReal)0.4;
  const MeReal spots[2][2] = {{0, 0}, {(MeReal)-23, (MeReal)17}};
  for (const auto &spot : spots) {
    McdModelID ball = MstModelAndBodyCreate(u, McdSphereCreate(MstUniverseGetFramework(u), r), 1);
    MdtBodyID b = McdModelGetBody(ball);
    const MeReal ground = HeightFieldHeightAt(&hf, spot[0], spot[1]);
    MdtBodySetPosition(b, spot[0], ground + r + (MeReal)0.5, spot[1]);
    for (int i = 0; i < 240; ++i) MstUniverseStep(u, (MeReal)1 / 60);
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    // Resting on the triangle below it: the centre is r from the plane of
    // that triangle, i.e. r / cos(slope) above the surface point below it.
    const MeReal below = HeightFieldHeightAt(&hf, p[0], p[2]);
    std::printf("sphere at (%.2f, %.2f): centre %.4f m above the surface\n", (double)p[0], (double)p[2],
                (double)(p[1] - below));
    EXPECT_GT(p[1] - below, r - 0.01);
    EXPECT_LT(p[1] - below, r / std::cos(25 * M_PI / 180) + 0.01);
    // On the flat start area it stays put; on the slope it rolls (the
    // sphere has nothing to stop rolling), yet never sinks in.
    if (spot[0] == 0) {
      EXPECT_LT(std::hypot(p[0], p[2]), 0.01);
    }
    EXPECT_TRUE(p[0] > mn[0] && p[0] < mx[0] && p[2] > mn[2] && p[2] < mx[2]);
    MstModelAndBodyDestroy(ball);
  }
  MstUniverseDestroy(u);
  HeightFieldDestroy(&hf);
  gField = nullptr;
}
