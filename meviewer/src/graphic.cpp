/* graphic.cpp: RGraphic memory, render lists, colour and transform.
 *
 * Memory layout (the guide's): one block from MeMemoryAPI holding the
 * RObjectHeader, padding to a 16-byte boundary, then m_nMaxNumVertices
 * RObjectVertex records; the RGraphic itself is a second block. The vertex
 * pointer is kept equal to the address just after the padded header. */
#include "viewer_internal.h"

#include <cstring>

namespace {

constexpr std::size_t kHeaderBytes = (sizeof(RObjectHeader) + 15) / 16 * 16;

RObjectHeader *AllocateObject(int numVertices) {
  const std::size_t bytes = kHeaderBytes + sizeof(RObjectVertex) * std::size_t(numVertices > 0 ? numVertices : 0);
  return static_cast<RObjectHeader *>(MeMemoryAPI.createZeroed(bytes));
}

RGraphic **ListHead(RRender *rc, int is2D) { return is2D ? &rc->m_pRG_First2D : &rc->m_pRG_First; }

}  // namespace

void RSetVertex(RObjectVertex *v, float x, float y, float z, float nx, float ny, float nz, float u, float w) {
  v->m_X = x, v->m_Y = y, v->m_Z = z;
  v->m_NX = nx, v->m_NY = ny, v->m_NZ = nz;
  v->m_U = u, v->m_V = w;
}

RGraphic *RGraphicCreateSized(int numVertices, int numUsed) {
  if (numVertices < 0 || numVertices > (1 << 26)) {
    MeWarning(0, "RGraphicCreateEmpty: %d vertices is out of range (0..%d)", numVertices, 1 << 26);
    return nullptr;
  }
  RGraphic *g = static_cast<RGraphic *>(MeMemoryAPI.createZeroed(sizeof(RGraphic)));
  RObjectHeader *h = AllocateObject(numVertices);
  if (!g || !h) {
    MeMemoryAPI.destroy(g);
    MeMemoryAPI.destroy(h);
    MeWarning(0, "RGraphicCreateEmpty: out of memory for %d vertices", numVertices);
    return nullptr;
  }
  g->m_pObject = h;
  g->m_pVertices = reinterpret_cast<RObjectVertex *>(reinterpret_cast<char *>(h) + kHeaderBytes);
  g->m_nMaxNumVertices = numVertices;
  MeMatrix4TMMakeIdentity(h->m_Matrix);
  h->m_nNumVertices = numUsed;
  h->m_nTextureID = -1;
  const float white[4] = {1, 1, 1, 1};
  RGraphicSetColor(g, white);
  return g;
}

RGraphic *RGraphicFinishPrimitive(RRender *rc, RGraphic *rg, const float color[4], MeMatrix4Ptr matrix, int is2D) {
  static const float white[4] = {1, 1, 1, 1};
  RGraphicSetColor(rg, color ? color : white);
  if (!is2D) {
    for (int i = 0; i < 3; ++i) rg->m_pObject->m_ColorSpecular[i] = 0.25f;
    rg->m_pObject->m_ColorSpecular[3] = 1;
    rg->m_pObject->m_SpecularPower = 32;
  }
  rg->m_pLWMatrix = matrix;
  RGraphicAddToList(rc, rg, is2D);
  return rg;
}

RGraphic *MEAPI RGraphicCreateEmpty(int numVertices) { return RGraphicCreateSized(numVertices, 0); }

void MEAPI RGraphicDestroy(RGraphic *rg) {
  if (!rg) return;
  MeMemoryAPI.destroy(rg->m_pObject);
  MeMemoryAPI.destroy(rg);
}

void MEAPI RGraphicAddToList(RRender *rc, RGraphic *rg, int is2D) {
  ME_REQUIRE_ARG(rc && rg, "RGraphicAddToList", "rc or rg is NULL");
  RGraphic **head = ListHead(rc, is2D);
  for (RGraphic *g = *head; g; g = g->m_pNext)
    if (g == rg) {
      MeWarning(0, "RGraphicAddToList: the graphic is already in the %s list", is2D ? "2D" : "3D");
      return;
    }
  /* Appended, so graphics draw in the order they were added. */
  rg->m_pNext = nullptr;
  while (*head) head = &(*head)->m_pNext;
  *head = rg;
}

