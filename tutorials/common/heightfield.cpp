// heightfield.cpp: see heightfield.h.
#include "heightfield.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#define STB_IMAGE_STATIC
#define STBI_ONLY_BMP
#define STBI_NO_STDIO_OVERRIDE
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wunused-function"
#  pragma GCC diagnostic ignored "-Wsign-conversion"
#  pragma GCC diagnostic ignored "-Wconversion"
#  pragma GCC diagnostic ignored "-Wdouble-promotion"
#  pragma GCC diagnostic ignored "-Wcast-qual"
#  pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#  pragma GCC diagnostic ignored "-Wshadow"
#  pragma GCC diagnostic ignored "-Wold-style-cast"
#  pragma GCC diagnostic ignored "-Wuseless-cast"
#  pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#  pragma GCC diagnostic pop
#endif

#ifndef KARMA_BUILD_DATA_DIR
#  define KARMA_BUILD_DATA_DIR ""
#endif
#ifndef KARMA_INSTALL_DATA_DIR
#  define KARMA_INSTALL_DATA_DIR ""
#endif

namespace fs = std::filesystem;

namespace {

std::string FindFile(const std::string &file) {
  std::vector<std::string> dirs{"."};
  if (const char *env = std::getenv("KARMA_DATA_DIR"); env && *env) dirs.emplace_back(env);
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = 0;
    const std::string dir = fs::path(exe).parent_path().string();
    dirs.push_back(dir);
    dirs.push_back(dir + "/data");
    dirs.push_back(dir + "/../share/karma");
  }
  if (*KARMA_BUILD_DATA_DIR) dirs.emplace_back(KARMA_BUILD_DATA_DIR);
  if (*KARMA_INSTALL_DATA_DIR) dirs.emplace_back(KARMA_INSTALL_DATA_DIR);
  std::error_code ec;
  if (fs::path(file).is_absolute()) return fs::is_regular_file(file, ec) ? file : std::string();
  for (const std::string &d : dirs)
    if (fs::is_regular_file(fs::path(d) / file, ec)) return (fs::path(d) / file).string();
  return {};
}

int Index(const HeightField *hf, int ix, int iz) { return iz * hf->countX + ix; }

// A neighbour's vertex this far below a triangle's plane (times the grid
// spacing) makes their shared edge a crest.
constexpr MeReal kCrestTolerance = (MeReal)1e-5;

// Unit normal of the triangle (a, b, c), counter-clockwise seen from +y.
void FaceNormal(const MeVector3 a, const MeVector3 b, const MeVector3 c, MeVector3 n) {
  MeVector3 u, v;
  MeVector3Subtract(u, b, a);
  MeVector3Subtract(v, c, a);
  MeVector3Cross(n, u, v);
  MeVector3Normalize(n);
}

// The triangles of cell (ix, iz): k = 0 is (00, 11, 10), k = 1 is
// (00, 01, 11) with 00 = (ix, iz), 10 = (ix + 1, iz), 01 = (ix, iz + 1).
// In this order (b - a) x (c - a) points up (+y) for both.
void CellTriangle(const HeightField *hf, int ix, int iz, int k, int v[3]) {
  const int i00 = Index(hf, ix, iz), i10 = Index(hf, ix + 1, iz), i01 = Index(hf, ix, iz + 1),
            i11 = Index(hf, ix + 1, iz + 1);
  if (k == 0) {
    v[0] = i00, v[1] = i11, v[2] = i10;
  } else {
    v[0] = i00, v[1] = i01, v[2] = i11;
  }
}

// The edge flags of triangle k of cell (ix, iz) (vertices v, face normal n):
// an edge is sharp where the surface folds down across it (a crest: the
// neighbouring triangle's far vertex lies below this triangle's plane), so
// that a body resting on the fold touches the edge, which no face's
// contact covers there. Seams that are flat or fold up (a hollow) stay
// smooth, and so does the field's rim. Edge e runs from v[e] to v[(e+1)%3]
// (McdTriangleList.h); kFar gives, per triangle and edge, the grid offset
// from (ix, iz) of the neighbour's vertex off that edge.
int CrestEdgeFlags(const HeightField *hf, int ix, int iz, int k, const int v[3], const MeVector3 n) {
  static constexpr int kFar[2][3][2] = {{{0, 1}, {2, 1}, {0, -1}}, {{-1, 0}, {1, 2}, {1, 0}}};
  const MeReal tolerance = kCrestTolerance * hf->spacing;
  int flags = 0;
  for (int e = 0; e < 3; ++e) {
    const int fx = ix + kFar[k][e][0], fz = iz + kFar[k][e][1];
    if (fx < 0 || fz < 0 || fx >= hf->countX || fz >= hf->countZ) continue;
    MeVector3 d;
    MeVector3Subtract(d, hf->vertices[Index(hf, fx, fz)], hf->vertices[v[0]]);
    if (MeVector3Dot(d, n) < -tolerance) flags |= kMcdTriangleUseEdge0 << e;
  }
  return flags;
}

}  // namespace

