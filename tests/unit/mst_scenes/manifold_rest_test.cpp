// manifold_rest_test.cpp: issue 12's resting-stack scenes through Mst at
// 60 Hz, for the box-box manifolds (engine/mcd/nearfield/box_box.cpp):
//  - two 0.5 m cubes stacked on a plane with every relative yaw from 0 to
//    45 degrees in 1 degree steps rest for 10 s with at most 1 mm
//    penetration, and so do they with the upper cube also tilted by 0.5
//    degree and placed 1 mm clear (it tips flat);
//  - a column of 10 cubes with small random yaws and tilts (pile1000's:
//    yaw within +-0.3 rad, tilts within +-0.1 rad), each placed 1 mm above
//    the one below so that it tips flat onto it, stands for 20 s with at
//    most 2 mm penetration once settled (after 3 s).
// Penetration is the deepest contact the bridge hands to the solver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "Mst.h"
#include "scene_spec.h"

namespace {

constexpr MeReal kStep = (MeReal)1 / 60;
constexpr MeReal kSide = (MeReal)0.5;

// Rotation rows of Ry(yaw) Rx(a) Rz(b) (rows: body axes in world, y up),
// as the anchor scenes' pile builds them (scene_spec.h).
void Orientation(MeMatrix3 R, double yaw, double a, double b) {
  const karma::scenes::Axes axes = karma::scenes::TiltAxes(yaw, a, b);
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 3; ++i) R[axis][i] = (MeReal)axes[(size_t)axis][(size_t)i];
}
// A universe with y up, a ground plane y = 0 and one material of friction
// 0.4 and no restitution (pile1000's), auto-disable off.
struct Scene {
  MstUniverseID u;
  MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  McdGeometryID cube;
  std::vector<MdtBodyID> bodies;
  Scene() {
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    u = MstUniverseCreate(&sizes);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, -(MeReal)9.81, 0);
    MdtWorldSetAutoDisable(w, 0);
    MstBridgeID bridge = MstUniverseGetBridge(u);
    MdtContactParamsID p = MstBridgeGetContactParams(bridge, 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoefficient(p, (MeReal)0.4);
    MdtContactParamsSetRestitution(p, 0);
    MstFixedModelCreate(u, McdPlaneCreate(MstUniverseGetFramework(u)), groundTM);
    cube = McdBoxCreate(MstUniverseGetFramework(u), kSide, kSide, kSide);
  }
  ~Scene() { MstUniverseDestroy(u); }
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;
  MdtBodyID addCube(double x, double y, double z, double yaw, double a, double b) {
    const MeReal density = 5 / McdGeometryGetVolume(cube);  // 5 kg
    McdModelID m = MstModelAndBodyCreate(u, cube, density);
    MdtBodyID body = McdModelGetBody(m);
    MdtBodySetPosition(body, (MeReal)x, (MeReal)y, (MeReal)z);
    MeMatrix3 R;
    Orientation(R, yaw, a, b);
    MdtBodySetOrientation(body, R);
    bodies.push_back(body);
    return body;
  }
  void step() { MstUniverseStep(u, kStep); }
  // The deepest penetration among the contacts handed to the solver.
  double deepest() const {
    double d = 0;
    for (MdtBodyID b : bodies)
      for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c))
        d = std::max(d, (double)MdtContactGetPenetration(c));
    return d;
  }
};

// A fixed pseudo-random sequence in [-1, 1) (64-bit LCG, top bits).
struct Sequence {
  std::uint64_t state = 0x6d616e69666f6cull;
  double next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(state >> 11) / (double)(1ull << 52) - 1;
  }
};

double Horizontal(const MeVector3 a, const MeVector3 b) {
  return std::hypot((double)(a[0] - b[0]), (double)(a[2] - b[2]));
}

}  // namespace

TEST(ManifoldRest, TwoCubesAtEveryYawRestWithin1mm) {
  double worstPen = 0, worstDrift = 0, worstSink = 0;
  int worstYaw = -1;
  for (int deg = 0; deg <= 45; ++deg) {
    Scene s;
    s.addCube(0, 0.25, 0, 0, 0, 0);
    MdtBodyID top = s.addCube(0, 0.75, 0, deg * M_PI / 180, 0, 0);
    MeVector3 start, end;
    MdtBodyGetPosition(top, start);
    double pen = 0;
    int fewest = 99, most = 0;       // contacts of the top cube (all with the lower one)
    for (int i = 0; i < 600; ++i) {  // 10 s
      s.step();
      pen = std::max(pen, s.deepest());
      int n = 0;
      for (MdtContactID c = MdtBodyGetFirstContact(top); c; c = MdtBodyGetNextContact(top, c)) ++n;
      fewest = std::min(fewest, n), most = std::max(most, n);
    }
    // A face contact every step: 3 or 4 points, never one edge point.
    EXPECT_GE(fewest, 3) << deg << " degrees";
    EXPECT_LE(most, 4) << deg << " degrees";
    MdtBodyGetPosition(top, end);
    const double drift = Horizontal(start, end), sink = (double)(start[1] - end[1]);
    if (pen > worstPen) worstPen = pen, worstYaw = deg;
    worstDrift = std::max(worstDrift, drift);
    worstSink = std::max(worstSink, sink);
    EXPECT_LE(pen, 1e-3) << deg << " degrees";
    EXPECT_LT(drift, 1e-3) << deg << " degrees";
  }
  std::printf(
      "[ figures  ] two cubes, yaw 0..45 deg, 10 s at 60 Hz: worst penetration %.3f mm "
      "(at %d deg), worst top drift %.3f mm, worst top sink %.3f mm\n",
      worstPen * 1e3, worstYaw, worstDrift * 1e3, worstSink * 1e3);
}

