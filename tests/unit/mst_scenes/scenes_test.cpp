// Issue 4's universe scenes: each asserts numbers and prints its figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "Mst.h"

namespace {

constexpr MeReal kG = (MeReal)9.81;

MstUniverseID NewUniverse() {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  return MstUniverseCreate(&sizes);
}

struct Universe {
  MstUniverseID u = NewUniverse();
  ~Universe() { MstUniverseDestroy(u); }
};

// Row-vector TM: rows 0..2 are the axes, row 3 the position.
void TMFromAxes(MeMatrix4 tm, const MeReal x[3], const MeReal y[3], const MeReal z[3], const MeReal p[3]) {
  for (int j = 0; j < 3; ++j) {
    tm[0][j] = x[j];
    tm[1][j] = y[j];
    tm[2][j] = z[j];
    tm[3][j] = p[j];
  }
  tm[0][3] = tm[1][3] = tm[2][3] = 0;
  tm[3][3] = 1;
}

// A plane y = 0 with its z normal along +y.
void YUpPlaneTM(MeMatrix4 tm) {
  const MeReal x[3] = {1, 0, 0}, y[3] = {0, 0, -1}, z[3] = {0, 1, 0}, p[3] = {0, 0, 0};
  TMFromAxes(tm, x, y, z, p);
}

// World position of a point given in the model's frame.
void ToWorld(McdModelID m, const MeReal l[3], MeReal w[3]) {
  MeMatrix4Ptr tm = McdModelGetTransformPtr(m);
  for (int j = 0; j < 3; ++j) w[j] = l[0] * tm[0][j] + l[1] * tm[1][j] + l[2] * tm[2][j] + tm[3][j];
}

}  // namespace