extern "C" {

int HeightFieldCreate(HeightField *hf, int countX, int countZ, MeReal spacing, MeReal originX, MeReal originZ,
                      const MeReal *heights) {
  if (!hf) return 0;
  *hf = HeightField{};
  if (countX < 2 || countZ < 2 || !(spacing > 0) || !heights) {
    std::fprintf(stderr, "HeightFieldCreate: need at least 2 x 2 points, a positive spacing and heights\n");
    return 0;
  }
  const size_t points = (size_t)countX * (size_t)countZ;
  const size_t cells = (size_t)(countX - 1) * (size_t)(countZ - 1);
  hf->heights = static_cast<MeReal *>(std::malloc(points * sizeof(MeReal)));
  hf->vertices = static_cast<MeVector3 *>(std::malloc(points * sizeof(MeVector3)));
  hf->normals = static_cast<MeVector3 *>(std::malloc(2 * cells * sizeof(MeVector3)));
  if (!hf->heights || !hf->vertices || !hf->normals) {
    HeightFieldDestroy(hf);
    std::fprintf(stderr, "HeightFieldCreate: out of memory\n");
    return 0;
  }
  hf->countX = countX, hf->countZ = countZ, hf->spacing = spacing;
  hf->originX = originX, hf->originZ = originZ;
  for (int iz = 0; iz < countZ; ++iz)
    for (int ix = 0; ix < countX; ++ix) {
      const int i = Index(hf, ix, iz);
      hf->heights[i] = heights[i];
      MeVector3Set(hf->vertices[i], originX + (MeReal)ix * spacing, heights[i], originZ + (MeReal)iz * spacing);
    }
  for (int iz = 0; iz + 1 < countZ; ++iz)
    for (int ix = 0; ix + 1 < countX; ++ix)
      for (int k = 0; k < 2; ++k) {
        int v[3];
        CellTriangle(hf, ix, iz, k, v);
        FaceNormal(hf->vertices[v[0]], hf->vertices[v[1]], hf->vertices[v[2]],
                   hf->normals[2 * (iz * (countX - 1) + ix) + k]);
      }
  return 1;
}

int HeightFieldFromBMP(HeightField *hf, const char *name, MeReal heightScale) {
  if (!hf) return 0;
  *hf = HeightField{};
  if (!name || !std::isfinite((double)heightScale)) {
    std::fprintf(stderr, "HeightFieldFromBMP: no name, or a height scale that is not finite\n");
    return 0;
  }
  std::string file = name;
  if (file.size() < 4 || file.compare(file.size() - 4, 4, ".bmp") != 0) file += ".bmp";
  const std::string path = FindFile(file);
  if (path.empty()) {
    std::fprintf(stderr,
                 "HeightFieldFromBMP: %s not found (working directory, $KARMA_DATA_DIR, "
                 "the program's directory, share/karma/)\n",
                 file.c_str());
    return 0;
  }
  int w = 0, h = 0, channels = 0;
  unsigned char *pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!pixels) {
    std::fprintf(stderr, "HeightFieldFromBMP: cannot read %s: %s\n", path.c_str(), stbi_failure_reason());
    return 0;
  }
  std::vector<MeReal> heights((size_t)w * (size_t)h);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const unsigned char *p = pixels + 3 * ((size_t)r * (size_t)w + (size_t)c);
      const int level = (p[0] + p[1] + p[2]) / 3;  // grey: all three equal
      heights[(size_t)r * (size_t)w + (size_t)c] = (MeReal)level / 255 * heightScale;
    }
  stbi_image_free(pixels);
  const MeReal s = HEIGHTFIELD_BMP_SPACING;
  return HeightFieldCreate(hf, w, h, s, -(MeReal)(w - 1) * s / 2, -(MeReal)(h - 1) * s / 2, heights.data());
}

void HeightFieldDestroy(HeightField *hf) {
  if (!hf) return;
  std::free(hf->heights);
  std::free(hf->vertices);
  std::free(hf->normals);
  *hf = HeightField{};
}

