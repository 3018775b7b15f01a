/* line.cpp: lines as RGraphics (RGraphicLineCreate) and native lines
 * (RNLineCreate).
 *
 * An RGraphic line is one triangle (origin, end, end) drawn in wireframe:
 * its edges are the segment twice and a point, so it shows as the segment
 * with the graphic's colour, lit like any other graphic. MoveEnds rewrites
 * the three vertices. A native line is drawn unlit with GL_LINES. */
#include "viewer_internal.h"

#include <cmath>

namespace {

bool Finite3(const AcmeReal *p) {
  return std::isfinite(double(p[0])) && std::isfinite(double(p[1])) && std::isfinite(double(p[2]));
}

void SetEnds(RGraphic *g, const AcmeReal *o, const AcmeReal *e) {
  RObjectVertex *v = g->m_pVertices;
  RSetVertex(&v[0], float(o[0]), float(o[1]), float(o[2]), 0, 1, 0, 0, 0);
  RSetVertex(&v[1], float(e[0]), float(e[1]), float(e[2]), 0, 1, 0, 1, 0);
  v[2] = v[1];
}

/* A line graphic is recognised by its shape: wireframe, three vertices,
 * the last two equal. */
bool IsLine(const RGraphic *g) {
  const RObjectVertex *v = g->m_pVertices;
  return g->m_pObject->m_bIsWireFrame && g->m_pObject->m_nNumVertices == 3 && v[1].m_X == v[2].m_X &&
         v[1].m_Y == v[2].m_Y && v[1].m_Z == v[2].m_Z;
}

}  // namespace

RGraphic *MEAPI RGraphicLineCreate(RRender *rc, AcmeReal *origin, AcmeReal *end, const float color[4],
                                   MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG_RET(rc && origin && end, nullptr, "RGraphicLineCreate", "rc, origin or end is NULL");
  ME_REQUIRE_ARG_RET(Finite3(origin) && Finite3(end), nullptr, "RGraphicLineCreate", "the ends must be finite");
  RGraphic *g = RGraphicCreateSized(3, 3);
  if (!g) return nullptr;
  SetEnds(g, origin, end);
  g->m_pObject->m_bIsWireFrame = 1;
  return RGraphicFinishPrimitive(rc, g, color, matrix, 0);
}

int MEAPI RGraphicLineMoveEnds(RGraphic *lineG, AcmeReal *origin, AcmeReal *end) {
  if (!lineG || !origin || !end) {
    MeWarning(0, "RGraphicLineMoveEnds: lineG, origin or end is NULL");
    return 1;
  }
  if (!IsLine(lineG)) {
    MeWarning(0, "RGraphicLineMoveEnds: the graphic is not a line made by RGraphicLineCreate");
    return 1;
  }
  if (!Finite3(origin) || !Finite3(end)) {
    MeWarning(0, "RGraphicLineMoveEnds: the ends must be finite");
    return 1;
  }
  SetEnds(lineG, origin, end);
  return 0;
}

RNativeLine *MEAPI RNLineCreate(RRender *const rc, const AcmeReal start[3], const AcmeReal end[3],
                                const AcmeReal color[4], const MeVector4 *const matrix) {
  ME_REQUIRE_ARG_RET(rc && start && end, nullptr, "RNLineCreate", "rc, start or end is NULL");
  RNativeLine *l = static_cast<RNativeLine *>(MeMemoryAPI.createZeroed(sizeof(RNativeLine)));
  if (!l) {
    MeWarning(0, "RNLineCreate: out of memory");
    return nullptr;
  }
  RNLineMoveEnds(l, start, end);
  for (int i = 0; i < 4; ++i) l->m_Color[i] = color ? float(color[i]) : 1.0f;
  l->m_pMatrix = matrix;
  RNativeLine **link = &rc->m_pNL_First;
  while (*link) link = &(*link)->m_pNext;
  *link = l;
  return l;
}

void MEAPI RNLineMoveEnds(RNativeLine *const line, const AcmeReal start[3], const AcmeReal end[3]) {
  ME_REQUIRE_ARG(line && start && end, "RNLineMoveEnds", "line, start or end is NULL");
  for (int i = 0; i < 3; ++i) line->m_Start[i] = start[i], line->m_End[i] = end[i];
}
