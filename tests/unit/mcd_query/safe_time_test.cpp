// McdSafeTime: times of impact against closed forms for moving and turning
// models, the unsupported pairs, and bad input.
#include <cmath>

#include "query_test_support.h"

namespace {

using mcd_query_test::Scene;
using mcd_query_test::Warnings;

// The safe time of two placed models with the given velocities.
struct Timed {
  MeBool supported;
  MeReal time;
};

Timed safeTime(McdModelID a, McdModelID b, MeReal maxTime) {
  McdModelPair *pair = McdModelPairCreate(a, b);
  McdHello(pair);
  McdSafeTimeResult r{};
  Timed t;
  t.supported = McdSafeTime(pair, maxTime, &r);
  t.time = r.time;
  EXPECT_EQ(r.pair, pair);
  McdGoodbye(pair);
  McdModelPairDestroy(pair);
  return t;
}

// The framework's touch tolerance lets contact start up to 1e-5 early.
constexpr double kEarly = 2e-5;

TEST(SafeTime, SpheresClosingHeadOn) {
  Scene s;
  McdGeometryID ball = McdSphereCreate(s.fw(), 1);
  McdModelID a = s.place(ball, 0, 0, 0), b = s.place(ball, 5, 0, 0);
  MeVector3 v = {10, 0, 0};
  McdModelSetLinearVelocityPtr(a, v);
  const Timed t = safeTime(a, b, 1);
  EXPECT_TRUE(t.supported);
  // The centres close from 5 to 2 at 10 m/s: contact at 0.3 s.
  EXPECT_LE(t.time, 0.3);
  EXPECT_GT(t.time, 0.3 - kEarly / 10);
  // Shorter horizon than the impact: the whole horizon is safe.
  EXPECT_EQ(safeTime(a, b, (MeReal)0.25).time, (MeReal)0.25);
}

TEST(SafeTime, FastSmallSphereDoesNotTunnelThroughAThinBall) {
  Scene s;
  McdModelID bullet = s.place(McdSphereCreate(s.fw(), (MeReal)0.01), 0, 0, 0);
  McdModelID target = s.place(McdSphereCreate(s.fw(), (MeReal)0.02), 5, 0, 0);
  MeVector3 v = {1000, 0, 0};
  McdModelSetLinearVelocityPtr(bullet, v);
  // One 10 ms step moves the bullet 10 m, past the target; contact at
  // x = 5 - 0.03, i.e. t = 4.97 ms.
  const Timed t = safeTime(bullet, target, (MeReal)0.01);
  EXPECT_TRUE(t.supported);
  EXPECT_LE(t.time, 4.97e-3 + 1e-9);
  EXPECT_GT(t.time, 4.97e-3 - 1e-6);
}

TEST(SafeTime, SphereFallingOnAPlaneEitherOrder) {
  Scene s;
  McdModelID plane = s.place(McdPlaneCreate(s.fw()), 0, 0, 0);
  McdModelID ball = s.place(McdSphereCreate(s.fw(), 1), 2, 3, 3);
  MeVector3 v = {0, 0, -4};
  McdModelSetLinearVelocityPtr(ball, v);
  for (const Timed t : {safeTime(ball, plane, 1), safeTime(plane, ball, 1)}) {
    EXPECT_TRUE(t.supported);
    EXPECT_LE(t.time, 0.5);
    EXPECT_GT(t.time, 0.5 - kEarly / 4);
  }
}

TEST(SafeTime, TurningBoxReachesThePlane) {
  Scene s;
  McdModelID plane = s.place(McdPlaneCreate(s.fw()), 0, 0, 0);
  McdModelID bar = s.place(McdBoxCreate(s.fw(), 4, (MeReal)0.2, (MeReal)0.2), 0, 0, 1);
  MeVector3 w = {0, 1, 0};  // its +x end swings down
  McdModelSetAngularVelocityPtr(bar, w);
  // Lowest corner (2, *, -0.1) after turning by a: z = 1 - 2 sin a - 0.1 cos a.
  const double lead = std::atan2(0.1, 2.0);
  const double angle = std::asin(1 / std::sqrt(4.01)) - lead;
  const Timed t = safeTime(bar, plane, 2);
  EXPECT_TRUE(t.supported);
  EXPECT_LE(t.time, angle + 1e-6);
  EXPECT_GT(t.time, angle - 1e-4);
}

TEST(SafeTime, AlreadyTouchingIsZeroAndApartAtRestIsMaxTime) {
  Scene s;
  McdGeometryID ball = McdSphereCreate(s.fw(), 1);
  McdModelID a = s.place(ball, 0, 0, 0), b = s.place(ball, (MeReal)1.5, 0, 0);
  EXPECT_EQ(safeTime(a, b, 1).time, 0);
  McdModelID c = s.place(ball, 10, 0, 0);
  EXPECT_EQ(safeTime(a, c, 1).time, 1);
}

TEST(SafeTime, UnsupportedPairReportsMaxTimeAndZero) {
  Scene s;
  McdModelID a = s.place(McdSphylCreate(s.fw(), 1, 1), 0, 0, 0);
  McdModelID b = s.place(McdSphereCreate(s.fw(), 1), 1, 0, 0);
  const Timed t = safeTime(a, b, (MeReal)0.75);
  EXPECT_FALSE(t.supported);
  EXPECT_EQ(t.time, (MeReal)0.75);
}

TEST(SafeTime, BadInputWarns) {
  Scene s;
  McdGeometryID ball = McdSphereCreate(s.fw(), 1);
  McdModelID a = s.place(ball, 0, 0, 0), b = s.place(ball, 5, 0, 0);
  McdModelPair *pair = McdModelPairCreate(a, b);
  McdSafeTimeResult r{};
  Warnings w;
  EXPECT_FALSE(McdSafeTime(pair, 1, &r));  // no hello yet
  EXPECT_NE(w.last().find("McdHello"), std::string::npos);
  McdHello(pair);
  EXPECT_FALSE(McdSafeTime(pair, -1, &r));
  EXPECT_EQ(r.time, 0);
  EXPECT_FALSE(McdSafeTime(nullptr, 1, &r));
  EXPECT_FALSE(McdSafeTime(pair, 1, nullptr));
  EXPECT_EQ(w.count(), 4u);
  McdModelPairDestroy(pair);
}

}  // namespace
