// Bad input to the Prismatic, Universal, Angular3, ConeLimit, Linear1/2 and
// FixedPath APIs: a warning and no effect. Type casts and names.
#include <cmath>

#include "joints_a_support.h"

using namespace mdt_test;

namespace {

struct OneBody {
  World w;
  MdtBodyID b;
  OneBody() : b(makeBody(w, 0, 0, 0)) {}
};

}  // namespace

TEST(JointsAInput, ZeroAxesAreRejectedWithAWarning) {
  OneBody s;
  WarningCapture warnings;
  MeVector3 a;

  MdtPrismaticID p = MdtPrismaticCreate(s.w);
  MdtPrismaticSetBodies(p, s.b, nullptr);
  MdtPrismaticSetAxis(p, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 1u);
  EXPECT_NE(warnings.last().find("MdtPrismaticSetAxis"), std::string::npos);
  MdtPrismaticGetAxis(p, a);
  EXPECT_EQ(a[0], 1);

  MdtUniversalID u = MdtUniversalCreate(s.w);
  MdtUniversalSetBodies(u, s.b, nullptr);
  MdtUniversalSetAxis(u, 1, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 2u);
  MdtUniversalSetAxis(u, 2, 0, 0, 1);  // no body 2
  EXPECT_EQ(warnings.count(), 3u);
  MdtUniversalSetAxes(u, 0, 1, 0, 0, 1, 0, 0);  // not orthogonal
  EXPECT_EQ(warnings.count(), 4u);
  EXPECT_NE(warnings.last().find("MdtUniversalSetAxes"), std::string::npos);
  MdtUniversalGetAxis(u, 1, a);
  EXPECT_EQ(a[1], 1);

  MdtAngular3ID g = MdtAngular3Create(s.w);
  MdtAngular3SetBodies(g, s.b, nullptr);
  MdtAngular3SetAxis(g, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 5u);
  MdtAngular3SetAxis(g, NAN, 0, 1);
  EXPECT_EQ(warnings.count(), 6u);
  MdtAngular3SetStiffness(g, -1);
  EXPECT_EQ(warnings.count(), 7u);
  EXPECT_EQ(MdtAngular3GetStiffness(g), MEINFINITY);

  MdtConeLimitID c = MdtConeLimitCreate(s.w);
  MdtConeLimitSetBodies(c, s.b, nullptr);
  MdtConeLimitSetAxis(c, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 8u);
  MdtConeLimitSetConeHalfAngle(c, -1);
  MdtConeLimitSetConeHalfAngle(c, 4);
  EXPECT_EQ(warnings.count(), 10u);
  EXPECT_NEAR(MdtConeLimitGetConeHalfAngle(c), M_PI, 1e-6);
  MdtConeLimitSetDamping(c, -2);
  EXPECT_EQ(warnings.count(), 11u);

  MdtLinear1ID l1 = MdtLinear1Create(s.w);
  MdtLinear1SetBodies(l1, s.b, nullptr);
  MdtLinear1SetAxis(l1, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 12u);
  MdtLinear2ID l2 = MdtLinear2Create(s.w);
  MdtLinear2SetBodies(l2, s.b, nullptr);
  MdtLinear2SetDirection(l2, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 13u);
  MdtLinear2GetDirection(l2, a);
  EXPECT_EQ(a[0], 1);

  MdtFixedPathID f = MdtFixedPathCreate(s.w);
  MdtFixedPathSetBodies(f, s.b, nullptr);
  MdtFixedPathSetVelocity(f, 0, INFINITY, 0, 0);
  MdtFixedPathSetPosition(f, 3, 0, 0, 0);
  EXPECT_EQ(warnings.count(), 15u);
  MdtFixedPathGetVelocity(f, 0, a);
  EXPECT_EQ(a[0], 0);
}

TEST(JointsAInput, WrongTypeIsRejected) {
  OneBody s;
  MdtPrismaticID p = MdtPrismaticCreate(s.w);
  MdtHingeID h = MdtHingeCreate(s.w);
  MdtConstraintID pc = MdtPrismaticQuaConstraint(p);
  MdtConstraintID hc = MdtHingeQuaConstraint(h);
  EXPECT_EQ(MdtConstraintDCastPrismatic(pc), p);
  EXPECT_EQ(MdtConstraintDCastPrismatic(hc), nullptr);
  EXPECT_EQ(MdtConstraintDCastUniversal(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastAngular3(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastConeLimit(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastLinear1(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastLinear2(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastFixedPath(pc), nullptr);
  EXPECT_EQ(MdtConstraintDCastPrismatic(nullptr), nullptr);
  // The typed API refuses a constraint of another type.
  WarningCapture warnings;
  MdtAngular3SetAxis((MdtAngular3ID)hc, 0, 0, 1);
  EXPECT_EQ(warnings.count(), 1u);
  EXPECT_NE(warnings.last().find("where Angular3 was expected"), std::string::npos);
  EXPECT_EQ(MdtPrismaticGetLimit(nullptr), nullptr);
  EXPECT_EQ(warnings.count(), 2u);
}

TEST(JointsAInput, TypesAndNames) {
  OneBody s;
  EXPECT_EQ(MdtConstraintGetType(MdtPrismaticQuaConstraint(MdtPrismaticCreate(s.w))), MdtConstraintTypePrismatic);
  EXPECT_EQ(MdtConstraintGetType(MdtUniversalQuaConstraint(MdtUniversalCreate(s.w))), MdtConstraintTypeUniversal);
  EXPECT_EQ(MdtConstraintGetType(MdtFixedPathQuaConstraint(MdtFixedPathCreate(s.w))), MdtConstraintTypeFixedPath);
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypePrismatic), "Prismatic");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeUniversal), "Universal");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeAngular3), "Angular3");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeConeLimit), "ConeLimit");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeLinear1), "Linear1");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeLinear2), "Linear2");
  EXPECT_STREQ(MdtConstraintTypeName(MdtConstraintTypeFixedPath), "FixedPath");
}

TEST(JointsAInput, ResetRestoresDefaults) {
  OneBody s;
  MdtAngular3ID g = MdtAngular3Create(s.w);
  MdtAngular3SetBodies(g, s.b, nullptr);
  MdtAngular3SetStiffness(g, 3);
  MdtAngular3EnableRotation(g, TRUE);
  MdtAngular3Reset(g);
  EXPECT_EQ(MdtAngular3GetStiffness(g), MEINFINITY);
  EXPECT_FALSE(MdtAngular3RotationIsEnabled(g));
  EXPECT_EQ(MdtAngular3GetBody(g, 0), s.b);
  MdtConeLimitID c = MdtConeLimitCreate(s.w);
  MdtConeLimitSetBodies(c, s.b, nullptr);
  MdtConeLimitSetConeHalfAngle(c, 1);
  MdtConeLimitReset(c);
  EXPECT_NEAR(MdtConeLimitGetConeHalfAngle(c), M_PI, 1e-6);
  MdtFixedPathID f = MdtFixedPathCreate(s.w);
  MdtFixedPathSetBodies(f, s.b, nullptr);
  MdtFixedPathSetVelocity(f, 1, 1, 2, 3);
  MdtFixedPathReset(f);
  MeVector3 v;
  MdtFixedPathGetVelocity(f, 1, v);
  EXPECT_EQ(MeVector3Magnitude(v), 0);
}
