// shape.cpp: building convex shapes from geometries; support points;
// supporting features; face normals.
//
// Support along d (local dl = R d): box (sgn dl_i h_i); cylinder r dl_xy/|dl_xy|
// + sgn(dl_z) h/2 z; sphyl sgn(dl_z) h/2 z; hull the vertex of largest
// v . dl; triangle the corner of largest c . d; then + margin d/|d|.
#include "convex/shape.h"

#include "geometry/convex_internal.h"

namespace karma::mcd::convex {

namespace {

double Sgn(double x) { return x < 0 ? -1 : 1; }

// Vertex of the hull with the largest dot with local dl.
int HullSupport(const ConvexMesh *m, V dl) {
  int best = 0;
  double bv = -INFINITY;
  for (int i = 0; i < m->vertexCount; ++i) {
    const double v = Dot(FromMe(m->vertices[i]), dl);
    if (v > bv) bv = v, best = i;
  }
  return best;
}

// Pushes the points of the polygon-or-vertex of a flat-faced core (hull or
// triangle) supporting along d; faces need a normal within ~78 degrees of d.
int PolyFeature(const Shape &s, V d, V out[16], int *dims, int *id) {
  if (s.kind == Kind::Triangle) {
    const double c = Dot(s.triN, d);
    if (std::fabs(c) >= 0.2) {
      for (int i = 0; i < 3; ++i) out[i] = s.tri[i];
      *dims = 2;
      *id = 8;
      return 3;
    }
    double best = -INFINITY;
    for (int i = 0; i < 3; ++i) best = std::fmax(best, Dot(s.tri[i], d));
    int n = 0;
    *id = 0;
    for (int i = 0; i < 3; ++i)
      if (Dot(s.tri[i], d) >= best - 1e-9 * s.scale) out[n++] = s.tri[i], *id |= 1 << i;
    *dims = n - 1;
    return n;
  }
  const ConvexMesh *m = s.mesh;
  const V dl = s.Local(d);
  int face = -1;
  double bc = 0.2;
  for (int f = 0; f < m->faceCount; ++f) {
    const double c = Dot(FromMe(m->normals[f]), dl);
    if (c > bc) bc = c, face = f;
  }
  const V shift = s.margin * d;
  if (face < 0 || m->faceStart[face + 1] - m->faceStart[face] > 16) {
    const int v = HullSupport(m, dl);
    out[0] = s.World(FromMe(m->vertices[v])) + shift;
    *dims = 0;
    *id = 2 * v;
    return 1;
  }
  *id = 2 * face + 1;
  int n = 0;
  for (int k = m->faceStart[face]; k < m->faceStart[face + 1]; ++k)
    out[n++] = s.World(FromMe(m->vertices[m->faceIndex[k]])) + shift;
  *dims = 2;
  return n;
}

}  // namespace

bool MakeShape(const McdGeometry *gc, MECONSTMATRIX MeMatrix4 tm, Shape &s) {
  auto *g = const_cast<McdGeometry *>(gc);
  s = Shape{};
  for (int i = 0; i < 3; ++i) s.axis[i] = FromMe(tm[i]);
  s.t = FromMe(tm[3]);
  switch (McdGeometryGetTypeId(g)) {
    case kMcdGeometryTypeSphere:
      s.kind = Kind::Sphere;
      s.margin = McdSphereGetRadius(g);
      s.scale = s.margin;
      break;
    case kMcdGeometryTypeBox: {
      MeVector3 h;
      McdBoxGetRadii(g, h);
      s.kind = Kind::Box;
      s.half = FromMe(h);
      s.scale = Len(s.half);
      break;
    }
    case kMcdGeometryTypeCylinder:
      s.kind = Kind::Cylinder;
      s.r = McdCylinderGetRadius(g);
      s.hh = McdCylinderGetHeight(g) / 2;
      s.scale = std::hypot(s.r, s.hh);
      break;
    case kMcdGeometryTypeSphyl:
      s.kind = Kind::Sphyl;
      s.margin = McdSphylGetRadius(g);
      s.hh = McdSphylGetHeight(g) / 2;
      s.scale = s.margin + s.hh;
      break;
    case kMcdGeometryTypeConvexMesh: {
      s.kind = Kind::Hull;
      s.mesh = reinterpret_cast<const ConvexMesh *>(gc);
      s.margin = s.mesh->fatness;
      double far = 0;
      for (int i = 0; i < s.mesh->vertexCount; ++i) far = std::fmax(far, Len(FromMe(s.mesh->vertices[i])));
      s.scale = far + s.margin;
      break;
    }
    default:
      return false;
  }
  return std::isfinite(s.scale) && s.scale > 0 && Finite(s.t);
}

void MakeTriangle(V a, V b, V c, Shape &s) {
  s = Shape{};
  s.kind = Kind::Triangle;
  s.tri[0] = a, s.tri[1] = b, s.tri[2] = c;
  s.triN = Unit(Cross(b - a, c - a));
  s.t = (1.0 / 3) * (a + b + c);
  s.axis[0] = {1, 0, 0}, s.axis[1] = {0, 1, 0}, s.axis[2] = {0, 0, 1};
  s.scale = std::fmax(std::fmax(Len(a - s.t), Len(b - s.t)), Len(c - s.t));
  if (!(s.scale > 0)) s.scale = 1;
}

V Support(const Shape &s, V d) {
  const V dl = s.Local(d);
  V p;
  switch (s.kind) {
    case Kind::Sphere:
      break;
    case Kind::Box:
      p = {Sgn(dl.x) * s.half.x, Sgn(dl.y) * s.half.y, Sgn(dl.z) * s.half.z};
      break;
    case Kind::Cylinder: {
      const double rad = std::hypot(dl.x, dl.y);
      if (rad > 0) p = {s.r * dl.x / rad, s.r * dl.y / rad, 0};
      p.z = Sgn(dl.z) * s.hh;
      break;
    }
    case Kind::Sphyl:
      p.z = Sgn(dl.z) * s.hh;
      break;
    case Kind::Hull:
      p = FromMe(s.mesh->vertices[HullSupport(s.mesh, dl)]);
      break;
    case Kind::Triangle: {
      int best = 0;
      for (int i = 1; i < 3; ++i)
        if (Dot(s.tri[i], d) > Dot(s.tri[best], d)) best = i;
      return s.tri[best];
    }
  }
  V w = s.World(p);
  if (s.margin > 0) w = w + s.margin * Unit(d);
  return w;
}

V Centre(const Shape &s) { return s.t; }

int Feature(const Shape &s, V d, V out[16], int *dims, int *idOut) {
  int scratch = 0;
  int *id = idOut ? idOut : &scratch;
  *id = 0;
  const V a = s.axis[2];
  const double ad = Dot(a, d);
  switch (s.kind) {
    case Kind::Sphere:
      out[0] = s.t + s.margin * d;
      *dims = 2;
      return 1;
    case Kind::Sphyl:  // side line when the axis is within ~6 degrees of level
      if (std::fabs(ad) < 0.1 && s.hh > 0) {
        out[0] = s.t + s.hh * a + s.margin * d;
        out[1] = s.t - s.hh * a + s.margin * d;
        *dims = 1;
        return 2;
      }
      out[0] = Support(s, d);
      *dims = 2;
      *id = ad < 0 ? 1 : 2;
      return 1;
    case Kind::Cylinder: {
      if (std::fabs(ad) >= 0.7) {  // the cap facing d, 8 rim points
        const V c = s.t + (Sgn(ad) * s.hh) * a;
        const double k = std::sqrt(0.5);
        const double cs[8][2] = {{1, 0}, {k, k}, {0, 1}, {-k, k}, {-1, 0}, {-k, -k}, {0, -1}, {k, -k}};
        for (int i = 0; i < 8; ++i) out[i] = c + (s.r * cs[i][0]) * s.axis[0] + (s.r * cs[i][1]) * s.axis[1];
        *dims = 2;
        *id = ad < 0 ? 1 : 2;
        return 8;
      }
      const V radial = Unit(d - ad * a);  // the side line facing d
      out[0] = s.t + s.r * radial + s.hh * a;
      out[1] = s.t + s.r * radial - s.hh * a;
      *dims = 1;
      *id = 3;
      return 2;
    }
    case Kind::Box: {
      const V dl = s.Local(d);
      int i = 0;
      for (int k = 1; k < 3; ++k)
        if (std::fabs(dl[k]) > std::fabs(dl[i])) i = k;
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const V c = s.t + (Sgn(dl[i]) * s.half[i]) * s.axis[i];
      const V u = s.half[j] * s.axis[j], v = s.half[k] * s.axis[k];
      out[0] = c + u + v, out[1] = c - u + v, out[2] = c - u - v, out[3] = c + u - v;
      *dims = 2;
      *id = 2 * i + (dl[i] < 0 ? 1 : 0);
      return 4;
    }
    case Kind::Hull:
    case Kind::Triangle:
      return PolyFeature(s, d, out, dims, id);
  }
  return 0;
}

int FaceCount(const Shape &s) { return s.kind == Kind::Hull ? s.mesh->faceCount : 6; }

int FaceNormals(const Shape &s, V out[], int max) {
  int n = 0;
  auto push = [&](V v) {
    if (n < max) out[n++] = v;
  };
  switch (s.kind) {
    case Kind::Box:
      for (int i = 0; i < 3; ++i) push(s.axis[i]), push(-s.axis[i]);
      break;
    case Kind::Cylinder:
      push(s.axis[2]), push(-s.axis[2]);
      break;
    case Kind::Triangle:
      push(s.triN), push(-s.triN);
      break;
    case Kind::Hull:
      for (int f = 0; f < s.mesh->faceCount; ++f) {
        const V nl = FromMe(s.mesh->normals[f]);
        push(nl.x * s.axis[0] + nl.y * s.axis[1] + nl.z * s.axis[2]);
      }
      break;
    default:
      break;
  }
  return n;
}

}  // namespace karma::mcd::convex
