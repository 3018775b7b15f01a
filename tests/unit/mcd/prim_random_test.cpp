// prim_random_test.cpp: property tests of the analytic primitive
// interactions over random poses: unit normals, finite separations, exactly
// mirrored results in the reversed order, touch agreeing with the true
// separation, and the reported normal being the minimum-translation
// direction (its separation equals a brute-force estimate: support
// functions maximised over directions), the deepest contact agreeing with
// it. Plus degenerate poses (coincident centres, parallel axes): no NaN.
#include "nearfield_test_support.h"

using namespace mcd_test;
using namespace mcd_test::prim;

namespace {

enum Shape { kSphere, kBox, kCylinder, kSphyl };

McdGeometryID make(McdFrameworkID fw, Shape s, Lcg &u) {
  switch (s) {
    case kSphere:
      return McdSphereCreate(fw, u(0.3, 1));
    case kBox:
      return McdBoxCreate(fw, u(0.4, 2), u(0.4, 2), u(0.4, 2));
    case kCylinder:
      return McdCylinderCreate(fw, u(0.3, 1), u(0.5, 2));
    default:
      return McdSphylCreate(fw, u(0.2, 0.7), u(0, 2));
  }
}

struct PairCase {
  Shape a, b;
  bool exactDepth;   // the deepest contact is the minimum translation itself
  double normalTol;  // allowed shortfall of the normal's separation
  bool faceMargin;   // box-box: a face normal is kept unless another axis is
                     // better by 5% of the depth plus 1% of the smallest half
                     // extent (box_box.cpp)
};

// The smallest half extent of a box geometry.
double smallestHalf(McdGeometryID g) {
  MeVector3 h;
  McdBoxGetRadii(g, h);
  return std::fmin(std::fmin(h[0], h[1]), h[2]);
}

const MeReal kFloatScale = (MeReal)(sizeof(MeReal) == 4 ? 1 : 1e-3);

class PrimRandom : public ::testing::TestWithParam<PairCase> {};

TEST_P(PrimRandom, RandomPosesAgreeWithBruteForce) {
  const PairCase pc = GetParam();
  Framework fw(8, 8);
  const double tol = McdFrameworkGetContactTolerance(fw);
  Lcg u(1234u + 17u * (unsigned)pc.a + 5u * (unsigned)pc.b);
  int touching = 0, apart = 0;
  for (int trial = 0; trial < 300; ++trial) {
    McdGeometryID ga = make(fw, pc.a, u), gb = make(fw, pc.b, u);
    Placed A(ga, u(-1, 1), u(-1, 1), u(-1, 1), {u(-1, 1), u(-1, 1), u(0.1, 1)}, u(0, 6.28));
    Placed B(gb, u(-1, 1), u(-1, 1), u(-1, 1), {u(-1, 1), u(0.1, 1), u(-1, 1)}, u(0, 6.28));
    Hit f(A.model, B.model), r(B.model, A.model);
    ASSERT_EQ(f.touch, r.touch) << "trial " << trial;
    ASSERT_EQ(f.count(), r.count()) << "trial " << trial;
    for (int i = 0; i < f.count(); ++i) {
      const McdContact &c = f.c[i], &d = r.c[i];
      EXPECT_NEAR(MeVector3Magnitude(c.normal), 1, 1e-5);
      EXPECT_TRUE(std::isfinite(c.separation));
      EXPECT_LE(c.separation, tol);
      EXPECT_EQ(c.separation, d.separation);
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(c.position[k]));
        EXPECT_EQ(d.position[k], c.position[k]);
        EXPECT_EQ(d.normal[k], -c.normal[k]);
      }
    }
    const D3 n = {(double)f.r.normal[0], (double)f.r.normal[1], (double)f.r.normal[2]};
    const double truth = bruteSeparation(A.model, B.model, n);
    const double eps = 3e-5 * kFloatScale + 1e-7;
    if (!f.touch) {
      ++apart;
      EXPECT_GT(truth, tol - eps) << "trial " << trial << ": missed an overlap";
      continue;
    }
    ++touching;
    EXPECT_LE(truth, tol + eps) << "trial " << trial << ": reported a contact when apart";
    const double along = sepAlong(A.model, B.model, n);
    if (pc.faceMargin) {
      // The normal is a separating-axis candidate no better than the truth,
      // and short of it by no more than the margins allow: with s the
      // chosen axis's separation, truth <= max(s, 0.95 s) + 0.01 h.
      const double h = std::fmin(smallestHalf(ga), smallestHalf(gb));
      EXPECT_LE(along, truth + eps) << "trial " << trial;
      EXPECT_LE(truth, std::fmax(along, 0.95 * along) + 0.01 * h + eps) << "trial " << trial;
      // No contact is deeper along n than the shapes' overlap along n.
      EXPECT_GE(f.minSep(), along - eps) << "trial " << trial;
    } else {
      // The normal is the minimum-translation direction.
      EXPECT_NEAR(along, truth, pc.normalTol + eps) << "trial " << trial;
      // No contact is deeper than the true penetration.
      EXPECT_GE(f.minSep(), truth - pc.normalTol - eps) << "trial " << trial;
    }
    if (pc.exactDepth) {
      EXPECT_NEAR(f.minSep(), truth, eps) << "trial " << trial;
      // Each contact lies midway (along n) between the surfaces' extreme
      // points: model1's lowest along n and model2's highest.
      const double mid = (support(B.model, n) - support(A.model, {-n[0], -n[1], -n[2]})) / 2;
      for (int i = 0; i < f.count(); ++i) {
        const D3 p = {f.c[i].position[0], f.c[i].position[1], f.c[i].position[2]};
        EXPECT_NEAR(dot(p, n), mid, 4 * eps) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(touching, 20);
  EXPECT_GT(apart, 20);
  RecordProperty("touching", touching);
  RecordProperty("apart", apart);
}

const PairCase kCases[] = {{kSphere, kBox, true, 0, false},   {kSphere, kCylinder, true, 0, false},
                           {kSphere, kSphyl, true, 0, false}, {kSphyl, kSphyl, true, 0, false},
                           {kSphyl, kBox, false, 0, false},   {kBox, kBox, false, 0, true}};

std::string CaseName(const ::testing::TestParamInfo<PairCase> &i) {
  static const char *const names[] = {"Sphere", "Box", "Cylinder", "Sphyl"};
  return std::string(names[i.param.a]) + names[i.param.b];
}

INSTANTIATE_TEST_SUITE_P(McdNearfield, PrimRandom, ::testing::ValuesIn(kCases), CaseName);

// Plane pairs: the deepest contact is the lowest point of the shape.
TEST(McdNearfieldRandom, CylinderAndSphylOnATiltedPlane) {
  Framework fw(8, 8);
  Lcg u(99);
  Placed ground(McdPlaneCreate(fw), 0, 0, 0, {1, 0, (MeReal)0.3}, (MeReal)-1.2);
  const D3 n = row(ground.model, 2), o = row(ground.model, 3);
  int touching = 0;
  for (int trial = 0; trial < 300; ++trial) {
    McdGeometryID g = make(fw, trial % 2 ? kCylinder : kSphyl, u);
    Placed s(g, u(-2, 2), u(-2, 2), u(-2, 2), {u(-1, 1), u(-1, 1), u(0.1, 1)}, u(0, 6.28));
    Hit f(s.model, ground.model), r(ground.model, s.model);
    const double lowest = -support(s.model, {-n[0], -n[1], -n[2]}) - dot(o, n);
    ASSERT_EQ(f.count(), r.count());
    EXPECT_EQ(f.touch, lowest <= McdFrameworkGetContactTolerance(fw) ? 1 : 0) << lowest;
    if (!f.touch) continue;
    ++touching;
    EXPECT_NEAR(f.minSep(), lowest, 1e-5);
    for (int i = 0; i < f.count(); ++i) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(f.c[i].normal[k], n[k], 1e-6);
        EXPECT_EQ(r.c[i].normal[k], -f.c[i].normal[k]);
      }
      // Each contact lies halfway between its shape point and the plane.
      const D3 p = {f.c[i].position[0], f.c[i].position[1], f.c[i].position[2]};
      EXPECT_NEAR(dot(p, n) - dot(o, n), f.c[i].separation / 2, 1e-5);
    }
  }
  EXPECT_GT(touching, 40);
}

