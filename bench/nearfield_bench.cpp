// Nearfield benchmarks: McdIntersect on one pair of models per interaction
// family, in a touching (resting or slightly penetrating) pose, with a
// 16-contact buffer. The pair is created and helloed once; only
// McdIntersect is timed. Every geometry is about unit size, z up (the plane
// is z = 0, solid below).
//
// Times are per McdIntersect call in microseconds. The "contacts" counter is
// the number of contacts the call returns (at most 16), "touch" its return
// value. BM_BoxBoxSeparated is the early-out cost of a pair that does not
// touch. Run e.g.
//   build/bench/bench/nearfield_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include "Mcd.h"

#include <memory>
#include <vector>

namespace {

constexpr int kContactMax = 16;
constexpr MeReal kHalfPi = MeReal(1.5707963267948966);

// A heap TM (models keep pointers to their TMs).
struct TM {
  MeMatrix4 m;
  TM(MeReal x, MeReal y, MeReal z) {
    MeMatrix4TMMakeIdentity(m);
    MeMatrix4TMSetPosition(m, x, y, z);
  }
  TM &rotate(MeReal ax, MeReal ay, MeReal az, MeReal angle) {
    MeVector3 a = {ax, ay, az};
    MeVector3Normalize(a);
    MeMatrix3 R;
    MeMatrix3FromAxisAngle(R, a, angle);
    MeMatrix4TMSetRotation(m, R);
    return *this;
  }
};

// The triangle list floor: the square [-5, 5]^2 at z = 0 as two triangles
// cut along the diagonal, which is a smooth edge (its edge flags cleared).
MeVector3 gCorner[4] = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
MeVector3 gUp = {0, 0, 1};

int MEAPI FloorTriangles(McdModelPair *, McdUserTriangle *t, MeVector3, MeReal, int max) {
  static const int idx[2][3] = {{0, 1, 2}, {0, 2, 3}};
  static const int flags[2] = {kMcdTriangleStandard & ~kMcdTriangleUseEdge2,
                               kMcdTriangleStandard & ~kMcdTriangleUseEdge0};
  const int n = max < 2 ? max : 2;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) t[i].vertices[k] = &gCorner[idx[i][k]];
    t[i].normal = &gUp;
    t[i].triangleData.ptr = nullptr;
    t[i].flags = flags[i];
  }
  return n;
}

// One framework with every built-in type and interaction, and the
// geometries, made on first use and kept for the whole run.
struct Shapes {
  McdFrameworkID fw;
  McdGeometryID sphere, plane, box, wideBox, cylinder, sphyl, hull, stool, floor;
  std::vector<std::unique_ptr<TM>> stoolTMs;  // the elements' relTMs (kept by pointer)

  Shapes() {
    fw = McdInit(0, 16, 64, 1);
    McdPrimitivesRegisterTypes(fw);
    McdPrimitivesRegisterInteractions(fw);
    sphere = McdSphereCreate(fw, MeReal(0.5));
    plane = McdPlaneCreate(fw);
    box = McdBoxCreate(fw, 1, 1, 1);
    wideBox = McdBoxCreate(fw, 2, 2, 1);
    cylinder = McdCylinderCreate(fw, MeReal(0.5), 1);
    sphyl = McdSphylCreate(fw, MeReal(0.3), 1);
    const MeVector3 cube[8] = {{-0.5, -0.5, -0.5}, {0.5, -0.5, -0.5}, {0.5, 0.5, -0.5}, {-0.5, 0.5, -0.5},
                               {-0.5, -0.5, 0.5},  {0.5, -0.5, 0.5},  {0.5, 0.5, 0.5},  {-0.5, 0.5, 0.5}};
    hull = McdConvexMeshCreateHull(fw, cube, 8, 0);
    // A stool: a 1 x 1 x 0.1 seat on four legs of radius 0.05 and height
    // 0.5, standing on its frame's z = 0.
    stool = McdAggregateCreate(fw, 5);
    stoolTMs.emplace_back(new TM(0, 0, MeReal(0.55)));
    McdAggregateAddElement(stool, McdBoxCreate(fw, 1, 1, MeReal(0.1)), stoolTMs.back()->m);
    McdGeometryID leg = McdCylinderCreate(fw, MeReal(0.05), MeReal(0.5));
    for (MeReal x : {MeReal(-0.4), MeReal(0.4)})
      for (MeReal y : {MeReal(-0.4), MeReal(0.4)}) {
        stoolTMs.emplace_back(new TM(x, y, MeReal(0.25)));
        McdAggregateAddElement(stool, leg, stoolTMs.back()->m);
      }
    MeVector3 mn = {-5, -5, -1}, mx = {5, 5, 0};
    floor = McdTriangleListCreate(fw, mn, mx, 2, FloorTriangles);
  }
};