TEST(ManifoldRest, TenCubeColumnWithRandomTiltsStandsWithin2mm) {
  Scene s;
  Sequence random;
  MdtBodyID top = nullptr;
  double y = 0;  // the top of the column so far
  for (int j = 0; j < 10; ++j) {
    const double yaw = 0.3 * random.next(), a = 0.1 * random.next(), b = 0.1 * random.next();
    MeMatrix3 R;
    Orientation(R, yaw, a, b);
    // Half the cube's vertical extent: sum over its axes of h |axis.y|.
    double half = 0;
    for (int k = 0; k < 3; ++k) half += 0.5 * kSide * std::fabs((double)R[k][1]);
    top = s.addCube(0, y + half + 1e-3, 0, yaw, a, b);  // 1 mm clear of the one below
    y += 2 * half + 1e-3;
  }
  const int landing = 180;  // 3 s to tip flat onto the one below and settle
  double pen = 0, landedPen = 0;
  MeVector3 landed = {0, 0, 0}, end;
  for (int i = 0; i < 1200; ++i) {  // 20 s
    s.step();
    const double d = s.deepest();
    pen = std::max(pen, d);
    if (i == landing) MdtBodyGetPosition(top, landed);
    if (i >= landing) landedPen = std::max(landedPen, d);
  }
  MdtBodyGetPosition(top, end);
  // Standing: the top cube is still about nine cubes up and above the base.
  const MeVector3 base = {0, 0, 0};
  const double height = (double)end[1], offset = Horizontal(end, base);
  const double drift = Horizontal(end, landed);
  std::printf(
      "[ figures  ] 10-cube column, 20 s at 60 Hz: penetration %.3f mm after 3 s "
      "(%.3f mm while settling), top at y = %.4f (9.5 cubes = 4.75), %.1f mm off the "
      "axis, drift after 3 s %.3f mm\n",
      landedPen * 1e3, pen * 1e3, height, offset * 1e3, drift * 1e3);
  EXPECT_GT(height, 4.5) << "the column fell";
  EXPECT_LT(offset, 0.25) << "the column fell";
  EXPECT_LE(landedPen, 2e-3);
}

// The same with the upper cube also tilted by 0.5 degree about x and z,
// placed 1 mm clear of the lower one: it tips flat and rests.
TEST(ManifoldRest, TwoCubesAtEveryYawWithATiltSettleWithin1mm) {
  double worstPen = 0, worstDrift = 0;
  int worstYaw = -1;
  const double tilt = 0.5 * M_PI / 180;
  for (int deg = 0; deg <= 45; ++deg) {
    Scene s;
    s.addCube(0, 0.25, 0, 0, 0, 0);
    // Half the vertical extent of the tilted cube: h (|cos a cos b| + ...).
    MeMatrix3 R;
    Orientation(R, deg * M_PI / 180, tilt, tilt);
    double half = 0;
    for (int k = 0; k < 3; ++k) half += 0.5 * kSide * std::fabs((double)R[k][1]);
    MdtBodyID top = s.addCube(0, 0.5 + half + 1e-3, 0, deg * M_PI / 180, tilt, tilt);
    MeVector3 settled, end;
    double pen = 0;
    int fewest = 99;
    for (int i = 0; i < 600; ++i) {  // 10 s; the first second to tip flat
      s.step();
      if (i == 60) MdtBodyGetPosition(top, settled);
      if (i < 60) continue;
      pen = std::max(pen, s.deepest());
      int n = 0;
      for (MdtContactID c = MdtBodyGetFirstContact(top); c; c = MdtBodyGetNextContact(top, c)) ++n;
      fewest = std::min(fewest, n);
    }
    MdtBodyGetPosition(top, end);
    const double drift = Horizontal(settled, end);
    if (pen > worstPen) worstPen = pen, worstYaw = deg;
    worstDrift = std::max(worstDrift, drift);
    EXPECT_GE(fewest, 3) << deg << " degrees";
    EXPECT_LE(pen, 1e-3) << deg << " degrees";
    EXPECT_LT(drift, 1e-3) << deg << " degrees";
  }
  std::printf(
      "[ figures  ] two cubes, yaw 0..45 deg, tilt 0.5 deg, 1..10 s at 60 Hz: worst "
      "penetration %.3f mm (at %d deg), worst top drift %.3f mm\n",
      worstPen * 1e3, worstYaw, worstDrift * 1e3);
}
