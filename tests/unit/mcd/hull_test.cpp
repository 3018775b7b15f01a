// hull_test.cpp: convex hulls: interior, repeated and face/edge points are
// dropped; faces are merged, ordered counter-clockwise from outside, with
// outward normals.
#include "mcd_test_support.h"

#include <set>

using namespace mcd_test;

namespace {

// The unit cube's corners plus points inside, on faces, on edges and repeats.
std::vector<std::array<MeReal, 3>> CubeCloud() {
  std::vector<std::array<MeReal, 3>> p;
  for (int k = 0; k < 8; ++k) p.push_back({(MeReal)(k & 1), (MeReal)((k >> 1) & 1), (MeReal)((k >> 2) & 1)});
  p.push_back({0.5f, 0.5f, 0.5f});  // centre
  p.push_back({0.2f, 0.7f, 0.4f});  // interior
  p.push_back({0.5f, 0.5f, 1});     // face centre
  p.push_back({0.5f, 0, 0});        // edge midpoint
  p.push_back({1, 1, 1});           // repeated corner
  p.push_back({0.25f, 0.75f, 0});   // on the bottom face
  return p;
}

TEST(McdHull, CubeWithExtraPointsHasEightVerticesAndSixFaces) {
  Framework fw;
  auto cloud = CubeCloud();
  McdGeometryID g =
      McdConvexMeshCreateHull(fw, reinterpret_cast<const MeVector3 *>(cloud.data()), (int)cloud.size(), 0);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(McdGeometryGetTypeId(g), kMcdGeometryTypeConvexMesh);
  EXPECT_EQ(McdConvexMeshGetVertexCount(g), 8);
  ASSERT_EQ(McdConvexMeshGetPolygonCount(g), 6);
  std::set<std::array<int, 3>> normals;
  for (int f = 0; f < 6; ++f) {
    ASSERT_EQ(McdConvexMeshGetPolygonVertexCount(g, f), 4);
    MeVector3 n;
    McdConvexMeshGetPolygonNormal(g, f, n);
    EXPECT_NEAR(MeVector3Magnitude(n), 1, tol(1));
    normals.insert({(int)std::lround(n[0]), (int)std::lround(n[1]), (int)std::lround(n[2])});
    // Counter-clockwise from outside: (v1 - v0) x (v2 - v1) points along n.
    const MeReal *v0 = McdConvexMeshGetVertex(g, McdConvexMeshGetPolygonVertexIndex(g, f, 0));
    const MeReal *v1 = McdConvexMeshGetVertex(g, McdConvexMeshGetPolygonVertexIndex(g, f, 1));
    const MeReal *v2 = McdConvexMeshGetVertex(g, McdConvexMeshGetPolygonVertexIndex(g, f, 2));
    MeVector3 e1, e2, c;
    MeVector3Subtract(e1, v1, v0);
    MeVector3Subtract(e2, v2, v1);
    MeVector3Cross(c, e1, e2);
    EXPECT_GT(MeVector3Dot(c, n), 0) << "face " << f;
    // Every corner of the face lies in its plane, on the outer side.
    for (int k = 0; k < 4; ++k) {
      const MeReal *v = McdConvexMeshGetVertex(g, McdConvexMeshGetPolygonVertexIndex(g, f, k));
      MeVector3 d;
      MeVector3Subtract(d, v, v0);
      EXPECT_NEAR(MeVector3Dot(d, n), 0, tol(1));
    }
  }
  EXPECT_EQ(normals.size(), 6u);
  // Every hull vertex is a cube corner.
  for (int i = 0; i < 8; ++i) {
    const MeReal *v = McdConvexMeshGetVertex(g, i);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(v[k] == 0 || v[k] == 1);
  }
  // Mass of the unit cube regardless of the extra points.
  MeReal m;
  MeVector3 c;
  ASSERT_TRUE(McdGeometryGetMassProperties(g, 1, &m, nullptr, c));
  EXPECT_NEAR(m, 1, tol(1));
  EXPECT_NEAR(c[0], 0.5, tol(1));
}

TEST(McdHull, PyramidHasFiveVerticesAndFiveFaces) {
  Framework fw;
  MeVector3 pyramid[] = {{0, 2, 0}, {-3, -1, -3}, {3, -1, -3}, {-3, -1, 3}, {3, -1, 3}, {0, 0, 0}};
  McdGeometryID g = McdConvexMeshCreateHull(fw, pyramid, 6, 0);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(McdConvexMeshGetVertexCount(g), 5);
  EXPECT_EQ(McdConvexMeshGetPolygonCount(g), 5);
  int squares = 0, triangles = 0;
  for (int f = 0; f < 5; ++f) {
    const int n = McdConvexMeshGetPolygonVertexCount(g, f);
    squares += n == 4;
    triangles += n == 3;
  }
  EXPECT_EQ(squares, 1);
  EXPECT_EQ(triangles, 4);
}

TEST(McdHull, DegenerateCloudsAreRejected) {
  Framework fw;
  WarningCapture w;
  MeVector3 three[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, three, 3, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("McdConvexMeshCreateHull"));
  EXPECT_TRUE(w.lastMentions("at least 4"));
  MeVector3 flat[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5f, 0.5f, 0}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, flat, 5, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("one plane"));
  MeVector3 line[] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, line, 4, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("one line"));
  MeVector3 same[] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, same, 4, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("coincide"));
  MeVector3 nan[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, nan, 4, 0), nullptr);
  EXPECT_TRUE(w.lastMentions("not finite"));
  MeVector3 tetra[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_EQ(McdConvexMeshCreateHull(fw, tetra, 4, -1), nullptr);
  EXPECT_TRUE(w.lastMentions("fatness"));
  EXPECT_EQ(McdConvexMeshCreateHull(fw, nullptr, 4, 0), nullptr);
  EXPECT_EQ(McdFrameworkGetGeometryCount(fw), 0);
  const size_t before = w.count();
  McdGeometryID ok = McdConvexMeshCreateHull(fw, tetra, 4, (MeReal)0.1);
  ASSERT_NE(ok, nullptr);
  EXPECT_EQ(w.count(), before);
  EXPECT_EQ(McdConvexMeshGetPolygonCount(ok), 4);
  EXPECT_NEAR(McdGeometryGetVolume(ok), 1.0 / 6, tol(1));
  EXPECT_EQ(McdConvexMeshGetFatness(ok), (MeReal)0.1);
}

}  // namespace
