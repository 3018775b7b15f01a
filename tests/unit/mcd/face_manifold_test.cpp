// face_manifold_test.cpp: face-face touches of the general families give
// at most four contacts on the common face (contact_reduce.h), with the
// face's normal and the overlap as separation: two hull cubes, a hull cube
// on a box, a box on a triangle list, each turned by every yaw 0..45
// degrees; a hull cube on a plane with 8 bottom vertices (a face split
// into a fan) keeps four.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "nearfield_support.h"

using namespace mcd_test;

namespace {

const double kOverlap = 1e-3;

McdGeometryID cubeHull(McdFrameworkID fw, double h) {
  MeVector3 c[8];
  for (int i = 0; i < 8; ++i)
    MeVector3Set(c[i], (MeReal)((i & 1) ? h : -h), (MeReal)((i & 2) ? h : -h), (MeReal)((i & 4) ? h : -h));
  return McdConvexMeshCreateHull(fw, c, 8, 0);
}

// The contacts of `upper` (model1) on `lower`: 3 or 4, normal +z within
// 1e-3, separation -kOverlap, all at the common face's height z.
void expectFaceContacts(McdModelID upper, McdModelID lower, double z, const std::string &what) {
  Hit h(upper, lower);
  ASSERT_EQ(h.touch, 1) << what;
  EXPECT_GE(h.count(), 3) << what;
  EXPECT_LE(h.count(), 4) << what;
  for (int i = 0; i < h.count(); ++i) {
    const McdContact &c = h.contacts[i];
    EXPECT_NEAR(c.normal[2], 1, 1e-3) << what;
    EXPECT_NEAR(c.separation, -kOverlap, 2e-5) << what;
    EXPECT_NEAR(c.position[2], z - kOverlap / 2, 2e-5) << what;
  }
}

TEST(McdFaceManifold, HullCubesAndBoxesAtEveryYaw) {
  Framework fw;
  Placed lowerHull(cubeHull(fw, 0.5), 0, 0, 0);
  Placed lowerBox(McdBoxCreate(fw, 1, 1, 1), 5, 0, 0);
  for (int deg = 0; deg <= 45; ++deg) {
    const MeReal yaw = (MeReal)(deg * ME_PI / 180);
    Placed a(cubeHull(fw, 0.5), 0, 0, (MeReal)(1 - kOverlap));
    a.rotate(0, 0, 1, yaw);
    expectFaceContacts(a.model, lowerHull.model, 0.5, "hull on hull, " + std::to_string(deg));
    Placed b(cubeHull(fw, 0.5), 5, 0, (MeReal)(1 - kOverlap));
    b.rotate(0, 0, 1, yaw);
    expectFaceContacts(b.model, lowerBox.model, 0.5, "hull on box, " + std::to_string(deg));
  }
}

// Two triangles: the square [-5, 5]^2 at z = 0, the diagonal smooth.
MeVector3 gCorner[4] = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
MeVector3 gUp = {0, 0, 1};

int MEAPI Floor(McdModelPair *, McdUserTriangle *t, MeVector3, MeReal, int max) {
  const int idx[2][3] = {{0, 1, 2}, {0, 2, 3}};
  const int flags[2] = {kMcdTriangleStandard & ~kMcdTriangleUseEdge2, kMcdTriangleStandard & ~kMcdTriangleUseEdge0};
  for (int i = 0; i < 2 && i < max; ++i) {
    for (int k = 0; k < 3; ++k) t[i].vertices[k] = &gCorner[idx[i][k]];
    t[i].normal = &gUp;
    t[i].flags = flags[i];
  }
  return 2;
}

TEST(McdFaceManifold, BoxOnATriangleListAtEveryYaw) {
  Framework fw(16, 64);
  MeVector3 mn = {-5, -5, -1}, mx = {5, 5, 0};
  Placed floor(McdTriangleListCreate(fw, mn, mx, 2, Floor), 0, 0, 0);
  for (int deg = 0; deg <= 45; ++deg) {
    // Across the smooth diagonal, so both triangles make contacts.
    Placed box(McdBoxCreate(fw, 1, 1, 1), (MeReal)0.1, (MeReal)-0.1, (MeReal)(0.5 - kOverlap));
    box.rotate(0, 0, 1, (MeReal)(deg * ME_PI / 180));
    expectFaceContacts(box.model, floor.model, 0, "box on list, " + std::to_string(deg));
  }
}

TEST(McdFaceManifold, OctagonalPrismOnPlaneAndBoxKeepsFour) {
  Framework fw;
  MeVector3 c[16];
  for (int i = 0; i < 16; ++i) {
    const double a = ME_PI / 4 * (i % 8);
    MeVector3Set(c[i], (MeReal)(0.5 * std::cos(a)), (MeReal)(0.5 * std::sin(a)), (MeReal)(i < 8 ? -0.25 : 0.25));
  }
  McdGeometryID prism = McdConvexMeshCreateHull(fw, c, 16, 0);
  Placed plane(McdPlaneCreate(fw), 0, 0, 0);
  Placed ground(McdBoxCreate(fw, 20, 20, 2), 5, 0, -1);
  Placed onPlane(prism, 0, 0, (MeReal)(0.25 - kOverlap));
  Placed onBox(prism, 5, 0, (MeReal)(0.25 - kOverlap));
  expectFaceContacts(onPlane.model, plane.model, 0, "prism on plane");
  expectFaceContacts(onBox.model, ground.model, 0, "prism on box");
  // The four kept enclose at least half the octagon (area 0.707).
  Hit h(onPlane.model, plane.model);
  ASSERT_EQ(h.count(), 4);
  double angle[4];
  for (int i = 0; i < 4; ++i) angle[i] = std::atan2(h.contacts[i].position[1], h.contacts[i].position[0]);
  std::sort(angle, angle + 4);
  double area = 0;
  for (int i = 0; i < 4; ++i) area += 0.5 * 0.25 * std::sin(angle[(i + 1) % 4] - angle[i] + (i == 3 ? 2 * ME_PI : 0));
  EXPECT_GT(area, 0.35);
}

}  // namespace
