/* primitives_flat.cpp: primitives made of flat quads: the 2D rectangle, the
 * ground plane, the box and the square. Every quad is two triangles wound
 * anticlockwise seen from the side its normal points to, textured once
 * (u, v from 0 to 1 across it). */
#include "viewer_internal.h"

#include <cmath>

namespace {

/* Corners a, b, c, d in order round the quad; u, v run a->b and a->d. The
 * triangles come out anticlockwise seen from the side n points to. */
RObjectVertex *Quad(RObjectVertex *v, const float a[3], const float b[3], const float c[3], const float d[3],
                    const float n[3], float u0 = 0, float v0 = 0, float u1 = 1, float v1 = 1) {
  /* If (b - a) x (c - a) points away from n, the corners run clockwise:
   * swap b and d (and their texture coordinates with them). */
  const float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const float cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  if (cr[0] * n[0] + cr[1] * n[1] + cr[2] * n[2] < 0) {
    RSetVertex(v++, a[0], a[1], a[2], n[0], n[1], n[2], u0, v0);
    RSetVertex(v++, c[0], c[1], c[2], n[0], n[1], n[2], u1, v1);
    RSetVertex(v++, b[0], b[1], b[2], n[0], n[1], n[2], u1, v0);
    RSetVertex(v++, a[0], a[1], a[2], n[0], n[1], n[2], u0, v0);
    RSetVertex(v++, d[0], d[1], d[2], n[0], n[1], n[2], u0, v1);
    RSetVertex(v++, c[0], c[1], c[2], n[0], n[1], n[2], u1, v1);
    return v;
  }
  RSetVertex(v++, a[0], a[1], a[2], n[0], n[1], n[2], u0, v0);
  RSetVertex(v++, b[0], b[1], b[2], n[0], n[1], n[2], u1, v0);
  RSetVertex(v++, c[0], c[1], c[2], n[0], n[1], n[2], u1, v1);
  RSetVertex(v++, a[0], a[1], a[2], n[0], n[1], n[2], u0, v0);
  RSetVertex(v++, c[0], c[1], c[2], n[0], n[1], n[2], u1, v1);
  RSetVertex(v++, d[0], d[1], d[2], n[0], n[1], n[2], u0, v1);
  return v;
}

bool Finite(AcmeReal x) { return std::isfinite(double(x)); }

}  // namespace

RGraphic *MEAPI RGraphic2DRectangleCreate(RRender *rc, AcmeReal x, AcmeReal y, AcmeReal width, AcmeReal height,
                                          const float color[4]) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphic2DRectangleCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(x) && Finite(y) && Finite(width) && Finite(height), nullptr, "RGraphic2DRectangleCreate",
                     "x, y, width and height must be finite");
  RGraphic *g = RGraphicCreateSized(6, 6);
  if (!g) return nullptr;
  const float x0 = float(x), y0 = float(y), x1 = float(x + width), y1 = float(y + height);
  const float a[3] = {x0, y0, 0}, b[3] = {x1, y0, 0}, c[3] = {x1, y1, 0}, d[3] = {x0, y1, 0}, n[3] = {0, 0, 1};
  Quad(g->m_pVertices, a, b, c, d, n);
  return RGraphicFinishPrimitive(rc, g, color, nullptr, 1);
}

RGraphic *MEAPI RGraphicGroundPlaneCreate(RRender *rc, AcmeReal length, int triangles, const float color[4],
                                          AcmeReal y_pos) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicGroundPlaneCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(length) && length > 0 && Finite(y_pos), nullptr, "RGraphicGroundPlaneCreate",
                     "length must be positive and y_pos finite");
  ME_REQUIRE_ARG_RET(triangles >= 1 && triangles <= 1024, nullptr, "RGraphicGroundPlaneCreate",
                     "triangles (cells per side) must be 1..1024, not %d", triangles);
  const int n = triangles;
  RGraphic *g = RGraphicCreateSized(6 * n * n, 6 * n * n);
  if (!g) return nullptr;
  RObjectVertex *v = g->m_pVertices;
  const float half = float(length) / 2, step = float(length) / float(n), y = float(y_pos);
  const float up[3] = {0, 1, 0};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      /* Cell (i, k) spans x in [x0, x1], z in [z0, z1]; seen from +y,
       * (x0,z1) -> (x1,z1) -> (x1,z0) -> (x0,z0) is anticlockwise. */
      const float x0 = -half + step * float(i), x1 = x0 + step;
      const float z0 = -half + step * float(k), z1 = z0 + step;
      const float a[3] = {x0, y, z1}, b[3] = {x1, y, z1}, c[3] = {x1, y, z0}, d[3] = {x0, y, z0};
      const float u0 = float(i) / float(n), u1 = float(i + 1) / float(n);
      const float v0 = float(n - k - 1) / float(n), v1 = float(n - k) / float(n);
      v = Quad(v, a, b, c, d, up, u0, v0, u1, v1);
    }
  return RGraphicFinishPrimitive(rc, g, color, nullptr, 0);
}

RGraphic *MEAPI RGraphicBoxCreate(RRender *rc, AcmeReal x, AcmeReal y, AcmeReal z, const float color[4],
                                  MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicBoxCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(x) && Finite(y) && Finite(z) && x >= 0 && y >= 0 && z >= 0, nullptr, "RGraphicBoxCreate",
                     "the sides must be finite and not negative");
  RGraphic *g = RGraphicCreateSized(36, 36);
  if (!g) return nullptr;
  const float hx = float(x) / 2, hy = float(y) / 2, hz = float(z) / 2;
  /* The eight corners, index bits (x, y, z) set = positive side. */
  float p[8][3];
  for (int i = 0; i < 8; ++i) {
    p[i][0] = (i & 1) ? hx : -hx;
    p[i][1] = (i & 2) ? hy : -hy;
    p[i][2] = (i & 4) ? hz : -hz;
  }
  const float nx[3] = {1, 0, 0}, mx[3] = {-1, 0, 0}, ny[3] = {0, 1, 0}, my[3] = {0, -1, 0}, nz[3] = {0, 0, 1},
              mz[3] = {0, 0, -1};
  RObjectVertex *v = g->m_pVertices;
  v = Quad(v, p[1], p[5], p[7], p[3], nx); /* +x */
  v = Quad(v, p[4], p[0], p[2], p[6], mx); /* -x */
  v = Quad(v, p[2], p[3], p[7], p[6], ny); /* +y */
  v = Quad(v, p[4], p[5], p[1], p[0], my); /* -y */
  v = Quad(v, p[4], p[5], p[7], p[6], nz); /* +z */
  Quad(v, p[1], p[0], p[2], p[3], mz);     /* -z */
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

RGraphic *MEAPI RGraphicSquareCreate(RRender *rc, AcmeReal side, const float color[4], MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc, nullptr, "RGraphicSquareCreate", "rc is NULL");
  ME_REQUIRE_ARG_RET(Finite(side) && side >= 0, nullptr, "RGraphicSquareCreate", "side must be finite, >= 0");
  RGraphic *g = RGraphicCreateSized(6, 6);
  if (!g) return nullptr;
  const float h = float(side) / 2;
  const float a[3] = {-h, -h, 0}, b[3] = {h, -h, 0}, c[3] = {h, h, 0}, d[3] = {-h, h, 0}, n[3] = {0, 0, 1};
  Quad(g->m_pVertices, a, b, c, d, n);
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}
