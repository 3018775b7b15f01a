// guide_forms_test.cpp: the guide writes colours both as float[4] and as
// MeReal[4]; both forms must work from C (c_api_check.c) and C++ in either
// precision (MeViewerColor.h).
#include "viewer_test_support.h"

using viewer_test::MakeContext;

namespace {

class GuideForms : public ::testing::Test {
 protected:
  void SetUp() override {
    rc = MakeContext("prog -null");
    ASSERT_NE(rc, nullptr);
  }
  void TearDown() override { RRenderContextDestroy(rc); }
  RRender *rc = nullptr;
};

}  // namespace

extern "C" int ViewerCApiCheck(RRender *rc);

namespace {

TEST_F(GuideForms, GuideColourArgumentsWorkFromCInEitherPrecision) {
  EXPECT_EQ(ViewerCApiCheck(rc), 8);
  EXPECT_EQ(rc->m_pRG_First->m_pObject->m_ColorAmbient[1], 1);  // the last SetColor, white
}

TEST_F(GuideForms, GuideColourArgumentsWorkFromCxx) {
  MeReal red[] = {1, 0, 0, 0};
  const float white[4] = {1, 1, 1, 1};
  RGraphic *a = RGraphicSphereCreate(rc, 1, red, nullptr);
  RGraphic *b = RGraphicSphereCreate(rc, 1, white, nullptr);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(a->m_pObject->m_ColorDiffuse[0], 1);
  EXPECT_EQ(a->m_pObject->m_ColorDiffuse[1], 0);
  EXPECT_EQ(b->m_pObject->m_ColorDiffuse[1], 1);
  const AcmeReal s[3] = {0, 0, 0}, e[3] = {1, 0, 0};
  EXPECT_NE(RNLineCreate(rc, s, e, white, nullptr), nullptr);
  EXPECT_NE(RNLineCreate(rc, s, e, red, nullptr), nullptr);
}

}  // namespace
