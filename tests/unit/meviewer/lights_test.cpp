// lights_test.cpp: the lighting rules of the guide, seen in rendered pixels.
// A white sphere fills the middle of a 64x64 frame; the test reads the
// centre pixel after changing the lights.
//  - The ambient colour applies from the next frame, no flag needed.
//  - A changed light structure applies only once its m_bForce...Update flag
//    is set; the renderer then clears the flag.
//  - RLightSwitchOn/Off (and the RSwitchLight spellings) raise the flag.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <array>

using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

class Lights : public ::testing::Test {
 protected:
  void SetUp() override {
    rc = MakeContext("prog -size 64x64");
    ASSERT_NE(rc, nullptr);
    const float white[4] = {1, 1, 1, 1};
    ASSERT_NE(RGraphicSphereCreate(rc, 3, white, nullptr), nullptr);
    // Only directional light 1, shining straight at the camera's side.
    RLightSwitchOff(rc, kRDirect2);
    rc->m_bUseAmbientLight = 0;
    rc->m_DirectLight1.m_Direction[0] = 0, rc->m_DirectLight1.m_Direction[1] = 0;
    rc->m_DirectLight1.m_Direction[2] = -1;
    rc->m_DirectLight1.m_rgbSpecular[0] = rc->m_DirectLight1.m_rgbSpecular[1] = rc->m_DirectLight1.m_rgbSpecular[2] = 0;
  }
  void TearDown() override { RRenderContextDestroy(rc); }
  // Red, green, blue of the centre pixel after drawing a frame.
  std::array<int, 3> Centre() {
    karma::viewer::Image img;
    rc->m_pPrivate->backend->DrawFrame(rc);
    EXPECT_TRUE(rc->m_pPrivate->backend->ReadFrame(img));
    const std::uint8_t *p = img.pixels.data() + (32 * 64 + 32) * 3;
    return {p[0], p[1], p[2]};
  }
  RRender *rc = nullptr;
};

TEST_F(Lights, DirectionalLightChangesWaitForTheirFlag) {
  const auto lit = Centre();  // 0.7 diffuse, facing the light: about 178
  EXPECT_NEAR(lit[0], 178, 3);
  rc->m_DirectLight1.m_rgbDiffuse[0] = 0;  // no flag: not applied
  EXPECT_EQ(Centre(), lit);
  rc->m_bForceDirectLight1Update = 1;
  const auto changed = Centre();
  EXPECT_LT(changed[0], 5);
  EXPECT_EQ(changed[1], lit[1]);
  EXPECT_EQ(rc->m_bForceDirectLight1Update, 0);  // cleared by the renderer
}

TEST_F(Lights, AmbientAppliesNextFrame) {
  RLightSwitchOff(rc, kRDirect1);
  EXPECT_EQ(rc->m_bForceDirectLight1Update, 1);
  EXPECT_EQ(Centre()[1], 0);  // no light at all
  rc->m_bUseAmbientLight = 1;
  rc->m_rgbAmbientLightColor[1] = 0.5f;
  rc->m_rgbAmbientLightColor[0] = rc->m_rgbAmbientLightColor[2] = 0;
  const auto c = Centre();  // ambient 0.5 times material ambient 1
  EXPECT_NEAR(c[1], 128, 2);
  EXPECT_EQ(c[0], 0);
}

TEST_F(Lights, PointLightFallsOffWithAttenuation) {
  RLightSwitchOff(rc, kRDirect1);
  RSwitchLightOn(rc, kRPoint);
  RPointLight &p = rc->m_PointLight;
  p.m_Position[0] = 0, p.m_Position[1] = 0, p.m_Position[2] = 7;  // 4 in front of the sphere's surface
  p.m_rgbSpecular[0] = p.m_rgbSpecular[1] = p.m_rgbSpecular[2] = 0;
  const int full = Centre()[0];  // attenuation 1: diffuse 1 head-on
  EXPECT_GE(full, 250);
  p.m_AttenuationConstant = 1, p.m_AttenuationLinear = 0,
  p.m_AttenuationQuadratic = 0.25f;  // 1 / (1 + 0.25 * 16) = 0.2
  rc->m_bForcePointLightUpdate = 1;
  EXPECT_NEAR(Centre()[0], 51, 2);
}

TEST(LightsBadInput, UnknownLightWarns) {
  Messages m;
  RRender *rc = MakeContext("prog -null");
  RLightSwitchOn(rc, static_cast<RRenderLight>(9));
  EXPECT_TRUE(Messages::Warned("is not a light"));
  RLightSwitchOn(nullptr, kRPoint);
  EXPECT_TRUE(Messages::Warned("RLightSwitchOn"));
  RRenderContextDestroy(rc);
}

}  // namespace

namespace {

// The guide: vertex edits show in the next frame, and the renderer fills
// each header's m_Matrix from the graphic's transform.
TEST(Drawing, VertexEditsShowNextFrameAndTheMatrixIsCopied) {
  RRender *rc = MakeContext("prog -size 64x64");
  ASSERT_NE(rc, nullptr);
  const float white[4] = {1, 1, 1, 1};
  MeMatrix4 tm;
  MeMatrix4TMMakeIdentity(tm);
  RGraphic *sq = RGraphicSquareCreate(rc, 2, white, tm);
  ASSERT_NE(sq, nullptr);
  auto centre = [&] {
    karma::viewer::Image img;
    rc->m_pPrivate->backend->DrawFrame(rc);
    EXPECT_TRUE(rc->m_pPrivate->backend->ReadFrame(img));
    return int(img.pixels[(32 * 64 + 32) * 3]);
  };
  const int background = int(0.2f * 255 + 0.5f);
  EXPECT_GT(centre(), background + 20);                                                  // the square covers the centre
  for (int i = 0; i < sq->m_pObject->m_nNumVertices; ++i) sq->m_pVertices[i].m_X += 50;  // move it away
  EXPECT_NEAR(centre(), background, 1);
  MeMatrix4TMSetPosition(tm, -50, 0, 0);  // the transform brings it back
  EXPECT_GT(centre(), background + 20);
  EXPECT_EQ(sq->m_pObject->m_Matrix[3][0], -50);
  RRenderContextDestroy(rc);
}

}  // namespace
