/* primitives_round.cpp: primitives round the z axis: sphere, cylinder, cone,
 * frustum and torus.
 *
 * Angles theta run anticlockwise about +z from +x. A band between the rings
 * (r0, z0) and (r1, z1) (z0 < z1) has outward normal proportional to
 * (dz cos theta, dz sin theta, -dr), dz = z1 - z0, dr = r1 - r0; smooth
 * bands use it at each vertex's angle, faceted ones (the frustum) at the
 * middle of each face. Triangles wind anticlockwise seen from outside. */
#include "viewer_internal.h"

#include <cmath>

namespace {

constexpr int kRoundSides = 24;   /* cylinder, cone */
constexpr int kSphereStacks = 16; /* sphere: kRoundSides slices */
constexpr int kTorusRing = 32, kTorusTube = 16;

RObjectVertex V(float x, float y, float z, float nx, float ny, float nz, float u, float w) {
  RObjectVertex v;
  RSetVertex(&v, x, y, z, nx, ny, nz, u, w);
  return v;
}

/* Corners a, b, c, d anticlockwise seen from outside. */
RObjectVertex *Quad(RObjectVertex *out, const RObjectVertex &a, const RObjectVertex &b, const RObjectVertex &c,
                    const RObjectVertex &d) {
  *out++ = a, *out++ = b, *out++ = c;
  *out++ = a, *out++ = c, *out++ = d;
  return out;
}

/* A band of `sides` quads; 6 * sides vertices. */
RObjectVertex *Band(RObjectVertex *v, float r0, float z0, float r1, float z1, int sides, bool smooth) {
  const float dz = z1 - z0, dr = r1 - r0, len = std::sqrt(dz * dz + dr * dr);
  const float nr = len > 0 ? dz / len : 1, nz = len > 0 ? -dr / len : 0;
  for (int k = 0; k < sides; ++k) {
    const float t0 = 2 * float(ME_PI) * float(k) / float(sides), t1 = 2 * float(ME_PI) * float(k + 1) / float(sides);
    const float tm = 0.5f * (t0 + t1);
    const float c0 = std::cos(t0), s0 = std::sin(t0), c1 = std::cos(t1), s1 = std::sin(t1);
    const float n0c = smooth ? c0 : std::cos(tm), n0s = smooth ? s0 : std::sin(tm);
    const float n1c = smooth ? c1 : std::cos(tm), n1s = smooth ? s1 : std::sin(tm);
    const float u0 = float(k) / float(sides), u1 = float(k + 1) / float(sides);
    v = Quad(v, V(r0 * c0, r0 * s0, z0, nr * n0c, nr * n0s, nz, u0, 1),
             V(r0 * c1, r0 * s1, z0, nr * n1c, nr * n1s, nz, u1, 1),
             V(r1 * c1, r1 * s1, z1, nr * n1c, nr * n1s, nz, u1, 0),
             V(r1 * c0, r1 * s0, z1, nr * n0c, nr * n0s, nz, u0, 0));
  }
  return v;
}

/* A disc of radius r at height z facing +z (up) or -z; 3 * sides vertices. */
RObjectVertex *Cap(RObjectVertex *v, float r, float z, int sides, bool up) {
  const float n = up ? 1.0f : -1.0f;
  for (int k = 0; k < sides; ++k) {
    const float t0 = 2 * float(ME_PI) * float(k) / float(sides), t1 = 2 * float(ME_PI) * float(k + 1) / float(sides);
    const RObjectVertex c = V(0, 0, z, 0, 0, n, 0.5f, 0.5f);
    const RObjectVertex a =
        V(r * std::cos(t0), r * std::sin(t0), z, 0, 0, n, 0.5f + 0.5f * std::cos(t0), 0.5f - 0.5f * std::sin(t0));
    const RObjectVertex b =
        V(r * std::cos(t1), r * std::sin(t1), z, 0, 0, n, 0.5f + 0.5f * std::cos(t1), 0.5f - 0.5f * std::sin(t1));
    *v++ = c;
    *v++ = up ? a : b;
    *v++ = up ? b : a;
  }
  return v;
}

bool Finite(AcmeReal x) { return std::isfinite(double(x)); }

}  // namespace