Shapes &S() {
  static Shapes shapes;
  return shapes;
}

// Times McdIntersect on (g1 at tm1, g2 at tm2).
void Run(benchmark::State &state, McdGeometryID g1, TM tm1, McdGeometryID g2, TM tm2) {
  McdModelID m1 = McdModelCreate(g1), m2 = McdModelCreate(g2);
  McdModelSetTransformPtr(m1, tm1.m);
  McdModelSetTransformPtr(m2, tm2.m);
  McdModelUpdate(m1);
  McdModelUpdate(m2);
  McdModelPair *pair = McdModelPairCreate(m1, m2);
  McdHello(pair);
  McdContact contacts[kContactMax];
  McdIntersectResult r{};
  int touch = 0;
  for (auto _ : state) {
    r.contacts = contacts;
    r.contactMaxCount = kContactMax;
    touch = McdIntersect(pair, &r);
    benchmark::DoNotOptimize(touch);
    benchmark::ClobberMemory();
  }
  state.counters["contacts"] = r.contactCount;
  state.counters["touch"] = touch;
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  McdModelDestroy(m1);
  McdModelDestroy(m2);
}

const TM kOrigin(0, 0, 0);

// Analytic primitive pairs.
void BM_SphereSphere(benchmark::State &st) { Run(st, S().sphere, TM(0, 0, MeReal(0.95)), S().sphere, kOrigin); }
void BM_SpherePlane(benchmark::State &st) { Run(st, S().sphere, TM(0, 0, MeReal(0.45)), S().plane, kOrigin); }
void BM_BoxPlane(benchmark::State &st) { Run(st, S().box, TM(0, 0, MeReal(0.49)), S().plane, kOrigin); }
void BM_SphereBox(benchmark::State &st) { Run(st, S().sphere, TM(0, 0, MeReal(0.95)), S().box, kOrigin); }
// The sphere against the cylinder's side.
void BM_SphereCylinder(benchmark::State &st) { Run(st, S().sphere, TM(MeReal(0.95), 0, 0), S().cylinder, kOrigin); }
void BM_SphereSphyl(benchmark::State &st) { Run(st, S().sphere, TM(MeReal(0.75), 0, 0), S().sphyl, kOrigin); }
// A unit cube resting face down on another, 0.01 deep.
void BM_BoxBoxResting(benchmark::State &st) { Run(st, S().box, TM(0, 0, MeReal(0.99)), S().box, kOrigin); }
// The upper cube tilted 30 degrees about (1, 1, 0): a corner digs in.
void BM_BoxBoxTilted(benchmark::State &st) {
  Run(st, S().box, TM(0, 0, MeReal(1.1)).rotate(1, 1, 0, MeReal(0.5236)), S().box, kOrigin);
}
// 0.5 apart: the early-out.
void BM_BoxBoxSeparated(benchmark::State &st) { Run(st, S().box, TM(0, 0, MeReal(1.5)), S().box, kOrigin); }
// Two lying sphyls crossing at right angles (along x below, along y above).
void BM_SphylSphyl(benchmark::State &st) {
  Run(st, S().sphyl, TM(0, 0, MeReal(0.58)).rotate(1, 0, 0, kHalfPi), S().sphyl, TM(0, 0, 0).rotate(0, 1, 0, kHalfPi));
}
// A sphyl lying along x on the 2 x 2 x 1 box's top face.
void BM_SphylBox(benchmark::State &st) {
  Run(st, S().sphyl, TM(0, 0, MeReal(0.79)).rotate(0, 1, 0, kHalfPi), S().wideBox, kOrigin);
}
// A standing cylinder (rim points).
void BM_CylinderPlane(benchmark::State &st) { Run(st, S().cylinder, TM(0, 0, MeReal(0.49)), S().plane, kOrigin); }
// A lying sphyl.
void BM_SphylPlane(benchmark::State &st) {
  Run(st, S().sphyl, TM(0, 0, MeReal(0.29)).rotate(0, 1, 0, kHalfPi), S().plane, kOrigin);
}