MeReal HeightFieldHeightAt(const HeightField *hf, MeReal x, MeReal z) {
  if (!hf || !hf->heights) return 0;
  // Cell coordinates, clamped to the grid; (u, w) in [0, 1] inside the cell.
  const MeReal fx = std::clamp((x - hf->originX) / hf->spacing, (MeReal)0, (MeReal)(hf->countX - 1));
  const MeReal fz = std::clamp((z - hf->originZ) / hf->spacing, (MeReal)0, (MeReal)(hf->countZ - 1));
  const int ix = std::min((int)fx, hf->countX - 2), iz = std::min((int)fz, hf->countZ - 2);
  const MeReal u = fx - (MeReal)ix, w = fz - (MeReal)iz;
  const MeReal h00 = hf->heights[Index(hf, ix, iz)], h10 = hf->heights[Index(hf, ix + 1, iz)],
               h01 = hf->heights[Index(hf, ix, iz + 1)], h11 = hf->heights[Index(hf, ix + 1, iz + 1)];
  // Triangle (00, 11, 10) below the diagonal (u >= w), (00, 01, 11) above.
  if (u >= w) return h00 + u * (h10 - h00) + w * (h11 - h10);
  return h00 + w * (h01 - h00) + u * (h11 - h01);
}

void HeightFieldGetBounds(const HeightField *hf, MeVector3 min, MeVector3 max) {
  if (!hf || !hf->heights) {
    MeVector3Set(min, 0, 0, 0);
    MeVector3Set(max, 0, 0, 0);
    return;
  }
  const int n = hf->countX * hf->countZ;
  const MeReal lo = *std::min_element(hf->heights, hf->heights + n);
  const MeReal hi = *std::max_element(hf->heights, hf->heights + n);
  MeVector3Set(min, hf->originX, lo, hf->originZ);
  MeVector3Set(max, hf->originX + (MeReal)(hf->countX - 1) * hf->spacing, hi,
               hf->originZ + (MeReal)(hf->countZ - 1) * hf->spacing);
}

int HeightFieldTrianglesNear(const HeightField *hf, const MeVector3 pos, MeReal radius, McdUserTriangle *triangles,
                             int maxTriangles) {
  if (!hf || !hf->heights || !triangles || maxTriangles <= 0 || !(radius >= 0)) return 0;
  const MeReal s = hf->spacing;
  const int x0 = std::max(0, (int)std::floor((pos[0] - radius - hf->originX) / s));
  const int x1 = std::min(hf->countX - 2, (int)std::floor((pos[0] + radius - hf->originX) / s));
  const int z0 = std::max(0, (int)std::floor((pos[2] - radius - hf->originZ) / s));
  const int z1 = std::min(hf->countZ - 2, (int)std::floor((pos[2] + radius - hf->originZ) / s));
  if (x0 > x1 || z0 > z1) return 0;
  // Cells nearest pos first, so a too-small triangleMaxCount drops the far
  // ones; ties keep (z, x) order, so the list is deterministic.
  struct Cell {
    MeReal d2;
    int ix, iz;
  };
  std::vector<Cell> cells;
  cells.reserve((size_t)(x1 - x0 + 1) * (size_t)(z1 - z0 + 1));
  for (int iz = z0; iz <= z1; ++iz)
    for (int ix = x0; ix <= x1; ++ix) {
      const MeReal cx = hf->originX + ((MeReal)ix + (MeReal)0.5) * s - pos[0];
      const MeReal cz = hf->originZ + ((MeReal)iz + (MeReal)0.5) * s - pos[2];
      cells.push_back({cx * cx + cz * cz, ix, iz});
    }
  std::stable_sort(cells.begin(), cells.end(), [](const Cell &a, const Cell &b) { return a.d2 < b.d2; });
  int count = 0;
  for (const Cell &c : cells)
    for (int k = 0; k < 2 && count < maxTriangles; ++k) {
      int v[3];
      CellTriangle(hf, c.ix, c.iz, k, v);
      McdUserTriangle &t = triangles[count++];
      for (int i = 0; i < 3; ++i) t.vertices[i] = &hf->vertices[v[i]];
      t.normal = &hf->normals[2 * (c.iz * (hf->countX - 1) + c.ix) + k];
      t.triangleData.tag = 0;
      t.flags = CrestEdgeFlags(hf, c.ix, c.iz, k, v, *t.normal);  // face normal, one-sided
    }
  return count;
}

}  // extern "C"
