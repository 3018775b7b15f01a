// aggregate.cpp: the aggregate geometry: up to maxCount elements, each a
// geometry with a relative TM kept by pointer. Each element slot holds one
// reference to its geometry.
//
// Mass properties (density 1), element i of volume m_i, centre c_i and
// inertia I_i in its own frame, relTM rotation R_i (rows = element axes in
// the aggregate frame) and translation t_i:
//   c_i' = c_i R_i + t_i,   M = sum m_i,   c = sum m_i c_i' / M
//   I = sum [ R_i^T I_i R_i + m_i (|d_i|^2 E - d_i d_i^T) ],  d_i = c_i' - c
#include "shape_util.h"

using namespace karma::mcd;

namespace {

McdAggregateData *Get(McdGeometry *g, const char *fn) { return As<McdAggregateData>(g, kMcdGeometryTypeAggregate, fn); }

void Release(McdGeometry *g) { AggregateDropElements(g); }

void Aabb(const McdGeometry *g, MECONSTMATRIX MeMatrix4 tm, MeVector3 mn, MeVector3 mx) {
  auto *a = reinterpret_cast<const McdAggregateData *>(g);
  MeVector3Set(mn, MEINFINITY, MEINFINITY, MEINFINITY);
  MeVector3Set(mx, -MEINFINITY, -MEINFINITY, -MEINFINITY);
  if (a->count == 0) {  // an empty aggregate is a point at its origin
    MeVector3Copy(mn, tm[3]);
    MeVector3Copy(mx, tm[3]);
    return;
  }
  for (int i = 0; i < a->count; ++i) {
    MeMatrix4 world;
    MeMatrix4TMCompose(world, a->relTMs[i], tm);
    MeVector3 emn, emx;
    TypeOf(a->elements[i])->aabb(a->elements[i], world, emn, emx);
    for (int j = 0; j < 3; ++j) {
      mn[j] = std::fmin(mn[j], emn[j]);
      mx[j] = std::fmax(mx[j], emx[j]);
    }
  }
}

bool Mass(const McdGeometry *g, MeReal *volume, MeVector3 com, MeMatrix3 I) {
  auto *a = reinterpret_cast<const McdAggregateData *>(g);
  double M = 0, c[3] = {0, 0, 0}, J[3][3] = {};
  // Two passes: total mass and centre first, then the inertia about it.
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < a->count; ++i) {
      MeReal v;
      MeVector3 ci, cw;
      MeMatrix3 Ii;
      const GeometryType *t = TypeOf(a->elements[i]);
      if (!t->mass(a->elements[i], &v, ci, Ii)) continue;
      MeMatrix4TMTransform(cw, a->relTMs[i], ci);
      if (pass == 0) {
        M += v;
        for (int k = 0; k < 3; ++k) c[k] += v * cw[k];
        continue;
      }
      const MeVector4 *R = a->relTMs[i];
      double d[3], dd = 0;
      for (int k = 0; k < 3; ++k) d[k] = cw[k] - c[k], dd += d[k] * d[k];
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) {
          double rot = 0;  // (R^T Ii R)[r][q] = sum_kl R[k][r] Ii[k][l] R[l][q]
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) rot += R[k][r] * Ii[k][l] * R[l][q];
          J[r][q] += rot + v * ((r == q ? dd : 0) - d[r] * d[q]);
        }
    }
    if (pass == 0) {
      if (!(M > 0)) return false;
      for (double &x : c) x /= M;
    }
  }
  *volume = (MeReal)M;
  for (int r = 0; r < 3; ++r) {
    com[r] = (MeReal)c[r];
    for (int q = 0; q < 3; ++q) I[r][q] = (MeReal)J[r][q];
  }
  return true;
}

}  // namespace

const GeometryType karma::mcd::kAggregateType = {"Aggregate", Release, Aabb, Mass};

void karma::mcd::AggregateDropElements(McdGeometry *g) {
  auto *a = reinterpret_cast<McdAggregateData *>(g);
  for (int i = 0; i < a->count; ++i) --a->elements[i]->m_refCount;
  a->count = 0;
}

