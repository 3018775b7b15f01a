// convex_mesh.cpp: the convex mesh geometry built from a hull (see
// convex_hull.cpp). The struct and its arrays share one MeMemoryAPI block;
// the mass properties are computed once, at creation.
#include "convex_internal.h"
#include "shape_util.h"

using namespace karma::mcd;

namespace {

ConvexMesh *Get(McdGeometry *g, const char *fn) { return As<ConvexMesh>(g, kMcdGeometryTypeConvexMesh, fn); }

// World AABB: the extreme vertices along each axis, widened by the fatness.
void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  auto *m = reinterpret_cast<const ConvexMesh *>(g);
  for (int j = 0; j < 3; ++j) {
    mn[j] = MEINFINITY;
    mx[j] = -MEINFINITY;
  }
  for (int i = 0; i < m->vertexCount; ++i) {
    MeVector3 w;
    MeMatrix4TMTransform(w, tm, m->vertices[i]);
    for (int j = 0; j < 3; ++j) {
      mn[j] = std::fmin(mn[j], w[j]);
      mx[j] = std::fmax(mx[j], w[j]);
    }
  }
  for (int j = 0; j < 3; ++j) {
    mn[j] -= m->fatness;
    mx[j] += m->fatness;
  }
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  auto *m = reinterpret_cast<const ConvexMesh *>(g);
  *volume = m->volume;
  MeVector3Copy(com, m->com);
  MeMatrix3Copy(I, m->inertia);
  return true;
}

template <class T>
T *Carve(char *&cursor, std::size_t n) {
  T *p = reinterpret_cast<T *>(cursor);
  cursor += (sizeof(T) * n + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) * alignof(std::max_align_t);
  return p;
}

}  // namespace

const GeometryType karma::mcd::kConvexMeshType = {"ConvexMesh", nullptr, Aabb, Mass};

extern "C" {

McdConvexMeshID MEAPI McdConvexMeshCreateHull(McdFrameworkID fw, const MeVector3 vertices[], int count,
                                              MeReal fatness) {
  static const char *fn = "McdConvexMeshCreateHull";
  ME_REQUIRE_ARG_RET(fw != nullptr, nullptr, fn, "framework is NULL");
  ME_REQUIRE_ARG_RET(McdFrameworkIsTypeRegistered(fw, kMcdGeometryTypeConvexMesh), nullptr, fn,
                     "the ConvexMesh type is not registered in this framework");
  ME_REQUIRE_ARG_RET(vertices != nullptr, nullptr, fn, "the point array is NULL");
  ME_REQUIRE_ARG_RET(PositiveFinite(fatness, true), nullptr, fn, "fatness must be finite and >= 0, got %g",
                     (double)fatness);
  Hull hull;
  std::string why;
  ME_REQUIRE_ARG_RET(BuildHull(vertices, count, hull, why), nullptr, fn, "no convex hull: %s", why.c_str());
  std::size_t corners = 0;
  for (const auto &f : hull.faces) corners += f.size();
  const std::size_t nv = hull.vertices.size(), nf = hull.faces.size();
  const std::size_t align = alignof(std::max_align_t);
  auto round = [&](std::size_t b) { return (b + align - 1) / align * align; };
  const std::size_t bytes = round(sizeof(ConvexMesh)) + round(sizeof(MeVector3) * nv) + round(sizeof(MeVector3) * nf) +
                            round(sizeof(int) * (nf + 1)) + round(sizeof(int) * corners);
  McdGeometry *g = NewGeometry(fw, kMcdGeometryTypeConvexMesh, bytes, fn);
  if (!g) return nullptr;
  auto *m = reinterpret_cast<ConvexMesh *>(g);
  char *cursor = reinterpret_cast<char *>(g) + round(sizeof(ConvexMesh));
  m->vertexCount = (int)nv;
  m->faceCount = (int)nf;
  m->vertices = Carve<MeVector3>(cursor, nv);
  m->normals = Carve<MeVector3>(cursor, nf);
  m->faceStart = Carve<int>(cursor, nf + 1);
  m->faceIndex = Carve<int>(cursor, corners);
  for (std::size_t i = 0; i < nv; ++i)
    for (int k = 0; k < 3; ++k) m->vertices[i][k] = (MeReal)hull.vertices[i][(std::size_t)k];
  int at = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    m->faceStart[f] = at;
    for (int idx : hull.faces[f]) m->faceIndex[at++] = idx;
    for (int k = 0; k < 3; ++k) m->normals[f][k] = (MeReal)hull.normals[f][(std::size_t)k];
  }
  m->faceStart[nf] = at;
  m->fatness = fatness;
  double volume, inertia[3][3];
  Vec3d com;
  PolyhedronMass(hull, volume, com, inertia);
  m->volume = (MeReal)volume;
  for (int r = 0; r < 3; ++r) {
    m->com[r] = (MeReal)com[(std::size_t)r];
    for (int q = 0; q < 3; ++q) m->inertia[r][q] = (MeReal)inertia[r][q];
  }
  return g;
}

