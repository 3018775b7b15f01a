// line_segment.cpp: McdLineSegIntersect, a segment against one model.
//
// The segment is mapped into each geometry instance's frame (a rigid map
// keeps the parameter t of every point), tested there (segment_shapes.h),
// and the hit is mapped back. An aggregate takes its earliest child hit;
// children carry their world TMs since the model's last update.
#include <cmath>
#include <vector>

#include "MeMessage.h"
#include "McdLineSegment.h"
#include "mcd_internal.h"
#include "query_internal.h"
#include "segment_shapes.h"

namespace karma::mcd::query {

namespace {

bool ConvexHit(McdGeometry *g, const MeVector3 a, const MeVector3 b, SegmentHit &hit) {
  const int faces = McdConvexMeshGetPolygonCount(g);
  std::vector<MeReal> offsets((size_t)faces);
  std::vector<MeReal> normals((size_t)faces * 3);
  for (int i = 0; i < faces; ++i) {
    MeReal *n = &normals[(size_t)i * 3];
    McdConvexMeshGetPolygonNormal(g, i, n);
    const MeReal *v = McdConvexMeshGetVertex(g, McdConvexMeshGetPolygonVertexIndex(g, i, 0));
    offsets[(size_t)i] = MeVector3Dot(n, v);
  }
  return SegmentHalfSpaces(a, b, reinterpret_cast<const MeVector3 *>(normals.data()), offsets.data(), faces, hit);
}

// The segment (world frame) against one geometry in its own frame.
bool LocalHit(McdGeometry *g, const MeVector3 a, const MeVector3 b, SegmentHit &hit) {
  switch (g->m_type) {
    case kMcdGeometryTypeSphere:
      return SegmentSphere(a, b, McdSphereGetRadius(g), hit);
    case kMcdGeometryTypeBox: {
      MeVector3 half;
      McdBoxGetRadii(g, half);
      return SegmentBox(a, b, half, hit);
    }
    case kMcdGeometryTypeCylinder:
      return SegmentCylinder(a, b, McdCylinderGetRadius(g), McdCylinderGetHeight(g), hit);
    case kMcdGeometryTypeSphyl:
      return SegmentSphyl(a, b, McdSphylGetRadius(g), McdSphylGetHeight(g), hit);
    case kMcdGeometryTypePlane:
      return SegmentPlane(a, b, hit);
    case kMcdGeometryTypeConvexMesh:
      return ConvexHit(g, a, b, hit);
    default:  // triangle lists (ignored by the guide's rule) and user types
      return false;
  }
}

// Earliest hit of the world segment on an instance tree; the normal comes
// back in the world frame.
bool InstanceHit(const McdGeometryInstance *inst, const MeVector3 a, const MeVector3 b, SegmentHit &hit) {
  if (!inst || !inst->geometry) return false;
  if (inst->geometry->m_type == kMcdGeometryTypeAggregate) {
    bool any = false;
    for (int i = 0; i < inst->childCount; ++i) {
      SegmentHit h;
      if (InstanceHit(inst->children[i], a, b, h) && (!any || h.t < hit.t)) {
        hit = h;
        any = true;
      }
    }
    return any;
  }
  MeVector3 la, lb;
  MeMatrix4TMInverseTransform(la, inst->tm, a);
  MeMatrix4TMInverseTransform(lb, inst->tm, b);
  SegmentHit local;
  if (!LocalHit(inst->geometry, la, lb, local)) return false;
  hit.t = local.t;
  MeMatrix4TMRotate(hit.normal, inst->tm, local.normal);
  return true;
}

bool Finite3(const MeReal *v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

}  // namespace

bool SegmentModel(McdModelID model, const MeVector3 a, const MeVector3 b, McdLineSegIntersectResult *out) {
  SegmentHit hit;
  if (!model->instance.tm || !InstanceHit(&model->instance, a, b, hit)) return false;
  MeVector3 d;
  MeVector3Subtract(d, b, a);
  out->model = model;
  for (int i = 0; i < 3; ++i) {
    out->position[i] = a[i] + hit.t * d[i];
    out->normal[i] = hit.normal[i];
  }
  if (hit.t == 0) MeVector3Copy(out->position, a);
  out->distance = hit.t * MeVector3Magnitude(d);
  return true;
}

bool ValidSegmentArgs(const void *model, const MeReal *a, const MeReal *b, const void *out, const char *fn) {
  if (!model || !a || !b || !out) {
    MeWarning(0, "%s: NULL argument", fn);
    return false;
  }
  if (!Finite3(a) || !Finite3(b)) {
    MeWarning(0, "%s: the segment's end points are not finite", fn);
    return false;
  }
  return true;
}

}  // namespace karma::mcd::query

unsigned int MEAPI McdLineSegIntersect(const McdModelID cm, MeVector3Ptr inOrig, MeVector3Ptr inDest,
                                       McdLineSegIntersectResult *outOverlap) {
  using namespace karma::mcd::query;
  if (!ValidSegmentArgs(cm, inOrig, inDest, outOverlap, "McdLineSegIntersect")) return 0;
  return SegmentModel(cm, inOrig, inDest, outOverlap) ? 1u : 0u;
}
