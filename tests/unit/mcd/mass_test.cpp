// mass_test.cpp: mass, centre of mass and inertia of every geometry for a
// density, against closed forms.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

const double kPi = 3.14159265358979323846;

struct Mass {
  MeReal m = 0;
  MeMatrix3 I;
  MeVector3 c;
  MeBool ok = 0;
  Mass(McdGeometryID g, MeReal density) { ok = McdGeometryGetMassProperties(g, density, &m, I, c); }
};

TEST(McdMass, SphereIsTwoFifthsMR2) {
  Framework fw;
  McdGeometryID s = McdSphereCreate(fw, (MeReal)0.5);
  Mass p(s, 2);
  ASSERT_TRUE(p.ok);
  const double m = 2 * 4.0 / 3 * kPi * 0.125;
  EXPECT_NEAR(p.m, m, tol(m));
  expectDiagonal(p.I, 0.4 * m * 0.25, 0.4 * m * 0.25, 0.4 * m * 0.25, tol(1));
  EXPECT_EQ(p.c[0], 0);
  EXPECT_EQ(p.c[1], 0);
  EXPECT_EQ(p.c[2], 0);
  EXPECT_NEAR(McdGeometryGetVolume(s), m / 2, tol(1));
}

TEST(McdMass, BoxOfTheGuide) {
  Framework fw;
  Mass p(McdBoxCreate(fw, 2, 1, 3), 1);  // the guide's 2x1x3 box
  ASSERT_TRUE(p.ok);
  EXPECT_NEAR(p.m, 6, tol(6));
  // I_xx = m (dy^2 + dz^2) / 12 and cyclic.
  expectDiagonal(p.I, 6 * (1 + 9) / 12.0, 6 * (4 + 9) / 12.0, 6 * (4 + 1) / 12.0, tol(10));
}

TEST(McdMass, CylinderAlongZ) {
  Framework fw;
  const double r = 0.5, h = 2, rho = 3;
  Mass p(McdCylinderCreate(fw, (MeReal)r, (MeReal)h), (MeReal)rho);
  ASSERT_TRUE(p.ok);
  const double m = rho * kPi * r * r * h;
  EXPECT_NEAR(p.m, m, tol(m));
  const double side = m * (3 * r * r + h * h) / 12;
  expectDiagonal(p.I, side, side, m * r * r / 2, tol(m));
}

TEST(McdMass, SphylIsACylinderPlusTwoHemispheres) {
  Framework fw;
  const double r = 0.5, h = 2, rho = 1.5;
  Mass p(McdSphylCreate(fw, (MeReal)r, (MeReal)h), (MeReal)rho);
  ASSERT_TRUE(p.ok);
  // Independent composition: the cylinder, plus two hemispheres of mass mh
  // whose centres sit 3r/8 beyond the ends; a hemisphere's transverse
  // inertia about its own centre is mh r^2 (2/5 - 9/64).
  const double mc = rho * kPi * r * r * h, mh = rho * 2.0 / 3 * kPi * r * r * r;
  const double arm = h / 2 + 3 * r / 8;
  const double side = mc * (3 * r * r + h * h) / 12 + 2 * (mh * r * r * (0.4 - 9.0 / 64) + mh * arm * arm);
  const double axial = mc * r * r / 2 + 2 * mh * 0.4 * r * r;
  EXPECT_NEAR(p.m, mc + 2 * mh, tol(mc));
  expectDiagonal(p.I, side, side, axial, tol(side, 256));
  // Height 0 is a sphere.
  Mass ball(McdSphylCreate(fw, (MeReal)r, 0), 1);
  const double mb = 4.0 / 3 * kPi * r * r * r;
  expectDiagonal(ball.I, 0.4 * mb * r * r, 0.4 * mb * r * r, 0.4 * mb * r * r, tol(1));
}

TEST(McdMass, PlaneAndTriangleListHaveNone) {
  Framework fw;
  WarningCapture w;
  Mass plane(McdPlaneCreate(fw), 1);
  EXPECT_FALSE(plane.ok);
  EXPECT_EQ(plane.m, 0);
  EXPECT_TRUE(w.lastMentions("McdGeometryGetMassProperties"));
  EXPECT_TRUE(w.lastMentions("Plane"));
  MeVector3 mn = {-1, -1, -1}, mx = {1, 1, 1};
  auto cb = [](McdModelPair *, McdUserTriangle *, MeVector3, MeReal, int) -> int { return 0; };
  Mass tri(McdTriangleListCreate(fw, mn, mx, 4, cb), 1);
  EXPECT_FALSE(tri.ok);
  EXPECT_EQ(McdGeometryGetVolume(McdPlaneCreate(fw)), 0);
}

TEST(McdMass, HullOfACubeIsTheBox) {
  Framework fw;
  // A 2 x 2 x 2 cube whose centre is at (1, 2, 3).
  std::vector<MeReal> pts;
  MeVector3 corners[8];
  for (int k = 0; k < 8; ++k) MeVector3Set(corners[k], (k & 1) ? 2 : 0, (k & 2) ? 3 : 1, (k & 4) ? 4 : 2);
  Mass p(McdConvexMeshCreateHull(fw, corners, 8, 0), 2);
  ASSERT_TRUE(p.ok);
  EXPECT_NEAR(p.m, 16, tol(16));
  EXPECT_NEAR(p.c[0], 1, tol(4));
  EXPECT_NEAR(p.c[1], 2, tol(4));
  EXPECT_NEAR(p.c[2], 3, tol(4));
  const double i = 16 * (4 + 4) / 12.0;
  expectDiagonal(p.I, i, i, i, tol(i, 256));
}