int MEAPI McdConvexMeshGetVertexCount(McdConvexMeshID g) {
  ConvexMesh *m = Get(g, "McdConvexMeshGetVertexCount");
  return m ? m->vertexCount : 0;
}

const MeReal *MEAPI McdConvexMeshGetVertex(McdConvexMeshID g, int i) {
  static const char *fn = "McdConvexMeshGetVertex";
  ConvexMesh *m = Get(g, fn);
  if (!m) return nullptr;
  ME_REQUIRE_ARG_RET(i >= 0 && i < m->vertexCount, nullptr, fn, "vertex %d out of range [0, %d)", i, m->vertexCount);
  return m->vertices[i];
}

int MEAPI McdConvexMeshGetPolygonCount(McdConvexMeshID g) {
  ConvexMesh *m = Get(g, "McdConvexMeshGetPolygonCount");
  return m ? m->faceCount : 0;
}

int MEAPI McdConvexMeshGetPolygonVertexCount(McdConvexMeshID g, int polygon) {
  static const char *fn = "McdConvexMeshGetPolygonVertexCount";
  ConvexMesh *m = Get(g, fn);
  if (!m) return 0;
  ME_REQUIRE_ARG_RET(polygon >= 0 && polygon < m->faceCount, 0, fn, "polygon %d out of range [0, %d)", polygon,
                     m->faceCount);
  return m->faceStart[polygon + 1] - m->faceStart[polygon];
}

int MEAPI McdConvexMeshGetPolygonVertexIndex(McdConvexMeshID g, int polygon, int corner) {
  static const char *fn = "McdConvexMeshGetPolygonVertexIndex";
  const int n = McdConvexMeshGetPolygonVertexCount(g, polygon);
  if (n == 0) return -1;
  ME_REQUIRE_ARG_RET(corner >= 0 && corner < n, -1, fn, "corner %d out of range [0, %d)", corner, n);
  ConvexMesh *m = reinterpret_cast<ConvexMesh *>(g);
  return m->faceIndex[m->faceStart[polygon] + corner];
}

void MEAPI McdConvexMeshGetPolygonNormal(McdConvexMeshID g, int polygon, MeVector3 normal) {
  static const char *fn = "McdConvexMeshGetPolygonNormal";
  MeVector3Set(normal, 0, 0, 0);
  ConvexMesh *m = Get(g, fn);
  if (!m) return;
  ME_REQUIRE_ARG(polygon >= 0 && polygon < m->faceCount, fn, "polygon %d out of range [0, %d)", polygon, m->faceCount);
  MeVector3Copy(normal, m->normals[polygon]);
}

MeReal MEAPI McdConvexMeshGetFatness(McdConvexMeshID g) {
  ConvexMesh *m = Get(g, "McdConvexMeshGetFatness");
  return m ? m->fatness : 0;
}

}  // extern "C"
