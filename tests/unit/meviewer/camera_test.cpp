// camera_test.cpp: the spherical camera against positions worked out by hand
// from P = L + d (cos phi sin theta, sin phi, cos phi cos theta).
#include "viewer_test_support.h"

#include <cmath>

using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

constexpr double kTol = 1e-5;

class Camera : public ::testing::Test {
 protected:
  void SetUp() override {
    rc = MakeContext("prog -null");
    ASSERT_NE(rc, nullptr);
  }
  void TearDown() override { RRenderContextDestroy(rc); }
  void ExpectPosition(double x, double y, double z) {
    AcmeVector3 p;
    RCameraGetPosition(rc, p);
    EXPECT_NEAR(p[0], x, kTol);
    EXPECT_NEAR(p[1], y, kTol);
    EXPECT_NEAR(p[2], z, kTol);
  }
  void ExpectLookAt(double x, double y, double z) {
    AcmeVector3 l;
    RCameraGetLookAt(rc, l);
    EXPECT_NEAR(l[0], x, kTol);
    EXPECT_NEAR(l[1], y, kTol);
    EXPECT_NEAR(l[2], z, kTol);
  }
  RRender *rc = nullptr;
};

TEST_F(Camera, DefaultLooksAtTheOriginFromTenAlongZ) {
  ExpectPosition(0, 0, 10);
  ExpectLookAt(0, 0, 0);
  EXPECT_NEAR(rc->m_CameraUp[1], 1, kTol);
}

TEST_F(Camera, SetViewQuarterTurnPutsTheCameraOnX) {
  RCameraSetView(rc, 5, ME_HALF_PI, 0);
  ExpectPosition(5, 0, 0);  // theta = pi/2: sin 1, cos 0
}

TEST_F(Camera, SetViewGeneralCase) {
  // L = (1, 2, 3), d = 4, theta = pi/6, phi = pi/3:
  // dir = (0.5 * 0.5, sqrt(3)/2, 0.5 * sqrt(3)/2) = (0.25, 0.8660254, 0.4330127)
  const AcmeVector3 L = {1, 2, 3};
  RCameraSetLookAt(rc, L);
  RCameraSetView(rc, 4, ME_PI / 6, ME_PI / 3);
  ExpectPosition(1 + 4 * 0.25, 2 + 4 * 0.8660254, 3 + 4 * 0.4330127);
  ExpectLookAt(1, 2, 3);
}

TEST_F(Camera, TopViewHasAWellDefinedUp) {
  RCameraSetView(rc, 2, 0, ME_HALF_PI);
  ExpectPosition(0, 2, 0);
  // up = (-sin phi sin theta, cos phi, -sin phi cos theta) = (0, 0, -1)
  EXPECT_NEAR(rc->m_CameraUp[0], 0, kTol);
  EXPECT_NEAR(rc->m_CameraUp[1], 0, kTol);
  EXPECT_NEAR(rc->m_CameraUp[2], -1, kTol);
}

TEST_F(Camera, ZoomAddsToTheDistanceAndStopsAtOneHundredth) {
  RCameraZoom(rc, 2);
  ExpectPosition(0, 0, 12);
  RCameraZoom(rc, -50);
  EXPECT_NEAR(rc->m_CameraDist, 0.01, 1e-7);
  ExpectPosition(0, 0, 0.01);
  RCameraSetView(rc, -3, 0, 0);
  EXPECT_NEAR(rc->m_CameraDist, 0.01, 1e-7);
}

TEST_F(Camera, RotationsWrapThetaAndClampPhi) {
  RCameraSetView(rc, 1, 3, 1.5);
  RCameraRotateAngle(rc, 0.5);
  EXPECT_NEAR(rc->m_CameraTheta, 3.5 - 2 * M_PI, kTol);
  RCameraRotateElevation(rc, 0.2);
  EXPECT_NEAR(rc->m_CameraPhi, M_PI / 2, kTol);
  RCameraRotateElevation(rc, -4);
  EXPECT_NEAR(rc->m_CameraPhi, -M_PI / 2, kTol);
}