TEST(McdMass, GuidePyramid) {
  Framework fw;
  // The guide's four-sided pyramid: base 6 x 6 at y = -1, apex (0, 2, 0).
  MeVector3 pyramid[] = {{0, 2, 0}, {-3, -1, -3}, {3, -1, -3}, {-3, -1, 3}, {3, -1, 3}};
  McdGeometryID g = McdConvexMeshCreateHull(fw, pyramid, 5, 0);
  ASSERT_NE(g, nullptr);
  Mass p(g, 1);
  ASSERT_TRUE(p.ok);
  // V = a^2 H / 3 = 36; centre of mass H/4 above the base (y = -0.25);
  // I_axis = m a^2 / 10; I_transverse = m (a^2/20 + 3 H^2/80).
  const double a = 6, H = 3, m = 36;
  EXPECT_NEAR(p.m, m, tol(m));
  EXPECT_NEAR(p.c[0], 0, tol(4));
  EXPECT_NEAR(p.c[1], -0.25, tol(4));
  EXPECT_NEAR(p.c[2], 0, tol(4));
  const double t = m * (a * a / 20 + 3 * H * H / 80);
  expectDiagonal(p.I, t, m * a * a / 10, t, tol(t, 512));
}

TEST(McdMass, AggregateUsesRotationAndParallelAxes) {
  Framework fw;
  // A 2x1x1 box turned 90 degrees about z, centred at (0, 0, 1), and a
  // sphere of radius 0.5 at (0, 0, -1).
  TM boxTM(0, 0, 1), ballTM(0, 0, -1);
  const MeVector3 z = {0, 0, 1};
  boxTM.rotate(z, ME_PI / 2);
  McdGeometryID agg = McdAggregateCreate(fw, 2);
  ASSERT_EQ(McdAggregateAddElement(agg, McdBoxCreate(fw, 2, 1, 1), boxTM), 0);
  ASSERT_EQ(McdAggregateAddElement(agg, McdSphereCreate(fw, (MeReal)0.5), ballTM), 1);
  Mass p(agg, 1);
  ASSERT_TRUE(p.ok);
  const double mb = 2, ms = 4.0 / 3 * kPi * 0.125, M = mb + ms;
  const double zc = (mb * 1 - ms * 1) / M;
  EXPECT_NEAR(p.m, M, tol(M));
  EXPECT_NEAR(p.c[2], zc, tol(2));
  EXPECT_NEAR(p.c[0], 0, tol(2));
  // Box inertia (1/3, 5/6, 5/6) in its frame; turned about z, x and y swap.
  const double isph = 0.4 * ms * 0.25;
  const double shift = mb * (1 - zc) * (1 - zc) + ms * (1 + zc) * (1 + zc);
  expectDiagonal(p.I, 5.0 / 6 + isph + shift, 1.0 / 3 + isph + shift, 5.0 / 6 + isph, tol(4, 256));
}

TEST(McdMass, StoolAggregateMatchesHandSum) {
  Framework fw(8, 16);
  // The guide's stool: a 2.2 x 2.2 x 0.1 seat at z = 1, four legs of
  // radius 0.1, height 2 at (+-1, +-1, 0). Each element needs its own TM.
  static TM seatTM(0, 0, 1), legTM[4] = {TM(1, 1, 0), TM(1, -1, 0), TM(-1, 1, 0), TM(-1, -1, 0)};
  McdGeometryID seat = McdBoxCreate(fw, (MeReal)2.2, (MeReal)2.2, (MeReal)0.1);
  McdGeometryID leg = McdCylinderCreate(fw, (MeReal)0.1, 2);
  McdGeometryID ag = McdAggregateCreate(fw, 5);
  McdAggregateAddElement(ag, seat, seatTM);
  for (TM &t : legTM) McdAggregateAddElement(ag, leg, t);
  EXPECT_EQ(McdGeometryGetReferenceCount(leg), 4);
  Mass p(ag, 1);
  ASSERT_TRUE(p.ok);
  const double ms = 2.2 * 2.2 * 0.1, ml = kPi * 0.01 * 2, M = ms + 4 * ml;
  const double zc = ms * 1 / M;
  const double seatX = ms * (2.2 * 2.2 + 0.01) / 12, seatZ = ms * (2.2 * 2.2 * 2) / 12;
  const double legX = ml * (3 * 0.01 + 4) / 12, legZ = ml * 0.01 / 2;
  const double Ixx = seatX + ms * (1 - zc) * (1 - zc) + 4 * (legX + ml * (1 + zc * zc));
  const double Izz = seatZ + 4 * (legZ + ml * 2);
  EXPECT_NEAR(p.m, M, tol(M));
  EXPECT_NEAR(p.c[2], zc, tol(1));
  expectDiagonal(p.I, Ixx, Ixx, Izz, tol(Ixx, 256));
}

}  // namespace