void MEAPI RGraphicRemoveFromList(RRender *rc, RGraphic *rg, int is2D) {
  ME_REQUIRE_ARG(rc && rg, "RGraphicRemoveFromList", "rc or rg is NULL");
  for (RGraphic **link = ListHead(rc, is2D); *link; link = &(*link)->m_pNext)
    if (*link == rg) {
      *link = rg->m_pNext;
      rg->m_pNext = nullptr;
      return;
    }
  MeWarning(0, "RGraphicRemoveFromList: the graphic is not in the %s list", is2D ? "2D" : "3D");
}

void MEAPI RGraphicDelete(RRender *rc, RGraphic *rg, int is2D) {
  ME_REQUIRE_ARG(rc && rg, "RGraphicDelete", "rc or rg is NULL");
  RGraphicRemoveFromList(rc, rg, is2D);
  RGraphicDestroy(rg);
}

void MEAPI RGraphicSetTransformPtr(RGraphic *g, MeMatrix4Ptr matrix) {
  ME_REQUIRE_ARG(g, "RGraphicSetTransformPtr", "g is NULL");
  g->m_pLWMatrix = matrix;
}

void MEAPI RGraphicSetColor(RGraphic *g, const float color[4]) {
  ME_REQUIRE_ARG(g && color, "RGraphicSetColor", "g or color is NULL");
  RObjectHeader *h = g->m_pObject;
  for (int i = 0; i < 4; ++i) {
    h->m_ColorAmbient[i] = color[i];
    h->m_ColorDiffuse[i] = color[i];
    h->m_ColorEmissive[i] = 0;
    h->m_ColorSpecular[i] = 0;
  }
}

void MEAPI RGraphicGetColor(RGraphic *g, float color[4]) {
  ME_REQUIRE_ARG(g && color, "RGraphicGetColor", "g or color is NULL");
  for (int i = 0; i < 4; ++i) color[i] = g->m_pObject->m_ColorAmbient[i];
}

void MEAPI RGraphicSetWireframe(RGraphic *g, MeBool wireframe) {
  ME_REQUIRE_ARG(g, "RGraphicSetWireframe", "g is NULL");
  g->m_pObject->m_bIsWireFrame = wireframe ? 1 : 0;
}

/* Strip vertices s0 s1 s2 s3 ... give triangles (s0 s1 s2), (s2 s1 s3),
 * (s2 s3 s4), ...: every odd triangle swaps its first two vertices so all
 * keep the strip's winding. */
void MEAPI RConvertTriStripToTriList(RGraphic *rg, RObjectVertex *strips, int *stripSize, int *stripStart,
                                     int numStrips) {
  ME_REQUIRE_ARG(rg && (numStrips <= 0 || (strips && stripSize && stripStart)), "RConvertTriStripToTriList",
                 "rg, strips, stripSize or stripStart is NULL");
  long add = 0;
  for (int s = 0; s < numStrips; ++s) {
    if (stripSize[s] < 0 || stripStart[s] < 0) {
      MeWarning(0, "RConvertTriStripToTriList: strip %d has a negative size or start", s);
      return;
    }
    if (stripSize[s] >= 3) add += 3L * (stripSize[s] - 2);
  }
  RObjectHeader *h = rg->m_pObject;
  const long need = long(h->m_nNumVertices) + add;
  if (need > (1L << 26)) {
    MeWarning(0, "RConvertTriStripToTriList: %ld vertices is too many", need);
    return;
  }
  if (need > rg->m_nMaxNumVertices) {
    RObjectHeader *bigger = AllocateObject(int(need));
    if (!bigger) {
      MeWarning(0, "RConvertTriStripToTriList: out of memory");
      return;
    }
    std::memcpy(bigger, h, kHeaderBytes + sizeof(RObjectVertex) * std::size_t(h->m_nNumVertices));
    MeMemoryAPI.destroy(h);
    rg->m_pObject = h = bigger;
    rg->m_pVertices = reinterpret_cast<RObjectVertex *>(reinterpret_cast<char *>(h) + kHeaderBytes);
    rg->m_nMaxNumVertices = int(need);
  }
  RObjectVertex *out = rg->m_pVertices + h->m_nNumVertices;
  for (int s = 0; s < numStrips; ++s) {
    const RObjectVertex *v = strips + stripStart[s];
    for (int i = 0; i + 2 < stripSize[s]; ++i) {
      const bool odd = i % 2 != 0;
      *out++ = v[odd ? i + 1 : i];
      *out++ = v[odd ? i : i + 1];
      *out++ = v[i + 2];
    }
  }
  h->m_nNumVertices = int(need);
}
