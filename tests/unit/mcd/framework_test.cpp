// framework_test.cpp: McdInit / McdTerm, type registration and the
// registration bundles.
#include "mcd_test_support.h"

using namespace mcd_test;

namespace {

TEST(McdFramework, InitRegisterTerm) {
  McdFrameworkID fw = McdInit(0, 50, 0, 1);  // the guide's call
  ASSERT_NE(fw, nullptr);
  EXPECT_EQ(McdFrameworkGetModelMaxCount(fw), 50);
  EXPECT_EQ(McdFrameworkGetLengthScale(fw), 1);
  EXPECT_NEAR(McdFrameworkGetContactTolerance(fw), 1e-5, 1e-9);
  for (int t = 0; t < kMcdGeometryBuiltInTypes; ++t) EXPECT_FALSE(McdFrameworkIsTypeRegistered(fw, t));
  McdPrimitivesRegisterTypes(fw);
  McdPrimitivesRegisterInteractions(fw);
  for (int t = 0; t < kMcdGeometryBuiltInTypes; ++t) EXPECT_TRUE(McdFrameworkIsTypeRegistered(fw, t));
  EXPECT_STREQ(McdFrameworkGetTypeName(fw, kMcdGeometryTypeSphyl), "Sphyl");
  EXPECT_EQ(McdPrimitivesGetTypeCount(), 8);
  McdGeometryID box = McdBoxCreate(fw, 2, 1, 3);
  EXPECT_STREQ(McdGeometryGetTypeName(box), "Box");
  EXPECT_EQ(McdGeometryGetTypeId(box), kMcdGeometryTypeBox);
  EXPECT_EQ(McdGeometryGetFramework(box), fw);
  MeReal dx, dy, dz;
  McdBoxGetDimensions(box, &dx, &dy, &dz);
  EXPECT_EQ(dx, 2);
  EXPECT_EQ(dz, 3);
  McdTerm(fw);  // frees the box too (ASan checks)
}

TEST(McdFramework, UnregisteredTypesCannotBeCreated) {
  Framework fw(8, 8, 1, false);
  McdSphereBoxPlaneRegisterTypes(fw);
  WarningCapture w;
  EXPECT_NE(McdSphereCreate(fw, 1), nullptr);
  EXPECT_NE(McdBoxCreate(fw, 1, 1, 1), nullptr);
  EXPECT_NE(McdPlaneCreate(fw), nullptr);
  EXPECT_EQ(w.count(), 0u);
  EXPECT_EQ(McdCylinderCreate(fw, 1, 1), nullptr);
  EXPECT_TRUE(w.lastMentions("McdCylinderCreate"));
  EXPECT_TRUE(w.lastMentions("not registered"));
  McdCylinderRegisterType(fw);
  EXPECT_NE(McdCylinderCreate(fw, 1, 1), nullptr);
  // Interactions need both types registered.
  McdInteractions fns{};
  fns.intersectFn = [](McdModelPair *, McdIntersectResult *) -> int { return 0; };
  McdFrameworkSetInteraction(fw, kMcdGeometryTypeSphyl, kMcdGeometryTypeBox, &fns);
  EXPECT_TRUE(w.lastMentions("registered first"));
  EXPECT_EQ(McdFrameworkGetInteraction(fw, kMcdGeometryTypeSphyl, kMcdGeometryTypeBox), nullptr);
}

TEST(McdFramework, UserTypeSlotsAndBadInit) {
  McdFrameworkID fw = McdInit(3, 1, 0, (MeReal)0.01);
  ASSERT_NE(fw, nullptr);
  EXPECT_NEAR(McdFrameworkGetContactTolerance(fw), 1e-7, 1e-10);
  EXPECT_FALSE(McdFrameworkIsTypeRegistered(fw, kMcdGeometryBuiltInTypes + 2));
  EXPECT_FALSE(McdFrameworkIsTypeRegistered(fw, kMcdGeometryBuiltInTypes + 3));
  McdTerm(fw);
  WarningCapture w;
  EXPECT_EQ(McdInit(-1, 1, 1, 1), nullptr);
  EXPECT_TRUE(w.lastMentions("McdInit"));
  EXPECT_EQ(McdInit(0, 1, 1, 0), nullptr);
  EXPECT_EQ(McdInit(0, 1, 1, NAN), nullptr);
  EXPECT_EQ(w.count(), 3u);
  McdTerm(nullptr);
}

}  // namespace