extern "C" {

McdAggregateID MEAPI McdAggregateCreate(McdFrameworkID fw, int maxChildren) {
  static const char *fn = "McdAggregateCreate";
  ME_REQUIRE_ARG_RET(maxChildren > 0, nullptr, fn, "maxChildren must be positive, got %d", maxChildren);
  const std::size_t n = (std::size_t)maxChildren;
  const std::size_t head = (sizeof(McdAggregateData) + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) *
                           alignof(std::max_align_t);
  McdGeometry *g =
      NewGeometry(fw, kMcdGeometryTypeAggregate, head + n * (sizeof(McdGeometry *) + sizeof(MeMatrix4Ptr)), fn);
  if (!g) return nullptr;
  auto *a = reinterpret_cast<McdAggregateData *>(g);
  a->maxCount = maxChildren;
  a->elements = reinterpret_cast<McdGeometry **>(reinterpret_cast<char *>(g) + head);
  a->relTMs = reinterpret_cast<MeMatrix4Ptr *>(a->elements + n);
  return g;
}

int MEAPI McdAggregateAddElement(McdAggregateID agg, McdGeometryID geom, MeMatrix4Ptr relTM) {
  static const char *fn = "McdAggregateAddElement";
  McdAggregateData *a = Get(agg, fn);
  if (!a) return -1;
  ME_REQUIRE_ARG_RET(geom != nullptr && relTM != nullptr, -1, fn, "geometry or relTM is NULL");
  ME_REQUIRE_ARG_RET(geom != agg, -1, fn, "an aggregate cannot contain itself");
  ME_REQUIRE_ARG_RET(geom->m_framework == agg->m_framework, -1, fn, "the element belongs to another framework");
  const int t = geom->m_type;
  ME_REQUIRE_ARG_RET(t != kMcdGeometryTypePlane && t != kMcdGeometryTypeTriangleList, -1, fn,
                     "a %s cannot be an aggregate element", McdGeometryGetTypeName(geom));
  ME_REQUIRE_ARG_RET(agg->m_refCount == 0, -1, fn,
                     "the aggregate is already used by a model or another aggregate; add "
                     "every element before using it");
  ME_REQUIRE_ARG_RET(a->count < a->maxCount, -1, fn, "the aggregate is full (%d elements)", a->maxCount);
  ME_REQUIRE_ARG_RET(IsFiniteTM(relTM) && MeMatrix4IsTM(relTM, (MeReal)1e-3), -1, fn,
                     "relTM is not a finite rigid transform");
  a->elements[a->count] = geom;
  a->relTMs[a->count] = relTM;
  ++geom->m_refCount;
  return a->count++;
}

int MEAPI McdAggregateGetElementCount(McdAggregateID agg) {
  McdAggregateData *a = Get(agg, "McdAggregateGetElementCount");
  return a ? a->count : 0;
}

int MEAPI McdAggregateGetElementMaxCount(McdAggregateID agg) {
  McdAggregateData *a = Get(agg, "McdAggregateGetElementMaxCount");
  return a ? a->maxCount : 0;
}

McdGeometryID MEAPI McdAggregateGetElementGeometry(McdAggregateID agg, int i) {
  static const char *fn = "McdAggregateGetElementGeometry";
  McdAggregateData *a = Get(agg, fn);
  if (!a) return nullptr;
  ME_REQUIRE_ARG_RET(i >= 0 && i < a->count, nullptr, fn, "element %d out of range [0, %d)", i, a->count);
  return a->elements[i];
}

MeMatrix4Ptr MEAPI McdAggregateGetElementTransformPtr(McdAggregateID agg, int i) {
  static const char *fn = "McdAggregateGetElementTransformPtr";
  McdAggregateData *a = Get(agg, fn);
  if (!a) return nullptr;
  ME_REQUIRE_ARG_RET(i >= 0 && i < a->count, nullptr, fn, "element %d out of range [0, %d)", i, a->count);
  return a->relTMs[i];
}

}  // extern "C"