// Degenerate poses: coincident centres, parallel and identical axes.
TEST(McdNearfieldRandom, DegeneratePosesGiveNoNaN) {
  Framework fw(8, 8);
  McdGeometryID shapes[4] = {McdSphereCreate(fw, 1), McdBoxCreate(fw, 1, 1, 1), McdCylinderCreate(fw, 1, 1),
                             McdSphylCreate(fw, (MeReal)0.5, 1)};
  McdGeometryID pointSphyl = McdSphylCreate(fw, (MeReal)0.5, 0);
  Placed ground(McdPlaneCreate(fw), 0, 0, 0);
  for (McdGeometryID a : shapes)
    for (McdGeometryID b : {shapes[0], shapes[1], shapes[2], shapes[3], pointSphyl}) {
      for (MeReal angle : {(MeReal)0, (MeReal)(ME_PI / 2), (MeReal)ME_PI}) {
        Placed A(a, 0, 0, 0), B(b, 0, 0, 0, {0, 1, 0}, angle);
        for (McdModelID m : {B.model, ground.model}) {
          Hit h(A.model, m);
          for (int i = 0; i < h.count(); ++i) {
            EXPECT_NEAR(MeVector3Magnitude(h.c[i].normal), 1, 1e-5);
            EXPECT_TRUE(std::isfinite(h.c[i].separation));
            for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(h.c[i].position[k]));
          }
        }
      }
    }
}

}  // namespace