// ---------------------------------------------------------------------------
// 1. The guide's 21-box stack (y up).
TEST(MstScenes, GuideBoxStackStandsAndSleeps) {
  Universe U;
  MstUniverseID u = U.u;
  MdtWorldID world = u->world;
  const MeReal h = (MeReal)1 / 60;
  MdtWorldSetGravity(world, 0, -kG, 0);
  MdtWorldSetEpsilon(world, (MeReal)0.005);
  // Our gamma is per step (the row's correction speed is gamma/h * error),
  // the guide's 5 is a rate: gamma h = 5/60 keeps gamma h < 1.
  MdtWorldSetGamma(world, 5 * h);
  MdtWorldSetAutoDisable(world, 1);
  const MeReal r = 2;
  MdtWorldSetAutoDisableVelocityThreshold(world, r * (MeReal)0.02);
  MdtWorldSetAutoDisableAccelerationThreshold(world, r * (MeReal)0.5);
  MdtWorldSetAutoDisableAngularVelocityThreshold(world, r * (MeReal)0.001);
  MdtWorldSetAutoDisableAngularAccelerationThreshold(world, r * (MeReal)0.002);

  MstBridgeID bridge = u->bridge;
  const MstMaterialID boxMat = MstBridgeGetNewMaterial(bridge);
  const MstMaterialID groundMat = MstBridgeGetNewMaterial(bridge);
  MdtContactParamsID bg = MstBridgeGetContactParams(bridge, boxMat, groundMat);
  MdtContactParamsSetPrimaryFrictionModel(bg, MdtFrictionModelNormalForce);
  MdtContactParamsSetSecondaryFrictionModel(bg, MdtFrictionModelNormalForce);
  MdtContactParamsSetType(bg, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(bg, (MeReal)0.4);
  MdtContactParamsSetRestitution(bg, (MeReal)0.01);
  MdtContactParamsID bb = MstBridgeGetContactParams(bridge, boxMat, boxMat);
  MdtContactParamsSetType(bb, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(bb, (MeReal)0.1);
  MdtContactParamsSetRestitution(bb, (MeReal)0.01);

  MeMatrix4 groundTM;
  YUpPlaneTM(groundTM);
  McdModelID ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  McdModelSetMaterial(ground, groundMat);

  const int n = 21;
  const MeReal side[3] = {1, (MeReal)0.3, 1};
  std::vector<McdModelID> boxes;
  std::vector<MdtBodyID> bodies;
  for (int i = 0; i < n; ++i) {
    McdModelID m = MstModelAndBodyCreate(u, McdBoxCreate(u->frame, side[0], side[1], side[2]), 1);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetMass(b, 5);
    MeMatrix3 I = {{5, 0, 0}, {0, 5, 0}, {0, 0, 5}};
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetPosition(b, 0, (i + 1) * side[1] * 2, 0);
    McdModelSetMaterial(m, boxMat);
    boxes.push_back(m);
    bodies.push_back(b);
  }
  int steps = 0;
  const int maxSteps = (int)(20 / h);
  auto anyAwake = [&] {
    for (MdtBodyID b : bodies)
      if (MdtBodyIsEnabled(b)) return true;
    return false;
  };
  while (anyAwake() && steps < maxSteps) {
    MstUniverseStep(u, h);
    ++steps;
  }
  MeVector3 top;
  MdtBodyGetPosition(bodies.back(), top);
  const double drift = std::hypot((double)top[0], (double)top[2]);
  std::printf(
      "[ figures  ] 21-box stack: all asleep: %s after %.3f s (%d steps); top box at "
      "y = %.4f (stacked %.4f), horizontal drift %.2f mm\n",
      anyAwake() ? "NO" : "yes", steps * (double)h, steps, (double)top[1], 0.15 + 0.3 * (n - 1), drift * 1000);
  // The contacts are soft: a contact carrying impulse lambda per step sits
  // at a penetration of about epsilon * lambda * h / gamma (softness
  // epsilon on the diagonal, corrected at gamma/h per step), ~4 mm under
  // the bottom box's 1030 N and less above it; summed over 21 contacts the
  // top box sits ~50 mm low. Bound the sink and each contact's overlap.
  double worstY = 0, worstOverlap = 0;
  MeReal below = 0;
  for (int i = 0; i < n; ++i) {
    MeVector3 p;
    MdtBodyGetPosition(bodies[i], p);
    worstY = std::max(worstY, std::fabs((double)p[1] - (0.15 + 0.3 * i)));
    const double gap = (double)p[1] - (i == 0 ? 0.0 : (double)below) - (i == 0 ? 0.15 : 0.3);
    worstOverlap = std::max(worstOverlap, -gap);
    below = p[1];
  }
  std::printf("[ figures  ] 21-box stack: sink %.2f mm at the worst box, worst contact overlap %.2f mm\n",
              worstY * 1000, worstOverlap * 1000);
  EXPECT_FALSE(anyAwake()) << "not every box auto-disabled within 20 s";
  EXPECT_LT(drift, 0.05);
  EXPECT_LT(worstY, 0.08) << "the stack fell or sank more than its contacts' softness explains";
  EXPECT_LT(worstOverlap, 0.008);
}

// ---------------------------------------------------------------------------
// 2. The stool aggregate (z up): seat and four legs.
TEST(MstScenes, StoolAggregateLandsUprightOnItsLegs) {
  Universe U;
  MstUniverseID u = U.u;
  MdtWorldSetGravity(u->world, 0, 0, -kG);
  MeMatrix4 groundTM;
  MeMatrix4TMMakeIdentity(groundTM);
  MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);

  McdAggregateID agg = McdAggregateCreate(u->frame, 5);
  MeMatrix4 rel[5];  // kept by pointer by the aggregate
  for (int i = 0; i < 5; ++i) MeMatrix4TMMakeIdentity(rel[i]);
  rel[0][3][2] = 1;
  ASSERT_GE(McdAggregateAddElement(agg, McdBoxCreate(u->frame, (MeReal)2.2, (MeReal)2.2, (MeReal)0.1), rel[0]), 0);
  const MeReal legXY[4][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  for (int i = 0; i < 4; ++i) {
    rel[i + 1][3][0] = legXY[i][0];
    rel[i + 1][3][1] = legXY[i][1];
    ASSERT_GE(McdAggregateAddElement(agg, McdCylinderCreate(u->frame, (MeReal)0.1, 2), rel[i + 1]), 0);
  }
  McdModelID stool = MstModelAndBodyCreate(u, agg, 1);
  MdtBodyID body = McdModelGetBody(stool);
  // Aggregate origin at z = 1.2: the legs' bottoms (z = -1 in the frame) 0.2 m up.
  MdtBodySetPosition(body, 0, 0, (MeReal)1.2);
  for (int i = 0; i < 300; ++i) MstUniverseStep(u, (MeReal)0.01);
  MeMatrix4Ptr tm = McdModelGetTransformPtr(stool);
  const double tiltDeg = std::acos(std::min(1.0, (double)tm[2][2])) * 180 / M_PI;
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    const MeReal bottom[3] = {legXY[i][0], legXY[i][1], -1};
    MeReal w[3];
    ToWorld(stool, bottom, w);
    worst = std::max(worst, std::fabs((double)w[2]));
  }
  MeVector3 p;
  MdtBodyGetPosition(body, p);
  std::printf(
      "[ figures  ] stool: frame origin z = %.5f (1 expected), body z = %.5f, seat tilt "
      "%.3f deg, worst leg-bottom height %.2f mm\n",
      (double)tm[3][2], (double)p[2], tiltDeg, worst * 1000);
  EXPECT_LT(tiltDeg, 3.0);
  EXPECT_LT(worst, 0.005);
}

// ---------------------------------------------------------------------------
// 3. The guide's pyramid hull on a y-up plane.
TEST(MstScenes, PyramidHullRestsOnItsBase) {
  Universe U;
  MstUniverseID u = U.u;
  MdtWorldSetGravity(u->world, 0, -kG, 0);
  MeMatrix4 groundTM;
  YUpPlaneTM(groundTM);
  MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  const MeVector3 pts[5] = {{0, 2, 0}, {-3, -1, -3}, {3, -1, -3}, {-3, -1, 3}, {3, -1, 3}};
  McdConvexMeshID hull = McdConvexMeshCreateHull(u->frame, pts, 5, 0);
  ASSERT_NE(hull, nullptr);
  McdModelID pyr = MstModelAndBodyCreate(u, hull, 1);
  MdtBodySetPosition(McdModelGetBody(pyr), 0, (MeReal)1.5, 0);  // base 0.5 m up
  for (int i = 0; i < 300; ++i) MstUniverseStep(u, (MeReal)0.01);
  double worst = 0;
  for (int i = 1; i < 5; ++i) {
    MeReal w[3];
    ToWorld(pyr, pts[i], w);
    worst = std::max(worst, std::fabs((double)w[1]));
  }
  MeMatrix4Ptr tm = McdModelGetTransformPtr(pyr);
  const double tiltDeg = std::acos(std::min(1.0, (double)tm[1][1])) * 180 / M_PI;
  std::printf(
      "[ figures  ] pyramid: origin y = %.5f (1 expected), tilt %.4f deg, worst base "
      "corner height %.2f mm\n",
      (double)tm[3][1], tiltDeg, worst * 1000);
  EXPECT_LT(worst, 0.003);
  EXPECT_LT(tiltDeg, 1.0);
}

// ---------------------------------------------------------------------------
// 4. A sphere rolling down a triangulated slope (z up, downhill along +x).
namespace {

constexpr double kSlopeDeg = 10;

struct Slope {
  struct V {
    MeVector3 p;
  };
  std::vector<V> v;  // grid vertices
  MeVector3 normal;
  std::vector<int> tri;        // 3 indices per triangle
  std::vector<MeReal> lo, hi;  // AABB per triangle, 3 each
  int calls = 0;
};
Slope *gSlope = nullptr;

int MEAPI SlopeTriangles(McdModelPair *, McdUserTriangle *out, MeVector3 pos, MeReal radius, int maxTriangles) {
  Slope &s = *gSlope;
  ++s.calls;
  int count = 0;
  const int nt = (int)s.tri.size() / 3;
  for (int t = 0; t < nt && count < maxTriangles; ++t) {
    bool apart = false;
    for (int j = 0; j < 3; ++j)
      if (pos[j] + radius < s.lo[3 * t + j] || pos[j] - radius > s.hi[3 * t + j]) apart = true;
    if (apart) continue;
    McdUserTriangle &o = out[count++];
    for (int k = 0; k < 3; ++k) o.vertices[k] = &s.v[s.tri[3 * t + k]].p;
    o.normal = &s.normal;
    o.triangleData.tag = t;
    o.flags = kMcdTriangleUseSmallestPenetration;
  }
  return count;
}

// Speeds along the slope, one per step, of a ball of radius 0.5 rolling
// from rest for `seconds`.
std::vector<double> RollDown(bool triangles, double seconds, double h, int *trianglesServed) {
  Universe U;
  MstUniverseID u = U.u;
  MdtWorldSetGravity(u->world, 0, 0, -kG);
  MdtContactParamsID p =
      MstBridgeGetContactParams(u->bridge, MstBridgeGetDefaultMaterial(), MstBridgeGetDefaultMaterial());
  MdtContactParamsSetType(p, MdtContactTypeFriction2D);
  MdtContactParamsSetFriction(p, 1);
  MdtContactParamsSetRestitution(p, 0);
  const double th = kSlopeDeg * M_PI / 180;
  const MeReal c = (MeReal)std::cos(th), sn = (MeReal)std::sin(th);
  Slope slope;
  MeMatrix4 tm;
  McdModelID ground;
  if (triangles) {
    const double cell = 0.5, x0 = -2, x1 = 20, y0 = -2, y1 = 2;
    const int nx = (int)((x1 - x0) / cell), ny = (int)((y1 - y0) / cell);
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        MeVector3 q;
        q[0] = (MeReal)(x0 + i * cell);
        q[1] = (MeReal)(y0 + j * cell);
        q[2] = (MeReal)(-(x0 + i * cell) * std::tan(th));
        Slope::V vv;
        MeVector3Copy(vv.p, q);
        slope.v.push_back(vv);
      }
    slope.normal[0] = sn;
    slope.normal[1] = 0;
    slope.normal[2] = c;
    auto at = [&](int i, int j) { return j * (nx + 1) + i; };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        // counter-clockwise seen from above: normals up
        const int a = at(i, j), b = at(i + 1, j), cc = at(i + 1, j + 1), d = at(i, j + 1);
        const int t2[6] = {a, b, cc, a, cc, d};
        for (int k = 0; k < 6; ++k) slope.tri.push_back(t2[k]);
      }
    for (size_t t = 0; t < slope.tri.size() / 3; ++t)
      for (int j = 0; j < 3; ++j) {
        MeReal lo = 1e9, hi = -1e9;
        for (int k = 0; k < 3; ++k) {
          lo = std::min(lo, slope.v[slope.tri[3 * t + k]].p[j]);
          hi = std::max(hi, slope.v[slope.tri[3 * t + k]].p[j]);
        }
        slope.lo.push_back(lo);
        slope.hi.push_back(hi);
      }
    gSlope = &slope;
    MeVector3 mn = {(MeReal)x0, (MeReal)y0, (MeReal)(-x1 * std::tan(th) - 0.1)};
    MeVector3 mx = {(MeReal)x1, (MeReal)y1, (MeReal)(-x0 * std::tan(th) + 0.1)};
    McdTriangleListID tl = McdTriangleListCreate(u->frame, mn, mx, 64, SlopeTriangles);
    MeMatrix4TMMakeIdentity(tm);
    ground = MstFixedModelCreate(u, tl, tm);
  } else {
    const MeReal x[3] = {c, 0, -sn}, y[3] = {0, 1, 0}, z[3] = {sn, 0, c}, o[3] = {0, 0, 0};
    TMFromAxes(tm, x, y, z, o);
    ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), tm);
  }
  (void)ground;
  const MeReal r = (MeReal)0.5;
  McdModelID ball = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, r), 1);
  MdtBodyID b = McdModelGetBody(ball);
  // Touching the slope at the origin (a grid vertex, away from any snag at start).
  MdtBodySetPosition(b, r * sn + (MeReal)0.1, 0, r * c - (MeReal)0.1 * sn / c);
  std::vector<double> speeds;
  const int n = (int)(seconds / h);
  for (int i = 0; i < n; ++i) {
    MstUniverseStep(u, (MeReal)h);
    MeVector3 vel;
    MdtBodyGetLinearVelocity(b, vel);
    speeds.push_back(vel[0] * c - vel[2] * sn);
  }
  if (trianglesServed) *trianglesServed = slope.calls;
  gSlope = nullptr;
  return speeds;
}

