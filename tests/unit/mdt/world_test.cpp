// world_test.cpp: world creation, defaults (Appendix A), scaling, the body
// pool and the public params block.
#include "mdt_test_support.h"

extern "C" int mdt_c_api_check(void);

using namespace mdt_test;

TEST(MdtWorld, CApiFromC) { EXPECT_EQ(mdt_c_api_check(), 1); }

TEST(MdtWorld, DefaultsUnitScales) {
  World w(4, 1, 1);
  ASSERT_NE(w.id, nullptr);
  MeVector3 g;
  MdtWorldGetGravity(w, g);
  EXPECT_EQ(g[0], 0);
  EXPECT_EQ(g[1], 0);
  EXPECT_EQ(g[2], 0);
  EXPECT_EQ(MdtWorldGetEpsilon(w), (MeReal)0.01);
  EXPECT_EQ(MdtWorldGetGamma(w), (MeReal)0.2);
  const MdtWorldParams &p = w.id->params;
  EXPECT_TRUE(p.autoDisable);
  EXPECT_EQ(p.velocityThreshold, (MeReal)0.02);
  EXPECT_EQ(p.angularVelocityThreshold, (MeReal)0.001);
  EXPECT_EQ(p.accelerationThreshold, (MeReal)0.5);
  EXPECT_EQ(p.angularAccelerationThreshold, (MeReal)0.002);
  EXPECT_EQ(p.aliveWindow, (MeReal)0.2);
  EXPECT_EQ(p.minSafeTime, (MeReal)0.001);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  EXPECT_EQ(MdtWorldGetBodyCount(w), 0u);
  EXPECT_EQ(MdtWorldGetMaxBodies(w), 4u);
}

TEST(MdtWorld, DefaultsScale) {
  World w(1, 2, 5);
  EXPECT_FLOAT_EQ(MdtWorldGetEpsilon(w), 0.01f / 5);
  EXPECT_FLOAT_EQ(w.id->params.velocityThreshold, 0.04f);
  EXPECT_FLOAT_EQ(w.id->params.accelerationThreshold, 1.0f);
  MdtBodyID b = MdtBodyCreate(w);
  EXPECT_EQ(MdtBodyGetMass(b), (MeReal)5);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(I[i][j], i == j ? 0.4f * 5 * 4 : 0.0f);
}

TEST(MdtWorld, ParamsWrittenDirectlyAreUsed) {
  World w(1);
  w.id->params.gravity[1] = -(MeReal)9.81;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtWorldStep(w, (MeReal)0.5);
  MeVector3 v;
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_EQ(v[1], (MeReal)0.5 * -(MeReal)9.81);
}

TEST(MdtWorld, SettersAndRejections) {
  World w(1);
  WarningCapture cap;
  MdtWorldSetGravity(w, 1, 2, 3);
  MdtWorldSetEpsilon(w, (MeReal)0.5);
  MdtWorldSetGamma(w, (MeReal)0.7);
  EXPECT_EQ(cap.count(), 0u);
  MdtWorldSetGravity(w, NAN, 0, 0);
  MdtWorldSetEpsilon(w, -1);
  MdtWorldSetGamma(w, INFINITY);
  MdtWorldStep(w, 0);
  MdtWorldStep(w, NAN);
  MdtWorldStep(nullptr, 1);
  EXPECT_EQ(cap.count(), 6u);
  EXPECT_NE(cap.last().find("MdtWorldStep"), std::string::npos);
  MeVector3 g;
  MdtWorldGetGravity(w, g);
  EXPECT_EQ(g[0], 1);
  EXPECT_EQ(g[2], 3);
  EXPECT_EQ(MdtWorldGetEpsilon(w), (MeReal)0.5);
  EXPECT_EQ(MdtWorldGetGamma(w), (MeReal)0.7);
  EXPECT_EQ(MdtWorldCreate(1, 0, 0, 1), nullptr);
  EXPECT_EQ(MdtWorldCreate(1, 0, 1, -1), nullptr);
  EXPECT_NE(cap.last().find("MdtWorldCreate"), std::string::npos);
}

TEST(MdtWorld, GammaAboveOneIsKeptWithAWarning) {
  // Gamma is a fraction per step; the guide's stacking sample writes 5 (a
  // rate): accepted, but the caller is told it over-corrects.
  World w(1);
  WarningCapture cap;
  MdtWorldSetGamma(w, 1);
  EXPECT_EQ(cap.count(), 0u);
  MdtWorldSetGamma(w, 5);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_NE(cap.last().find("r * h"), std::string::npos);
  EXPECT_EQ(MdtWorldGetGamma(w), 5);
}

TEST(MdtWorld, PoolExhaustionReturnsNullWithOneWarning) {
  World w(2);
  WarningCapture cap;
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodyID b = MdtBodyCreate(w);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(cap.count(), 0u);
  EXPECT_EQ(MdtBodyCreate(w), nullptr);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_EQ(MdtBodyCreate(w), nullptr);
  EXPECT_EQ(cap.count(), 1u);
  MdtBodyDestroy(a);
  EXPECT_NE(MdtBodyCreate(w), nullptr);
  EXPECT_EQ(MdtWorldGetBodyCount(w), 2u);
}

TEST(MdtWorld, ZeroBodyWorld) {
  WarningCapture cap;
  World w(0);
  ASSERT_NE(w.id, nullptr);
  EXPECT_EQ(MdtBodyCreate(w), nullptr);
  MdtWorldStep(w, (MeReal)0.01);
  EXPECT_EQ(cap.count(), 1u);
}

TEST(MdtWorld, EnabledCount) {
  World w(4);
  MdtBodyID a = MdtBodyCreate(w);
  MdtBodyID b = MdtBodyCreate(w);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  MdtBodyEnable(a);
  MdtBodyEnable(a);
  MdtBodyEnable(b);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 2u);
  MdtBodyDisable(a);
  MdtBodyDisable(a);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 1u);
  MdtBodyDestroy(b);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  EXPECT_EQ(MdtWorldGetBodyCount(w), 1u);
}
