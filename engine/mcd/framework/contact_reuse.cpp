// contact_reuse.cpp: the reuse rule of contact_reuse.h.
#include "contact_reuse.h"

#include <cmath>
#include <limits>

namespace karma::mcd {

namespace {

// A remembered contact: its point in each model's coordinates, its normal
// in model 2's, and the contact as the full test reported it.
struct KeptContact {
  MeReal on1[3], on2[3], normal2[3];
  McdContact contact;
};

// One MeMemoryAPI block: this header, then `capacity` KeptContacts.
struct PairMemory {
  const McdGeometry *geometry1, *geometry2;
  unsigned shapeRevision;
  int cap;
  MeReal tested;          // the tolerance of the full test, t + d
  MeReal reach1, reach2;  // r_1, r_2
  RelativePose pose;      // Q0
  int touch;              // the full test's
  MeReal normal2[3];      // its representative normal, in model 2's coordinates
  int count, capacity;
  KeptContact *contacts() { return reinterpret_cast<KeptContact *>(this + 1); }
  const KeptContact *contacts() const { return reinterpret_cast<const KeptContact *>(this + 1); }
};
static_assert(sizeof(PairMemory) % alignof(KeptContact) == 0, "the contacts follow the header aligned");

const MeReal kInfinity = std::numeric_limits<MeReal>::infinity();

MeReal Dot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

MeMatrix4Ptr TmOf(const McdModel *m) { return m->instance.tm; }

// How far the geometry's surface reaches from its model's origin at most:
// the distance to the farthest corner of its bounds about the origin, or
// infinity for an unbounded shape (a plane).
MeReal Reach(const McdGeometry *g) {
  static const MeMatrix4 kIdentity = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  MeVector3 lo, hi;
  TypeOf(g)->aabb(g, kIdentity, lo, hi);
  MeReal far[3];
  for (int k = 0; k < 3; ++k) far[k] = std::fmax(std::fabs(lo[k]), std::fabs(hi[k]));
  const MeReal r = std::sqrt(Dot3(far, far));
  return std::isfinite(r) ? r : kInfinity;
}

// Whether D = min(D_1, D_2) between the remembered pose and `q` is at most
// `limit`; D_2 (the inverse pose) is computed only when D_1 exceeds it.
bool DriftWithin(const PairMemory &m, const RelativePose &q, MeReal limit) {
  const RelativePose &q0 = m.pose;
  MeReal rotation2 = 0, shift1[3];
  for (int j = 0; j < 3; ++j) {
    shift1[j] = q.p[j] - q0.p[j];
    for (int i = 0; i < 3; ++i) {
      const MeReal e = q.R[j][i] - q0.R[j][i];
      rotation2 += e * e;
    }
  }
  const MeReal rotation = std::sqrt(rotation2);  // |R - R0|_F = |R^T - R0^T|_F
  if (m.reach1 < kInfinity && std::sqrt(Dot3(shift1, shift1)) + rotation * m.reach1 <= limit) return true;
  if (!(m.reach2 < kInfinity)) return false;
  // The inverse pose: p' = -R^T p; its shift is -(R^T p - R0^T p0).
  MeReal shift2[3];
  for (int i = 0; i < 3; ++i) {
    MeReal now = 0, then = 0;
    for (int j = 0; j < 3; ++j) {
      now += q.R[j][i] * q.p[j];
      then += q0.R[j][i] * q0.p[j];
    }
    shift2[i] = now - then;
  }
  return std::sqrt(Dot3(shift2, shift2)) + rotation * m.reach2 <= limit;
}

// Pairs whose full test costs more than remembering it: both shapes a box,
// a cylinder, a sphyl or a convex mesh (clipping, GJK). A sphere's tests
// are a closest point and a plane's a few supports: the pose check and
// the memory would cost about what they save (topple's box-plane pairs
// measured so, docs/NOTES.md).
bool Served(int type1, int type2) {
  const auto clipped = [](int type) {
    return type == kMcdGeometryTypeBox || type == kMcdGeometryTypeCylinder || type == kMcdGeometryTypeSphyl ||
           type == kMcdGeometryTypeConvexMesh;
  };
  return clipped(type1) && clipped(type2);
}

PairMemory *MemoryOf(const McdModelPair *pair) { return static_cast<PairMemory *>(pair->m_contactMemory); }

// Whether the memory was made for the pair's present geometries and sizes.
bool SameShapes(const PairMemory &m, const McdModelPair *pair) {
  return m.geometry1 == pair->model1->instance.geometry && m.geometry2 == pair->model2->instance.geometry &&
         m.shapeRevision == pair->model1->framework->shapeRevision;
}

std::size_t BytesFor(int capacity) { return sizeof(PairMemory) + sizeof(KeptContact) * (std::size_t)capacity; }

// The pair's memory with room for `count` contacts, or NULL.
PairMemory *MemoryWithRoom(McdModelPair *pair, int count) {
  PairMemory *m = MemoryOf(pair);
  if (m && m->capacity >= count) return m;
  const int capacity = count < 4 ? 4 : count;
  void *block = m ? MeMemoryAPI.resize(m, BytesFor(capacity)) : MeMemoryAPI.create(BytesFor(capacity));
  if (!block) return nullptr;
  m = static_cast<PairMemory *>(block);
  m->capacity = capacity;
  pair->m_contactMemory = m;
  return m;
}

// The direction v given in the coordinates of the model with TM tm, in
// the world's.
void Turned(const MeMatrix4Ptr tm, const MeReal *v, MeReal *out) {
  for (int c = 0; c < 3; ++c) out[c] = v[0] * tm[0][c] + v[1] * tm[1][c] + v[2] * tm[2][c];
}

// The world point x in the coordinates of the model with TM tm.
void ToLocal(const MeMatrix4Ptr tm, const MeReal *x, MeReal *y) {
  const MeReal d[3] = {x[0] - tm[3][0], x[1] - tm[3][1], x[2] - tm[3][2]};
  for (int i = 0; i < 3; ++i) y[i] = Dot3(d, tm[i]);
}

}  // namespace

RelativePose PoseOf(const McdModel *m1, const McdModel *m2) {
  const MeMatrix4Ptr t1 = TmOf(m1), t2 = TmOf(m2);
  RelativePose q;
  const MeReal d[3] = {t1[3][0] - t2[3][0], t1[3][1] - t2[3][1], t1[3][2] - t2[3][2]};
  for (int j = 0; j < 3; ++j) {
    q.p[j] = Dot3(d, t2[j]);
    for (int i = 0; i < 3; ++i) q.R[j][i] = Dot3(t1[i], t2[j]);
  }
  return q;
}

MeReal ReuseDistance(const McdModelPair *pair) {
  const McdFramework *fw = pair->model1->framework;
  if (!(fw->contactReuseDistance > 0) || !pair->m_interaction || !pair->m_interaction->m_builtIn) return 0;
  const McdGeometry *g1 = pair->model1->instance.geometry, *g2 = pair->model2->instance.geometry;
  if (!Served(g1->m_type, g2->m_type)) return 0;
  const PairMemory *m = MemoryOf(pair);
  const MeReal smaller = m && SameShapes(*m, pair) ? std::fmin(m->reach1, m->reach2) : std::fmin(Reach(g1), Reach(g2));
  return std::fmin(fw->contactReuseDistance, kShapeFraction * smaller);
}

bool ServeFromMemory(McdModelPair *pair, McdIntersectResult *result, MeReal tolerance, int cap, MeReal distance,
                     const RelativePose &now) {
  const PairMemory *m = MemoryOf(pair);
  const McdModel *m1 = pair->model1, *m2 = pair->model2;
  if (!m || m->cap != cap || !SameShapes(*m, pair)) return false;
  // D <= d and D + t' <= t + d.
  const MeReal limit = std::fmin(distance, m->tested - tolerance);
  if (!(limit >= 0 && DriftWithin(*m, now, limit))) return false;
  const MeMatrix4Ptr t1 = TmOf(m1), t2 = TmOf(m2);
  // Differences of the carried points taken from the difference of the
  // origins, so that their rounding is that of the offsets, not of the
  // world coordinates.
  const MeReal origins[3] = {t1[3][0] - t2[3][0], t1[3][1] - t2[3][1], t1[3][2] - t2[3][2]};
  for (int k = 0; k < m->count; ++k) {
    const KeptContact &kept = m->contacts()[k];
    MeReal r1[3], r2[3], normal[3], gap[3];
    Turned(t1, kept.on1, r1);
    Turned(t2, kept.on2, r2);
    Turned(t2, kept.normal2, normal);
    McdContact &c = result->contacts[k];
    c = kept.contact;
    for (int i = 0; i < 3; ++i) {
      gap[i] = origins[i] + r1[i] - r2[i];
      c.position[i] = t2[3][i] + (MeReal)0.5 * (origins[i] + r1[i] + r2[i]);
      c.normal[i] = normal[i];
    }
    c.separation = kept.contact.separation + Dot3(gap, normal);
  }
  result->contactCount = m->count;
  result->touch = m->touch;
  Turned(t2, m->normal2, result->normal);
  return true;
}

void Remember(McdModelPair *pair, const McdIntersectResult *result, MeReal tested, int cap, const RelativePose &now) {
  const int count = result->contactCount;
  const bool newBlock = pair->m_contactMemory == nullptr;
  PairMemory *m = MemoryWithRoom(pair, count);
  if (!m) {
    Forget(pair);
    return;
  }
  const McdModel *m1 = pair->model1, *m2 = pair->model2;
  if (newBlock || !SameShapes(*m, pair)) {
    m->geometry1 = m1->instance.geometry;
    m->geometry2 = m2->instance.geometry;
    m->shapeRevision = m1->framework->shapeRevision;
    m->reach1 = Reach(m->geometry1);
    m->reach2 = Reach(m->geometry2);
  }
  m->cap = cap;
  m->tested = tested;
  m->touch = result->touch;
  for (int i = 0; i < 3; ++i) m->normal2[i] = Dot3(result->normal, TmOf(m2)[i]);
  m->pose = now;
  m->count = count;
  const MeMatrix4Ptr t1 = TmOf(m1), t2 = TmOf(m2);
  for (int k = 0; k < count; ++k) {
    KeptContact &kept = m->contacts()[k];
    const McdContact &c = result->contacts[k];
    kept.contact = c;
    ToLocal(t1, c.position, kept.on1);
    ToLocal(t2, c.position, kept.on2);
    for (int i = 0; i < 3; ++i) kept.normal2[i] = Dot3(c.normal, t2[i]);
  }
}

bool AllWithin(const McdIntersectResult *result, MeReal tolerance) {
  for (int k = 0; k < result->contactCount; ++k)
    if (!(result->contacts[k].separation <= tolerance)) return false;
  return true;
}

void Forget(McdModelPair *pair) {
  if (pair->m_contactMemory) MeMemoryAPI.destroy(pair->m_contactMemory);
  pair->m_contactMemory = nullptr;
}

}  // namespace karma::mcd
