/* camera.cpp: the spherical camera of Appendix B.
 *
 * With look-at point L, distance d, angle theta and elevation phi:
 *   view direction from L to the camera  z_c = (cos phi sin theta, sin phi, cos phi cos theta)
 *   camera position                      P   = L + d z_c
 *   camera right                         x_c = (cos theta, 0, -sin theta)
 *   camera up                            y_c = z_c x x_c = (-sin phi sin theta, cos phi, -sin phi cos theta)
 * (x_c, y_c, z_c) is a right-handed orthonormal frame for every theta, phi,
 * so the poles need no special case. The camera looks down -z_c.
 * Limits: d >= 0.01; theta wrapped into [-pi, pi]; phi clamped to
 * [-pi/2, pi/2]. Pans move L (and so P) by dist along x_c (PanX), y_c
 * (PanY) or -z_c (PanZ, towards the look-at point). */
#include "viewer_internal.h"

#include <cmath>

namespace {

constexpr AcmeReal kMinDistance = (AcmeReal)0.01;

void Axes(const RRender *rc, AcmeReal x[3], AcmeReal y[3], AcmeReal z[3]) {
  const AcmeReal st = MeSin(rc->m_CameraTheta), ct = MeCos(rc->m_CameraTheta);
  const AcmeReal sp = MeSin(rc->m_CameraPhi), cp = MeCos(rc->m_CameraPhi);
  z[0] = cp * st, z[1] = sp, z[2] = cp * ct;
  x[0] = ct, x[1] = 0, x[2] = -st;
  y[0] = -sp * st, y[1] = cp, y[2] = -sp * ct;
}

void Normalise(RRender *rc) {
  if (!(rc->m_CameraDist >= kMinDistance)) rc->m_CameraDist = kMinDistance; /* also catches NaN */
  AcmeReal t = rc->m_CameraTheta;
  if (!std::isfinite(double(t))) t = 0;
  if (t > ME_PI || t < -ME_PI) t = t - ME_TWO_PI * std::floor((t + ME_PI) / ME_TWO_PI);
  rc->m_CameraTheta = t;
  AcmeReal p = rc->m_CameraPhi;
  if (!std::isfinite(double(p))) p = 0;
  rc->m_CameraPhi = p > ME_HALF_PI ? ME_HALF_PI : (p < -ME_HALF_PI ? -ME_HALF_PI : p);
}

void Pan(RRender *rc, int axis, AcmeReal dist) {
  AcmeReal a[3][3];
  Axes(rc, a[0], a[1], a[2]);
  const AcmeReal s = axis == 2 ? -dist : dist;
  for (int i = 0; i < 3; ++i) rc->m_CameraLookAt[i] += s * a[axis][i];
  RCameraUpdate(rc);
}

}  // namespace

void MEAPI RCameraUpdate(RRender *rc) {
  ME_REQUIRE_ARG(rc, "RCameraUpdate", "rc is NULL");
  Normalise(rc);
  AcmeReal x[3], y[3], z[3];
  Axes(rc, x, y, z);
  for (int i = 0; i < 3; ++i) {
    rc->m_CameraPos[i] = rc->m_CameraLookAt[i] + rc->m_CameraDist * z[i];
    rc->m_CameraUp[i] = y[i];
  }
  /* World to camera: p_c = (p - P) . [x_c y_c z_c] as a Karma TM (rows are
   * the world axes in camera coordinates, row 3 the translation). */
  MeMatrix4 &m = rc->m_CameraMatrix;
  for (int i = 0; i < 3; ++i) {
    m[i][0] = x[i], m[i][1] = y[i], m[i][2] = z[i], m[i][3] = 0;
  }
  const AcmeReal *P = rc->m_CameraPos;
  m[3][0] = -(P[0] * x[0] + P[1] * x[1] + P[2] * x[2]);
  m[3][1] = -(P[0] * y[0] + P[1] * y[1] + P[2] * y[2]);
  m[3][2] = -(P[0] * z[0] + P[1] * z[1] + P[2] * z[2]);
  m[3][3] = 1;
}