// Convex pairs (GJK/EPA and a clipped manifold).
void BM_ConvexBox(benchmark::State &st) { Run(st, S().hull, TM(0, 0, MeReal(0.99)), S().box, kOrigin); }
void BM_ConvexConvex(benchmark::State &st) { Run(st, S().hull, TM(0, 0, MeReal(0.99)), S().hull, kOrigin); }
// A standing cylinder on the 2 x 2 x 1 box.
void BM_BoxCylinder(benchmark::State &st) { Run(st, S().wideBox, kOrigin, S().cylinder, TM(0, 0, MeReal(0.99))); }
// A standing cylinder on another.
void BM_CylinderCylinder(benchmark::State &st) { Run(st, S().cylinder, TM(0, 0, MeReal(0.99)), S().cylinder, kOrigin); }
void BM_ConvexPlane(benchmark::State &st) { Run(st, S().hull, TM(0, 0, MeReal(0.49)), S().plane, kOrigin); }

// The stool standing on the plane, legs 0.01 deep (the seat clear).
void BM_AggregatePlane(benchmark::State &st) { Run(st, S().stool, TM(0, 0, MeReal(-0.01)), S().plane, kOrigin); }

// The two-triangle floor.
void BM_SphereTriangleList(benchmark::State &st) {
  Run(st, S().sphere, TM(MeReal(0.1), MeReal(0.2), MeReal(0.45)), S().floor, kOrigin);
}
void BM_BoxTriangleList(benchmark::State &st) {
  Run(st, S().box, TM(MeReal(0.3), MeReal(0.1), MeReal(0.49)), S().floor, kOrigin);
}

#define NF_BENCH(fn) BENCHMARK(fn)->Unit(benchmark::kMicrosecond)
NF_BENCH(BM_SphereSphere);
NF_BENCH(BM_SpherePlane);
NF_BENCH(BM_BoxPlane);
NF_BENCH(BM_SphereBox);
NF_BENCH(BM_SphereCylinder);
NF_BENCH(BM_SphereSphyl);
NF_BENCH(BM_BoxBoxResting);
NF_BENCH(BM_BoxBoxTilted);
NF_BENCH(BM_BoxBoxSeparated);
NF_BENCH(BM_SphylSphyl);
NF_BENCH(BM_SphylBox);
NF_BENCH(BM_CylinderPlane);
NF_BENCH(BM_SphylPlane);
NF_BENCH(BM_ConvexBox);
NF_BENCH(BM_ConvexConvex);
NF_BENCH(BM_BoxCylinder);
NF_BENCH(BM_CylinderCylinder);
NF_BENCH(BM_ConvexPlane);
NF_BENCH(BM_AggregatePlane);
NF_BENCH(BM_SphereTriangleList);
NF_BENCH(BM_BoxTriangleList);

}  // namespace