// Least-squares slope of v(t) over [from, end).
double FitAcceleration(const std::vector<double> &v, double h, size_t from) {
  double st = 0, sv = 0, stt = 0, stv = 0;
  const double n = (double)(v.size() - from);
  for (size_t i = from; i < v.size(); ++i) {
    const double t = (i + 1) * h;
    st += t;
    sv += v[i];
    stt += t * t;
    stv += t * v[i];
  }
  return (n * stv - st * sv) / (n * stt - st * st);
}

}  // namespace

TEST(MstScenes, SphereRollsDownATriangleListSlopeWithoutSnagging) {
  const double h = 0.01, seconds = 3;
  const double expected = kG * std::sin(kSlopeDeg * M_PI / 180) * 5 / 7;
  int calls = 0;
  const std::vector<double> tri = RollDown(true, seconds, h, &calls);
  const std::vector<double> flat = RollDown(false, seconds, h, nullptr);
  double worstDrop = 0;
  for (size_t i = 1; i < tri.size(); ++i) worstDrop = std::max(worstDrop, tri[i - 1] - tri[i]);
  double worstDropFlat = 0;
  for (size_t i = 1; i < flat.size(); ++i) worstDropFlat = std::max(worstDropFlat, flat[i - 1] - flat[i]);
  const double aTri = FitAcceleration(tri, h, 10), aFlat = FitAcceleration(flat, h, 10);
  std::printf(
      "[ figures  ] rolling %.0f deg: expected a = %.4f; triangle list a = %.4f (end speed %.4f, "
      "worst step drop %.5f m/s, %d callbacks); tilted plane a = %.4f (end speed %.4f, worst "
      "drop %.5f)\n",
      kSlopeDeg, expected, aTri, tri.back(), worstDrop, calls, aFlat, flat.back(), worstDropFlat);
  EXPECT_GT(calls, 0);
  EXPECT_LT(worstDrop, 0.005) << "the ball snagged on an edge between triangles";
  EXPECT_NEAR(aTri, expected, 0.03 * expected);
  EXPECT_NEAR(aFlat, expected, 0.03 * expected);
  EXPECT_NEAR(aTri, aFlat, 0.02 * expected);
}