void MEAPI RCameraSetLookAt(RRender *rc, const AcmeVector3 lookAt) {
  ME_REQUIRE_ARG(rc && lookAt, "RCameraSetLookAt", "rc or lookAt is NULL");
  for (int i = 0; i < 3; ++i) rc->m_CameraLookAt[i] = lookAt[i];
  RCameraUpdate(rc);
}

void MEAPI RCameraGetLookAt(RRender *rc, AcmeVector3 camlookat) {
  ME_REQUIRE_ARG(rc && camlookat, "RCameraGetLookAt", "rc or camlookat is NULL");
  for (int i = 0; i < 3; ++i) camlookat[i] = rc->m_CameraLookAt[i];
}

void MEAPI RCameraSetView(RRender *rc, AcmeReal dist, AcmeReal theta, AcmeReal phi) {
  ME_REQUIRE_ARG(rc, "RCameraSetView", "rc is NULL");
  rc->m_CameraDist = dist;
  rc->m_CameraTheta = theta;
  rc->m_CameraPhi = phi;
  RCameraUpdate(rc);
}

void MEAPI RCameraGetPosition(RRender *rc, AcmeVector3 campos) {
  ME_REQUIRE_ARG(rc && campos, "RCameraGetPosition", "rc or campos is NULL");
  RCameraUpdate(rc);
  for (int i = 0; i < 3; ++i) campos[i] = rc->m_CameraPos[i];
}

void MEAPI RCameraZoom(RRender *rc, AcmeReal dist) {
  ME_REQUIRE_ARG(rc, "RCameraZoom", "rc is NULL");
  rc->m_CameraDist += dist;
  RCameraUpdate(rc);
}

void MEAPI RCameraPanX(RRender *rc, AcmeReal dist) {
  ME_REQUIRE_ARG(rc, "RCameraPanX", "rc is NULL");
  Pan(rc, 0, dist);
}
void MEAPI RCameraPanY(RRender *rc, AcmeReal dist) {
  ME_REQUIRE_ARG(rc, "RCameraPanY", "rc is NULL");
  Pan(rc, 1, dist);
}
void MEAPI RCameraPanZ(RRender *rc, AcmeReal dist) {
  ME_REQUIRE_ARG(rc, "RCameraPanZ", "rc is NULL");
  Pan(rc, 2, dist);
}

void MEAPI RCameraRotateAngle(RRender *rc, AcmeReal d_theta) {
  ME_REQUIRE_ARG(rc, "RCameraRotateAngle", "rc is NULL");
  rc->m_CameraTheta += d_theta;
  RCameraUpdate(rc);
}

void MEAPI RCameraRotateElevation(RRender *rc, AcmeReal d_phi) {
  ME_REQUIRE_ARG(rc, "RCameraRotateElevation", "rc is NULL");
  rc->m_CameraPhi += d_phi;
  RCameraUpdate(rc);
}

namespace karma::viewer {

/* OpenGL's perspective matrix (column-major) for the context's field of
 * view and aspect; near = min(0.1, d/2) so a close camera still sees the
 * look-at point, far = 1000 + d. */
void PerspectiveMatrix(const RRender *rc, float out[16]) {
  const double aspect = double(rc->m_nWidth) / double(rc->m_nHeight);
  const double f = 1.0 / std::tan(double(rc->m_CameraFOV) / 2);
  const double d = double(rc->m_CameraDist);
  const double n = d / 2 < 0.1 ? d / 2 : 0.1, fa = 1000 + d;
  for (int i = 0; i < 16; ++i) out[i] = 0;
  out[0] = float(f / aspect);
  out[5] = float(f);
  out[10] = float((fa + n) / (n - fa));
  out[11] = -1;
  out[14] = float(2 * fa * n / (n - fa));
}

/* A Karma TM in memory is already OpenGL's column-major layout. */
void CameraMatrixFloat(const RRender *rc, float out[16]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out[4 * i + j] = float(rc->m_CameraMatrix[i][j]);
}

}  // namespace karma::viewer
