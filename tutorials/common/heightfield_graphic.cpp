// heightfield_graphic.cpp: see heightfield_graphic.h.
#include "heightfield_graphic.h"

#include <cmath>

namespace {

// Smooth normal at grid point (ix, iz) from the central (one-sided at the
// border) height differences: n ~ (-dh/dx, 1, -dh/dz).
void GridNormal(const HeightField *hf, int ix, int iz, float n[3]) {
  const int xa = ix > 0 ? ix - 1 : ix, xb = ix + 1 < hf->countX ? ix + 1 : ix;
  const int za = iz > 0 ? iz - 1 : iz, zb = iz + 1 < hf->countZ ? iz + 1 : iz;
  const double dhdx = (double)(hf->heights[iz * hf->countX + xb] - hf->heights[iz * hf->countX + xa]) /
                      ((double)(xb - xa) * (double)hf->spacing);
  const double dhdz = (double)(hf->heights[zb * hf->countX + ix] - hf->heights[za * hf->countX + ix]) /
                      ((double)(zb - za) * (double)hf->spacing);
  const double len = std::sqrt(dhdx * dhdx + 1 + dhdz * dhdz);
  n[0] = (float)(-dhdx / len), n[1] = (float)(1 / len), n[2] = (float)(-dhdz / len);
}

}  // namespace

extern "C" RGraphic *HeightFieldCreateGraphic(RRender *rc, const HeightField *hf, const float color[4],
                                              MeReal texelMetres, MeMatrix4Ptr tm) {
  if (!rc || !hf || !hf->heights) return nullptr;
  const int cells = (hf->countX - 1) * (hf->countZ - 1);
  RGraphic *g = RGraphicCreateEmpty(6 * cells);
  if (!g) return nullptr;
  const double texel = texelMetres > 0 ? (double)texelMetres : 1.0;
  RObjectVertex *out = g->m_pVertices;
  for (int iz = 0; iz + 1 < hf->countZ; ++iz)
    for (int ix = 0; ix + 1 < hf->countX; ++ix) {
      // The same two triangles, in the same order, as collision sees them
      // (heightfield.cpp, CellTriangle): (00, 11, 10) and (00, 01, 11).
      const int corner[2][3][2] = {{{0, 0}, {1, 1}, {1, 0}}, {{0, 0}, {0, 1}, {1, 1}}};
      for (int k = 0; k < 2; ++k)
        for (int v = 0; v < 3; ++v) {
          const int gx = ix + corner[k][v][0], gz = iz + corner[k][v][1];
          const MeReal *p = hf->vertices[gz * hf->countX + gx];
          RObjectVertex &o = *out++;
          o.m_X = (float)p[0], o.m_Y = (float)p[1], o.m_Z = (float)p[2];
          float n[3];
          GridNormal(hf, gx, gz, n);
          o.m_NX = n[0], o.m_NY = n[1], o.m_NZ = n[2];
          o.m_U = (float)((double)p[0] / texel), o.m_V = (float)((double)p[2] / texel);
        }
    }
  g->m_pObject->m_nNumVertices = 6 * cells;
  static const float white[4] = {1, 1, 1, 1};
  RGraphicSetColor(g, color ? color : white);
  g->m_pLWMatrix = tm;
  RGraphicAddToList(rc, g, 0);
  return g;
}