RGraphic *MEAPI RGraphicSphereCreate(RRender *rc, AcmeReal radius, const float color[4], MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicSphereCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(radius) && radius >= 0, nullptr, "RGraphicSphereCreate", "radius must be finite, >= 0");
  const int S = kRoundSides, T = kSphereStacks;
  RGraphic *g = RGraphicCreateSized(6 * S * T, 6 * S * T);
  if (!g) return nullptr;
  const float r = float(radius);
  /* Vertex (i, j): theta = 2 pi i / S, polar angle phi = pi j / T from +z. */
  auto P = [&](int i, int j) {
    const float t = 2 * float(ME_PI) * float(i) / float(S), p = float(ME_PI) * float(j) / float(T);
    const float nx = std::sin(p) * std::cos(t), ny = std::sin(p) * std::sin(t), nz = std::cos(p);
    return V(r * nx, r * ny, r * nz, nx, ny, nz, float(i) / float(S), float(j) / float(T));
  };
  RObjectVertex *v = g->m_pVertices;
  for (int j = 0; j < T; ++j)
    for (int i = 0; i < S; ++i) v = Quad(v, P(i, j + 1), P(i + 1, j + 1), P(i + 1, j), P(i, j));
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

RGraphic *MEAPI RGraphicCylinderCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                       MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicCylinderCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(radius) && Finite(height) && radius >= 0 && height >= 0, nullptr, "RGraphicCylinderCreate",
                     "radius and height must be finite, >= 0");
  const int S = kRoundSides;
  RGraphic *g = RGraphicCreateSized(12 * S, 12 * S);
  if (!g) return nullptr;
  const float r = float(radius), h = float(height) / 2;
  RObjectVertex *v = Band(g->m_pVertices, r, -h, r, h, S, true);
  v = Cap(v, r, h, S, true);
  Cap(v, r, -h, S, false);
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

RGraphic *MEAPI RGraphicConeCreate(RRender *rc, AcmeReal radius, AcmeReal uheight, AcmeReal lheight,
                                   const float color[4], MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicConeCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(radius) && Finite(uheight) && Finite(lheight) && radius >= 0 && uheight + lheight > 0,
                     nullptr, "RGraphicConeCreate", "radius must be finite, >= 0, and uheight + lheight > 0");
  const int S = kRoundSides;
  RGraphic *g = RGraphicCreateSized(9 * S, 9 * S);
  if (!g) return nullptr;
  RObjectVertex *v = Band(g->m_pVertices, float(radius), -float(lheight), 0, float(uheight), S, true);
  Cap(v, float(radius), -float(lheight), S, false);
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

RGraphic *MEAPI RGraphicFrustumCreate(RRender *rc, AcmeReal bottomRadius, AcmeReal topRadius, AcmeReal bottom,
                                      AcmeReal top, int sides, const float color[4], MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicFrustumCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(bottomRadius) && Finite(topRadius) && Finite(bottom) && Finite(top) && bottomRadius >= 0 &&
                         topRadius >= 0 && top > bottom,
                     nullptr, "RGraphicFrustumCreate", "radii must be finite, >= 0, and top > bottom");
  ME_REQUIRE_ARG_RET(sides >= 3 && sides <= 4096, nullptr, "RGraphicFrustumCreate", "sides must be 3..4096, not %d",
                     sides);
  RGraphic *g = RGraphicCreateSized(12 * sides, 12 * sides);
  if (!g) return nullptr;
  RObjectVertex *v =
      Band(g->m_pVertices, float(bottomRadius), float(bottom), float(topRadius), float(top), sides, false);
  v = Cap(v, float(topRadius), float(top), sides, true);
  Cap(v, float(bottomRadius), float(bottom), sides, false);
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

RGraphic *MEAPI RGraphicTorusCreate(RRender *rc, AcmeReal innerRadius, AcmeReal outerRadius, const float color[4],
                                    MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicTorusCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(innerRadius) && Finite(outerRadius) && innerRadius >= 0 && outerRadius >= innerRadius,
                     nullptr, "RGraphicTorusCreate", "need 0 <= innerRadius <= outerRadius, both finite");
  const int A = kTorusRing, B = kTorusTube;
  RGraphic *g = RGraphicCreateSized(6 * A * B, 6 * A * B);
  if (!g) return nullptr;
  /* Ring radius R, tube radius r; vertex (i, j) at alpha = 2 pi i / A about
   * z, beta = 2 pi j / B round the tube from its outer equator upwards. */
  const float R = float(outerRadius + innerRadius) / 2, r = float(outerRadius - innerRadius) / 2;
  auto P = [&](int i, int j) {
    const float a = 2 * float(ME_PI) * float(i) / float(A), b = 2 * float(ME_PI) * float(j) / float(B);
    const float ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
    return V((R + r * cb) * ca, (R + r * cb) * sa, r * sb, cb * ca, cb * sa, sb, float(i) / float(A),
             float(j) / float(B));
  };
  RObjectVertex *v = g->m_pVertices;
  for (int i = 0; i < A; ++i)
    for (int j = 0; j < B; ++j) v = Quad(v, P(i, j), P(i + 1, j), P(i + 1, j + 1), P(i, j + 1));
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}
