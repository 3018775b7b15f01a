// Line segments against single models: entry point, normal and distance
// against hand-worked values for every solid type, and the guide's rules
// (start inside, one hit per model, aggregates, triangle lists ignored).
#include <cmath>

#include "query_test_support.h"

namespace {

using mcd_query_test::Scene;
using mcd_query_test::Warnings;

constexpr double kTol = 1e-5;

struct Hit {
  bool found;
  McdLineSegIntersectResult r;
};

Hit segment(McdModelID m, MeReal ax, MeReal ay, MeReal az, MeReal bx, MeReal by, MeReal bz) {
  MeVector3 a = {ax, ay, az}, b = {bx, by, bz};
  Hit h{};
  h.found = McdLineSegIntersect(m, a, b, &h.r) != 0;
  return h;
}

void expectHit(const Hit &h, McdModelID m, double px, double py, double pz, double nx, double ny, double nz,
               double distance) {
  ASSERT_TRUE(h.found);
  EXPECT_EQ(h.r.model, m);
  EXPECT_NEAR(h.r.position[0], px, kTol);
  EXPECT_NEAR(h.r.position[1], py, kTol);
  EXPECT_NEAR(h.r.position[2], pz, kTol);
  EXPECT_NEAR(h.r.normal[0], nx, kTol);
  EXPECT_NEAR(h.r.normal[1], ny, kTol);
  EXPECT_NEAR(h.r.normal[2], nz, kTol);
  EXPECT_NEAR(h.r.distance, distance, kTol);
}

TEST(LineSegment, Sphere) {
  Scene s;
  McdModelID m = s.place(McdSphereCreate(s.fw(), 1), 5, 0, 0);
  expectHit(segment(m, 0, 0, 0, 10, 0, 0), m, 4, 0, 0, -1, 0, 0, 4);
  // Off-centre chord: enters where y = 0.6, x = 5 - 0.8.
  expectHit(segment(m, 0, (MeReal)0.6, 0, 10, (MeReal)0.6, 0), m, 4.2, 0.6, 0, -0.8, 0.6, 0, 4.2);
  EXPECT_FALSE(segment(m, 0, 0, 0, 3, 0, 0).found);    // too short
  EXPECT_FALSE(segment(m, 0, 2, 0, 10, 2, 0).found);   // passes above
  EXPECT_FALSE(segment(m, 10, 0, 0, 20, 0, 0).found);  // points away
}

TEST(LineSegment, BoxAxisAlignedAndRotated) {
  Scene s;
  McdGeometryID box = McdBoxCreate(s.fw(), 2, 4, 6);  // half 1, 2, 3
  McdModelID m = s.place(box, 0, 0, 10);
  expectHit(segment(m, 0, 0, 0, 0, 0, 20), m, 0, 0, 7, 0, 0, -1, 7);
  expectHit(segment(m, 0, -5, 10, 0, 5, 10), m, 0, -2, 10, 0, -1, 0, 3);
  // Turned 90 degrees about x: the box's y extent (half 2) now lies along z.
  MeMatrix3 R = {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  McdModelID r = s.place(box, 0, 0, 10, &R);
  expectHit(segment(r, 0, 0, 0, 0, 0, 20), r, 0, 0, 8, 0, 0, -1, 8);
}

TEST(LineSegment, CylinderSideAndEnd) {
  Scene s;
  McdModelID m = s.place(McdCylinderCreate(s.fw(), 1, 2), 0, 0, 0);
  expectHit(segment(m, 5, 0, 0, -5, 0, 0), m, 1, 0, 0, 1, 0, 0, 4);
  expectHit(segment(m, 0, 0, 5, 0, 0, -5), m, 0, 0, 1, 0, 0, 1, 4);
  // Along the axis but outside the radius: misses.
  EXPECT_FALSE(segment(m, 2, 0, 5, 2, 0, -5).found);
  // Slanted through the rim region: enters the side at x = 1, z = 0.5.
  expectHit(segment(m, 3, 0, (MeReal)1.5, -3, 0, (MeReal)-1.5), m, 1, 0, 0.5, 1, 0, 0, std::sqrt(4.0 + 1.0));
}

TEST(LineSegment, SphylCapAndSide) {
  Scene s;
  McdModelID m = s.place(McdSphylCreate(s.fw(), (MeReal)0.5, 2), 0, 0, 0);
  expectHit(segment(m, 0, 0, 5, 0, 0, -5), m, 0, 0, 1.5, 0, 0, 1, 3.5);
  expectHit(segment(m, 3, 0, (MeReal)0.5, -3, 0, (MeReal)0.5), m, 0.5, 0, 0.5, 1, 0, 0, 2.5);
  // Into the rounded end at 45 degrees in the xz plane through its centre.
  const double c = std::sqrt(0.5);
  expectHit(segment(m, 3, 0, 4, 0, 0, 1), m, 0.5 * c, 0, 1 + 0.5 * c, c, 0, c, std::sqrt(18.0) - 0.5);
}

TEST(LineSegment, PlaneIsSolidBelow) {
  Scene s;
  McdModelID m = s.place(McdPlaneCreate(s.fw()), 0, 0, 0);
  expectHit(segment(m, 1, 2, 5, 1, 2, -5), m, 1, 2, 0, 0, 0, 1, 5);
  EXPECT_FALSE(segment(m, 0, 0, 5, 0, 0, 1).found);
  Hit below = segment(m, 1, 2, -1, 1, 2, 5);  // starts inside
  expectHit(below, m, 1, 2, -1, 0, 0, 0, 0);
}

TEST(LineSegment, ConvexCubeMatchesTheBox) {
  Scene s;
  MeVector3 corners[8];
  for (int i = 0; i < 8; ++i) MeVector3Set(corners[i], (i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  McdGeometryID hull = McdConvexMeshCreateHull(s.fw(), corners, 8, 0);
  ASSERT_NE(hull, nullptr);
  McdModelID m = s.place(hull, 0, 0, 0);
  expectHit(segment(m, 5, (MeReal)0.5, (MeReal)0.2, -5, (MeReal)0.5, (MeReal)0.2), m, 1, 0.5, 0.2, 1, 0, 0, 4);
  expectHit(segment(m, (MeReal)0.3, -4, 0, (MeReal)0.3, 4, 0), m, 0.3, -1, 0, 0, -1, 0, 3);
  EXPECT_FALSE(segment(m, 5, 2, 0, -5, 2, 0).found);
}

TEST(LineSegment, StartInsideReportsDistanceZero) {
  Scene s;
  McdModelID m = s.place(McdBoxCreate(s.fw(), 2, 2, 2), 0, 0, 0);
  expectHit(segment(m, (MeReal)0.5, 0, 0, 9, 0, 0), m, 0.5, 0, 0, 0, 0, 0, 0);
}

TEST(LineSegment, AggregateReportsItsEarliestChild) {
  Scene s;
  McdGeometryID ball = McdSphereCreate(s.fw(), (MeReal)0.5);
  McdGeometryID agg = McdAggregateCreate(s.fw(), 2);
  MeMatrix4 near, far;  // the aggregate keeps these pointers
  MeMatrix4TMMakeIdentity(near);
  MeMatrix4TMMakeIdentity(far);
  MeMatrix4TMSetPosition(far, 5, 0, 0);
  MeMatrix4TMSetPosition(near, 2, 0, 0);
  McdAggregateAddElement(agg, ball, far);  // added first, hit second
  McdAggregateAddElement(agg, ball, near);
  McdModelID m = s.place(agg, 0, 0, 0);
  expectHit(segment(m, 0, 0, 0, 10, 0, 0), m, 1.5, 0, 0, -1, 0, 0, 1.5);
  expectHit(segment(m, 10, 0, 0, 0, 0, 0), m, 5.5, 0, 0, 1, 0, 0, 4.5);
}

int MEAPI noTriangles(McdModelPair *, McdUserTriangle *, MeVector3, MeReal, int) { return 0; }

TEST(LineSegment, TriangleListsAreIgnored) {
  Scene s;
  MeVector3 mn = {-10, -10, -10}, mx = {10, 10, 10};
  McdGeometryID tl = McdTriangleListCreate(s.fw(), mn, mx, 4, noTriangles);
  ASSERT_NE(tl, nullptr);
  McdModelID m = s.place(tl, 0, 0, 0);
  EXPECT_FALSE(segment(m, 0, 0, 5, 0, 0, -5).found);
}

TEST(LineSegment, BadInputWarnsAndReportsNothing) {
  Scene s;
  McdModelID m = s.place(McdSphereCreate(s.fw(), 1), 0, 0, 0);
  Warnings w;
  MeVector3 a = {0, 0, 5}, b = {0, 0, -5};
  McdLineSegIntersectResult r;
  EXPECT_EQ(McdLineSegIntersect(nullptr, a, b, &r), 0u);
  EXPECT_EQ(McdLineSegIntersect(m, a, b, nullptr), 0u);
  MeVector3 bad = {0, std::nan(""), 0};
  EXPECT_EQ(McdLineSegIntersect(m, bad, b, &r), 0u);
  EXPECT_EQ(w.count(), 3u);
  EXPECT_NE(w.last().find("McdLineSegIntersect"), std::string::npos);
}

}  // namespace