TEST_F(Camera, GuideRainbowChainMoves) {
  // RainbowChain: elevation 1.1, angle 0.2, zoom 10 from the default (d = 10).
  RCameraRotateElevation(rc, (MeReal)1.1);
  RCameraRotateAngle(rc, (MeReal)0.2);
  RCameraZoom(rc, 10);
  const double d = 20, c = std::cos(1.1), s = std::sin(1.1);
  ExpectPosition(d * c * std::sin(0.2), d * s, d * c * std::cos(0.2));
}

TEST_F(Camera, PansMoveLookAtAndCameraTogether) {
  RCameraPanX(rc, 2);  // right = (1, 0, 0) at theta = 0
  ExpectLookAt(2, 0, 0);
  ExpectPosition(2, 0, 10);
  RCameraPanY(rc, 1);  // up = (0, 1, 0) at phi = 0
  ExpectLookAt(2, 1, 0);
  RCameraPanZ(rc, 3);  // forward = (0, 0, -1)
  ExpectLookAt(2, 1, -3);
  ExpectPosition(2, 1, 7);
  // At theta = pi/2 the right vector is (0, 0, -1).
  RCameraSetView(rc, 10, ME_HALF_PI, 0);
  RCameraPanX(rc, 1);
  ExpectLookAt(2, 1, -4);
}

TEST_F(Camera, MatrixTakesTheCameraToTheOriginAndTheLookAtDownMinusZ) {
  const AcmeVector3 L = {1, -2, 0.5};
  RCameraSetLookAt(rc, L);
  RCameraSetView(rc, 3, 0.7, -0.4);
  AcmeVector3 P;
  RCameraGetPosition(rc, P);
  auto apply = [&](const AcmeReal *p, double out[3]) {
    for (int j = 0; j < 3; ++j)
      out[j] = p[0] * rc->m_CameraMatrix[0][j] + p[1] * rc->m_CameraMatrix[1][j] + p[2] * rc->m_CameraMatrix[2][j] +
               rc->m_CameraMatrix[3][j];
  };
  double a[3], b[3];
  apply(P, a);
  apply(L, b);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[j], 0, kTol);
  EXPECT_NEAR(b[0], 0, kTol);
  EXPECT_NEAR(b[1], 0, kTol);
  EXPECT_NEAR(b[2], -3, kTol);
}

TEST_F(Camera, UpdateAfterWritingMembersDirectly) {
  rc->m_CameraDist = 2;
  rc->m_CameraTheta = ME_PI;  // behind: -z
  rc->m_CameraPhi = 0;
  RCameraUpdate(rc);
  EXPECT_NEAR(rc->m_CameraPos[2], -2, kTol);
  EXPECT_NEAR(rc->m_CameraPos[0], 0, kTol);
}

TEST(CameraBadInput, NullContextWarnsAndDoesNothing) {
  Messages m;
  AcmeVector3 p = {7, 7, 7};
  RCameraGetPosition(nullptr, p);
  RCameraZoom(nullptr, 1);
  RCameraUpdate(nullptr);
  EXPECT_EQ(p[0], 7);
  EXPECT_TRUE(Messages::Warned("RCameraGetPosition"));
  EXPECT_TRUE(Messages::Warned("RCameraZoom"));
}

TEST(CameraBadInput, NonFiniteAnglesFallBackToZero) {
  Messages m;
  RRender *rc = MakeContext("prog -null");
  ASSERT_NE(rc, nullptr);
  RCameraSetView(rc, NAN, NAN, INFINITY);
  EXPECT_NEAR(rc->m_CameraDist, 0.01, 1e-7);
  EXPECT_EQ(rc->m_CameraTheta, 0);
  EXPECT_EQ(rc->m_CameraPhi, 0);
  RRenderContextDestroy(rc);
}

}  // namespace