// ---------------------------------------------------------------------------
// 5. Restitution e: a dropped sphere bounces to e^2 h.
namespace {
double Bounce(MeReal e, MeReal dropHeight, MeReal h) {
  Universe U;
  MstUniverseID u = U.u;
  MdtWorldSetGravity(u->world, 0, 0, -kG);
  MeMatrix4 groundTM;
  MeMatrix4TMMakeIdentity(groundTM);
  McdModelID ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  const MeReal r = (MeReal)0.25;
  McdModelID ball = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, r), 1);
  const MstMaterialID bm = MstBridgeGetNewMaterial(u->bridge), fm = MstBridgeGetNewMaterial(u->bridge);
  MdtContactParamsID p = MstBridgeGetContactParams(u->bridge, bm, fm);
  MdtContactParamsSetRestitution(p, e);
  MdtContactParamsSetRestitutionThreshold(p, (MeReal)0.1);  // impact ~4.4 m/s
  McdModelSetMaterial(ball, bm);
  McdModelSetMaterial(ground, fm);
  MdtBodyID b = McdModelGetBody(ball);
  MdtBodySetPosition(b, 0, 0, dropHeight + r);
  bool up = false;
  double top = 0;
  const int n = (int)(2 * std::sqrt(2 * dropHeight / kG) / h) + 50;
  for (int i = 0; i < n; ++i) {
    MstUniverseStep(u, h);
    MeVector3 pos, v;
    MdtBodyGetPosition(b, pos);
    MdtBodyGetLinearVelocity(b, v);
    if (v[2] > 0) up = true;
    if (up && v[2] < 0) break;  // past the top of the first bounce
    if (up) top = std::max(top, (double)pos[2] - r);
  }
  return top;
}
}  // namespace

TEST(MstScenes, RestitutionBouncesToESquaredH) {
  const MeReal dropH = 1;
  for (MeReal e : {(MeReal)0.5, (MeReal)0.8}) {
    for (MeReal h : {(MeReal)0.01, (MeReal)0.002}) {
      const double top = Bounce(e, dropH, h);
      // The apex semi-implicit Euler reaches after leaving at speed
      // u = e sqrt(2 g H): u^2 / 2g - u h / 2 (positions advance with
      // each step's new velocity), i.e. e^2 H less u h / 2.
      const double u = (double)e * std::sqrt(2 * (double)kG * (double)dropH);
      const double want = u * u / (2 * (double)kG) - u * (double)h / 2;
      std::printf(
          "[ figures  ] restitution %.1f, step %.3f: bounce to %.4f m (e^2 h = %.4f, "
          "discrete apex %.4f, %+.2f%%)\n",
          (double)e, (double)h, top, (double)(e * e * dropH), want, 100 * (top - want) / want);
      EXPECT_NEAR(top, want, 0.02 * want) << "e = " << e << ", h = " << h;
    }
  }
}
