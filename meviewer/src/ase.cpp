/* ase.cpp: ASE (3ds Max ASCII scene export) meshes, RGraphicLoadASE and
 * RGraphicCreate.
 *
 * Read, per *MESH block (several meshes are joined into one graphic):
 *   *MESH_NUMVERTEX n, *MESH_NUMFACES m, *MESH_NUMTVERTEX t
 *   *MESH_VERTEX i x y z                      (0 <= i < n)
 *   *MESH_FACE i: A: a B: b C: c ...          (0 <= i < m, corners < n)
 *   *MESH_TVERT i u v w                       (0 <= i < t)
 *   *MESH_TFACE i a b c                       (corners < t)
 *   *MESH_VERTEXNORMAL v nx ny nz             (three after each *MESH_FACENORMAL i)
 * Everything else (materials, scene, braces) is skipped. Faces without
 * normals get their flat normal; without texture coordinates, (0, 0).
 * Texture v is flipped (ASE's v runs up, MeViewer's down). Counts are
 * limited to 10^7 and every index is checked, so a malformed file gives a
 * message naming the line, never an out-of-bounds access. */
#include "viewer_internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace karma::viewer {
namespace {

constexpr long kMaxCount = 10000000;

struct Mesh {
  long numVertex = -1, numFaces = -1, numTVertex = 0;
  std::vector<std::array<float, 3>> vertex, tvert;
  std::vector<std::array<long, 3>> face, tface;
  std::vector<std::array<std::array<float, 3>, 3>> normal; /* per face corner */
  std::vector<int> normalCount;                            /* corners given per face */
};

bool Flush(Mesh &m, std::vector<RObjectVertex> &out, std::string &error) {
  if (m.numVertex < 0 && m.numFaces < 0) return true;
  /* Every index used below is checked here against the arrays themselves,
   * whatever order the file gave counts and lists in. */
  if (m.normal.size() < m.face.size() || m.normalCount.size() < m.face.size()) {
    error = "faces without *MESH_NUMFACES";
    return false;
  }
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    for (long c : m.face[f])
      if (c < 0 || std::size_t(c) >= m.vertex.size()) return error = "a face corner is not a vertex", false;
    if (f < m.tface.size())
      for (long c : m.tface[f])
        if (c < 0 || std::size_t(c) >= m.tvert.size()) return error = "a texture corner is not a *MESH_TVERT", false;
  }
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const std::array<long, 3> &c = m.face[f];
    float p[3][3];
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) p[k][j] = m.vertex[std::size_t(c[std::size_t(k)])][std::size_t(j)];
    float n[3] = {(p[1][1] - p[0][1]) * (p[2][2] - p[0][2]) - (p[1][2] - p[0][2]) * (p[2][1] - p[0][1]),
                  (p[1][2] - p[0][2]) * (p[2][0] - p[0][0]) - (p[1][0] - p[0][0]) * (p[2][2] - p[0][2]),
                  (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])};
    float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) n[0] = 0, n[1] = 0, n[2] = 1, len = 1;
    for (int k = 0; k < 3; ++k) {
      RObjectVertex v{};
      v.m_X = p[k][0], v.m_Y = p[k][1], v.m_Z = p[k][2];
      const float *vn = m.normalCount[f] == 3 ? m.normal[f][std::size_t(k)].data() : nullptr;
      const float vl = vn ? std::sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2]) : 0;
      if (vl > 0)
        v.m_NX = vn[0] / vl, v.m_NY = vn[1] / vl, v.m_NZ = vn[2] / vl;
      else
        v.m_NX = n[0] / len, v.m_NY = n[1] / len, v.m_NZ = n[2] / len;
      if (f < m.tface.size()) {
        const std::array<float, 3> &t = m.tvert[std::size_t(m.tface[f][std::size_t(k)])];
        v.m_U = t[0], v.m_V = 1 - t[1];
      }
      out.push_back(v);
    }
  }
  m = Mesh{};
  return true;
}

}  // namespace

