// body_test.cpp: body defaults, accessors, the live TM and rejected input.
#include <cstring>

#include "mdt_test_support.h"

using namespace mdt_test;

TEST(MdtBody, Defaults) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  ASSERT_NE(b, nullptr);
  EXPECT_FALSE(MdtBodyIsEnabled(b));
  EXPECT_EQ(MdtBodyGetWorld(b), w.id);
  EXPECT_EQ(MdtBodyGetMass(b), 1);
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(I[i][j], i == j ? (MeReal)0.4 : 0);
  MeVector3 v;
  MeVector4 q;
  MdtBodyGetPosition(b, v);
  EXPECT_TRUE(v[0] == 0 && v[1] == 0 && v[2] == 0);
  MdtBodyGetQuaternion(b, q);
  EXPECT_TRUE(q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0);
  MeMatrix4 tm;
  MdtBodyGetTransform(b, tm);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(tm[i][j], i == j ? 1 : 0);
  MdtBodyGetFastSpinAxis(b, v);
  EXPECT_TRUE(v[0] == 0 && v[1] == 1 && v[2] == 0);
  EXPECT_FALSE(MdtBodyIsFastSpinAxisEnabled(b));
  MdtBodyGetLinearVelocity(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  MdtBodyGetAngularVelocity(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  MdtBodyGetLinearAcceleration(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  MdtBodyGetAngularAcceleration(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  MdtBodyGetForce(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  MdtBodyGetTorque(b, v);
  EXPECT_EQ(MeVector3MagnitudeSqr(v), 0);
  EXPECT_EQ(MdtBodyGetLinearVelocityDamping(b), 0);
  EXPECT_EQ(MdtBodyGetAngularVelocityDamping(b), 0);
  EXPECT_EQ(MdtBodyGetUserData(b), nullptr);
  EXPECT_EQ(MdtBodyGetSortKey(b), 0);
}

TEST(MdtBody, TransformPtrIsLive) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
  MdtBodySetPosition(b, 1, 2, 3);
  EXPECT_EQ(MdtBodyGetTransformPtr(b), tm);
  EXPECT_EQ(tm[3][0], 1);
  EXPECT_EQ(tm[3][1], 2);
  EXPECT_EQ(tm[3][2], 3);
  // +90 degrees about z carries body x onto world y: row 0 is (0, 1, 0).
  const MeReal s = MeSqrt((MeReal)0.5);
  MdtBodySetQuaternion(b, s, 0, 0, s);
  EXPECT_NEAR(tm[0][1], 1, 1e-6);
  EXPECT_NEAR(tm[1][0], -1, 1e-6);
  MdtBodyEnable(b);
  MdtBodySetLinearVelocity(b, 1, 0, 0);
  MdtWorldStep(w, 1);
  EXPECT_EQ(MdtBodyGetTransformPtr(b), tm);
  EXPECT_EQ(tm[3][0], 2);
}

TEST(MdtBody, QuaternionNormalisedAndOrientationRoundTrip) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetQuaternion(b, 2, 0, 0, 0);
  MeVector4 q;
  MdtBodyGetQuaternion(b, q);
  EXPECT_EQ(q[0], 1);
  MeMatrix3 R, R2;
  MeMatrix3MakeRotationX(R, (MeReal)0.3);
  MdtBodySetOrientation(b, R);
  MdtBodyGetOrientation(b, R2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(R[i][j], R2[i][j], 1e-6);
  MdtBodyGetQuaternion(b, q);
  EXPECT_NEAR(q[0], std::cos(0.15), 1e-6);
  EXPECT_NEAR(q[1], std::sin(0.15), 1e-6);
}

TEST(MdtBody, MassAndInertia) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetMass(b, 3);
  EXPECT_EQ(MdtBodyGetMass(b), 3);
  MeMatrix3 I = {{2, (MeReal)0.1, 0}, {(MeReal)0.1, 3, 0}, {0, 0, 4}};
  MdtBodySetInertiaTensor(b, I);
  MeMatrix3 out;
  MdtBodyGetInertiaTensor(b, out);
  EXPECT_EQ(std::memcmp(I, out, sizeof I), 0);
  MdtBodySetUserData(b, &w);
  EXPECT_EQ(MdtBodyGetUserData(b), &w);
  MdtBodySetSortKey(b, -7);
  EXPECT_EQ(MdtBodyGetSortKey(b), -7);
  MdtBodySetLinearVelocityDamping(b, (MeReal)0.5);
  MdtBodySetAngularVelocityDamping(b, (MeReal)0.25);
  EXPECT_EQ(MdtBodyGetLinearVelocityDamping(b), (MeReal)0.5);
  EXPECT_EQ(MdtBodyGetAngularVelocityDamping(b), (MeReal)0.25);
  MdtBodySetFastSpinAxis(b, 0, 0, 2);
  MeVector3 a;
  MdtBodyGetFastSpinAxis(b, a);
  EXPECT_TRUE(a[0] == 0 && a[1] == 0 && a[2] == 1);
  EXPECT_TRUE(MdtBodyIsFastSpinAxisEnabled(b));
  MdtBodyDisableFastSpinAxis(b);
  EXPECT_FALSE(MdtBodyIsFastSpinAxisEnabled(b));
}

TEST(MdtBody, BadInputRejectedWithNamedWarning) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 2, 3);
  MdtBodySetLinearVelocity(b, 4, 5, 6);
  MdtBodyEnable(b);
  MdtBodySetMass(b, 2);
  unsigned char before[512];
  MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
  MeVector3 pos, vel;
  MdtBodyGetPosition(b, pos);
  MdtBodyGetLinearVelocity(b, vel);
  std::memcpy(before, tm, sizeof(MeMatrix4));

  WarningCapture cap;
  struct Case {
    const char *name;
    void (*call)(MdtBodyID);
  };
  const Case cases[] = {
      {"MdtBodySetPosition", [](MdtBodyID x) { MdtBodySetPosition(x, NAN, 0, 0); }},
      {"MdtBodySetPosition", [](MdtBodyID x) { MdtBodySetPosition(x, 0, INFINITY, 0); }},
      {"MdtBodySetLinearVelocity", [](MdtBodyID x) { MdtBodySetLinearVelocity(x, 0, 0, NAN); }},
      {"MdtBodySetAngularVelocity", [](MdtBodyID x) { MdtBodySetAngularVelocity(x, -INFINITY, 0, 0); }},
      {"MdtBodySetQuaternion", [](MdtBodyID x) { MdtBodySetQuaternion(x, 0, 0, 0, 0); }},
      {"MdtBodySetQuaternion", [](MdtBodyID x) { MdtBodySetQuaternion(x, NAN, 0, 0, 0); }},
      {"MdtBodySetMass", [](MdtBodyID x) { MdtBodySetMass(x, 0); }},
      {"MdtBodySetMass", [](MdtBodyID x) { MdtBodySetMass(x, -1); }},
      {"MdtBodySetMass", [](MdtBodyID x) { MdtBodySetMass(x, NAN); }},
      {"MdtBodySetInertiaTensor",
       [](MdtBodyID x) {
         MeMatrix3 I = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
         MdtBodySetInertiaTensor(x, I);
       }},
      {"MdtBodySetInertiaTensor",
       [](MdtBodyID x) {
         MeMatrix3 I = {{1, 2, 0}, {2, 1, 0}, {0, 0, 1}};  // symmetric, indefinite
         MdtBodySetInertiaTensor(x, I);
       }},
      {"MdtBodySetInertiaTensor",
       [](MdtBodyID x) {
         MeMatrix3 I = {{1, (MeReal)0.5, 0}, {0, 1, 0}, {0, 0, 1}};  // not symmetric
         MdtBodySetInertiaTensor(x, I);
       }},
      {"MdtBodySetOrientation",
       [](MdtBodyID x) {
         MeMatrix3 R = {{2, 0, 0}, {0, 1, 0}, {0, 0, 1}};
         MdtBodySetOrientation(x, R);
       }},
      {"MdtBodyAddForce", [](MdtBodyID x) { MdtBodyAddForce(x, NAN, 0, 0); }},
      {"MdtBodyAddTorque", [](MdtBodyID x) { MdtBodyAddTorque(x, 0, INFINITY, 0); }},
      {"MdtBodyAddForceAtPosition", [](MdtBodyID x) { MdtBodyAddForceAtPosition(x, 1, 0, 0, 0, NAN, 0); }},
      {"MdtBodyAddImpulse", [](MdtBodyID x) { MdtBodyAddImpulse(x, 0, 0, NAN); }},
      {"MdtBodyAddImpulseAtPosition", [](MdtBodyID x) { MdtBodyAddImpulseAtPosition(x, INFINITY, 0, 0, 0, 0, 0); }},
      {"MdtBodySetLinearVelocityDamping", [](MdtBodyID x) { MdtBodySetLinearVelocityDamping(x, -1); }},
      {"MdtBodySetAngularVelocityDamping", [](MdtBodyID x) { MdtBodySetAngularVelocityDamping(x, NAN); }},
      {"MdtBodySetFastSpinAxis", [](MdtBodyID x) { MdtBodySetFastSpinAxis(x, 0, 0, 0); }},
  };
  for (const Case &c : cases) {
    cap.clear();
    c.call(b);
    ASSERT_EQ(cap.count(), 1u) << c.name;
    EXPECT_NE(cap.last().find(c.name), std::string::npos) << cap.last();
  }
  // Nothing changed.
  EXPECT_EQ(std::memcmp(before, tm, sizeof(MeMatrix4)), 0);
  MeVector3 v2, f;
  MdtBodyGetLinearVelocity(b, v2);
  EXPECT_EQ(std::memcmp(vel, v2, sizeof vel), 0);
  EXPECT_EQ(MdtBodyGetMass(b), 2);
  MdtBodyGetForce(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  MdtBodyGetImpulse(b, f);
  EXPECT_EQ(MeVector3MagnitudeSqr(f), 0);
  EXPECT_FALSE(MdtBodyIsFastSpinAxisEnabled(b));
  MeMatrix3 I;
  MdtBodyGetInertiaTensor(b, I);
  EXPECT_EQ(I[1][1], (MeReal)0.4);

  // NULL bodies: a warning, no crash.
  cap.clear();
  MdtBodySetPosition(nullptr, 0, 0, 0);
  MdtBodyEnable(nullptr);
  MdtBodyAddForce(nullptr, 1, 0, 0);
  EXPECT_EQ(MdtBodyGetMass(nullptr), 0);
  EXPECT_EQ(MdtBodyGetTransformPtr(nullptr), nullptr);
  EXPECT_EQ(MdtBodyCreate(nullptr), nullptr);
  EXPECT_EQ(cap.count(), 6u);
  MdtBodyDestroy(nullptr);  // accepted silently
  EXPECT_EQ(cap.count(), 6u);

  // The state stays finite through a step.
  MdtWorldStep(w, (MeReal)0.01);
  MdtBodyGetPosition(b, pos);
  EXPECT_TRUE(MeVector3AllFinite(pos));
}