bool ParseAse(const std::string &text, std::vector<RObjectVertex> &out, std::string &error) {
  out.clear();
  std::istringstream in(text);
  std::string line;
  Mesh m;
  long lineNo = 0, lastNormalFace = -1;
  int normalsSinceFace = 0;
  bool anyMesh = false;
  auto fail = [&](const std::string &why) {
    error = "line " + std::to_string(lineNo) + ": " + why;
    out.clear();
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key) || key[0] != '*') continue;
    auto count = [&](long &dst) {
      long n = -1;
      if (!(ls >> n) || n < 0 || n > kMaxCount) return false;
      dst = n;
      return true;
    };
    if (key == "*MESH") {
      if (!Flush(m, out, error)) return fail(error);
      anyMesh = true;
      lastNormalFace = -1, normalsSinceFace = 0; /* normals belong to their own mesh */
    } else if (key == "*MESH_NUMVERTEX") {
      if (m.numVertex >= 0) return fail("*MESH_NUMVERTEX given twice in one mesh");
      if (!count(m.numVertex)) return fail("bad *MESH_NUMVERTEX");
      m.vertex.assign(std::size_t(m.numVertex), {0, 0, 0});
    } else if (key == "*MESH_NUMFACES") {
      if (m.numFaces >= 0) return fail("*MESH_NUMFACES given twice in one mesh");
      if (!count(m.numFaces)) return fail("bad *MESH_NUMFACES");
      m.face.clear(), m.face.reserve(std::size_t(m.numFaces));
      m.normal.assign(std::size_t(m.numFaces), {});
      m.normalCount.assign(std::size_t(m.numFaces), 0);
    } else if (key == "*MESH_NUMTVERTEX") {
      if (!m.tvert.empty() || !m.tface.empty()) return fail("*MESH_NUMTVERTEX given twice in one mesh");
      if (!count(m.numTVertex)) return fail("bad *MESH_NUMTVERTEX");
      m.tvert.assign(std::size_t(m.numTVertex), {0, 0, 0});
    } else if (key == "*MESH_VERTEX" || key == "*MESH_TVERT") {
      const bool t = key == "*MESH_TVERT";
      long i = -1;
      float x, y, z;
      if (!(ls >> i >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        return fail("bad " + key + " (want index and three numbers)");
      std::vector<std::array<float, 3>> &list = t ? m.tvert : m.vertex;
      if (i < 0 || std::size_t(i) >= list.size()) return fail(key + " index " + std::to_string(i) + " out of range");
      list[std::size_t(i)] = {x, y, z};
    } else if (key == "*MESH_FACE") {
      std::string idx, a, b, c;
      long va = -1, vb = -1, vc = -1;
      if (!(ls >> idx >> a >> va >> b >> vb >> c >> vc) || a != "A:" || b != "B:" || c != "C:")
        return fail("bad *MESH_FACE (want 'i: A: a B: b C: c')");
      if (m.numVertex < 0 || m.numFaces < 0) return fail("*MESH_FACE before *MESH_NUMVERTEX / *MESH_NUMFACES");
      if (long(m.face.size()) >= m.numFaces) return fail("more faces than *MESH_NUMFACES");
      for (long v : {va, vb, vc})
        if (v < 0 || v >= m.numVertex) return fail("face corner " + std::to_string(v) + " is not a vertex");
      m.face.push_back({va, vb, vc});
    } else if (key == "*MESH_TFACE") {
      long i = -1, ta = -1, tb = -1, tc = -1;
      if (!(ls >> i >> ta >> tb >> tc)) return fail("bad *MESH_TFACE");
      if (i != long(m.tface.size()) || i >= m.numFaces)
        return fail("*MESH_TFACE " + std::to_string(i) + " out of order or range");
      for (long v : {ta, tb, tc})
        if (v < 0 || v >= m.numTVertex) return fail("texture corner " + std::to_string(v) + " is not a *MESH_TVERT");
      m.tface.push_back({ta, tb, tc});
    } else if (key == "*MESH_FACENORMAL") {
      long i = -1;
      if (!(ls >> i) || i < 0 || std::size_t(i) >= m.normal.size()) return fail("bad *MESH_FACENORMAL index");
      lastNormalFace = i, normalsSinceFace = 0;
    } else if (key == "*MESH_VERTEXNORMAL") {
      long v = -1;
      float x, y, z;
      if (!(ls >> v >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        return fail("bad *MESH_VERTEXNORMAL");
      if (lastNormalFace < 0 || normalsSinceFace >= 3 || std::size_t(lastNormalFace) >= m.normal.size())
        return fail("*MESH_VERTEXNORMAL outside a face's three");
      m.normal[std::size_t(lastNormalFace)][std::size_t(normalsSinceFace)] = {x, y, z};
      m.normalCount[std::size_t(lastNormalFace)] = ++normalsSinceFace;
    }
  }
  if (!anyMesh) return fail("no *MESH in the file");
  if (m.numFaces >= 0 && long(m.face.size()) != m.numFaces)
    return fail("the last mesh has " + std::to_string(m.face.size()) + " faces, *MESH_NUMFACES says " +
                std::to_string(m.numFaces));
  if (!m.tface.empty() && m.tface.size() != m.face.size()) return fail("*MESH_TFACE count differs from the faces");
  if (!Flush(m, out, error)) return fail(error);
  if (out.empty()) return fail("the meshes have no faces");
  return true;
}

}  // namespace karma::viewer

using namespace karma::viewer;

namespace {

RGraphic *Load(RRender *rc, const char *fn, const char *filename, const AcmeReal scale[3], bool normalise,
               bool keepAspect, const float color[4], MeMatrix4Ptr matrix, int is2D) {
  const std::string path = FindDataFile(filename);
  if (path.empty()) {
    MeWarning(0, "%s: cannot find '%s' (searched like textures; see docs/ARCHITECTURE.md)", fn, filename);
    return nullptr;
  }
  std::ifstream f(path);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::vector<RObjectVertex> v;
  std::string error;
  if (!f || !ParseAse(text, v, error)) {
    MeWarning(0, "%s: %s: %s", fn, path.c_str(), f ? error.c_str() : "cannot read");
    return nullptr;
  }
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (const RObjectVertex &x : v) {
    const float p[3] = {x.m_X, x.m_Y, x.m_Z};
    for (int j = 0; j < 3; ++j) lo[j] = std::min(lo[j], p[j]), hi[j] = std::max(hi[j], p[j]);
  }
  /* p' = (p - centre) * k * scale; normals by the inverse factors, renormalised. */
  float centre[3], k[3];
  const float longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  for (int j = 0; j < 3; ++j) {
    centre[j] = normalise ? 0.5f * (lo[j] + hi[j]) : 0;
    const float side = keepAspect ? longest : hi[j] - lo[j];
    k[j] = float(scale[j]) * (normalise ? (side > 0 ? 2 / side : 1) : 1);
  }
  RGraphic *g = RGraphicCreateSized(int(v.size()), int(v.size()));
  if (!g) return nullptr;
  for (std::size_t i = 0; i < v.size(); ++i) {
    RObjectVertex x = v[i];
    x.m_X = (x.m_X - centre[0]) * k[0], x.m_Y = (x.m_Y - centre[1]) * k[1], x.m_Z = (x.m_Z - centre[2]) * k[2];
    float n[3] = {k[0] != 0 ? x.m_NX / k[0] : 0, k[1] != 0 ? x.m_NY / k[1] : 0, k[2] != 0 ? x.m_NZ / k[2] : 0};
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0) x.m_NX = n[0] / len, x.m_NY = n[1] / len, x.m_NZ = n[2] / len;
    g->m_pVertices[i] = x;
  }
  return RGraphicFinishPrimitive(rc, g, color, matrix, is2D);
}

}  // namespace

RGraphic *MEAPI RGraphicLoadASE(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                                const float color[4], MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc && filename, nullptr, "RGraphicLoadASE", "rc or filename is NULL");
  const AcmeReal scale[3] = {xScale, yScale, zScale};
  return Load(rc, "RGraphicLoadASE", filename, scale, false, false, color, matrix, 0);
}

RGraphic *MEAPI RGraphicCreate(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                               const AcmeReal color[4], MeMatrix4Ptr matrix, int is2D, int bKeepAspectRatio) {
  ME_REQUIRE_ARG_RET(rc && filename, nullptr, "RGraphicCreate", "rc or filename is NULL");
  const AcmeReal scale[3] = {xScale, yScale, zScale};
  float c[4] = {1, 1, 1, 1};
  if (color)
    for (int i = 0; i < 4; ++i) c[i] = float(color[i]);
  return Load(rc, "RGraphicCreate", filename, scale, true, bKeepAspectRatio != 0, c, matrix, is2D);
}
