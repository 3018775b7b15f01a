/* text.cpp: RGraphicTextCreate, text as textured quads in the 2D list.
 *
 * A character at pen position px on line l is the quad [px, px + W] x
 * [y + l H, y + (l+1) H] in 2D units (W = R_TEXT_CHAR_WIDTH, H =
 * R_TEXT_CHAR_HEIGHT; '\n' starts a new line at px = x), mapped onto the character's
 * cell of the font texture (font.cpp): 2 texels per 2D unit, the first
 * 2W x 2H texels of the cell. The pen then moves by the character's
 * own advance (FontAdvance), so spacing is proportional. Spaces take room
 * but no quad;
 * The text is put through RParseText first. Characters outside printable ASCII (32..126) show as '?'. */
#include "viewer_internal.h"

#include <cmath>
#include <cstring>

using namespace karma::viewer;

RGraphic *MEAPI RGraphicTextCreate(RRender *rc, char *text_in, AcmeReal x, AcmeReal y, const float color[4]) {
  ME_REQUIRE_ARG_RET(rc && text_in, nullptr, "RGraphicTextCreate", "rc or text is NULL");
  const std::string parsed = ParseText(rc, text_in); /* $ variables, as the guide says */
  const char *text = parsed.c_str();
  ME_REQUIRE_ARG_RET(std::isfinite(double(x)) && std::isfinite(double(y)), nullptr, "RGraphicTextCreate",
                     "x and y must be finite");
  int quads = 0;
  for (const char *c = text; *c; ++c)
    if (*c != '\n' && *c != ' ') ++quads;
  RGraphic *g = RGraphicCreateSized(6 * quads, 6 * quads);
  if (!g) return nullptr;
  RObjectVertex *v = g->m_pVertices;
  const float W = R_TEXT_CHAR_WIDTH, H = R_TEXT_CHAR_HEIGHT;
  const float du = float(2 * R_TEXT_CHAR_WIDTH) / kFontTextureSize, dv = float(kFontCellH) / kFontTextureSize;
  float pen = float(x);
  int line = 0;
  for (const char *c = text; *c; ++c) {
    if (*c == '\n') {
      pen = float(x), ++line;
      continue;
    }
    if (*c != ' ') {
      const unsigned char ch = static_cast<unsigned char>(*c);
      const int cell = (ch >= 32 && ch < 127 ? ch : '?') - 32;
      const float u0 = float(cell % kFontColumns * kFontCellW) / kFontTextureSize, v0 = float(cell / kFontColumns) * dv;
      const float x0 = pen, y0 = float(y) + H * float(line);
      const RObjectVertex a = {x0, y0, 0, 0, 0, 1, u0, v0};
      const RObjectVertex b = {x0 + W, y0, 0, 0, 0, 1, u0 + du, v0};
      const RObjectVertex c2 = {x0 + W, y0 + H, 0, 0, 0, 1, u0 + du, v0 + dv};
      const RObjectVertex d = {x0, y0 + H, 0, 0, 0, 1, u0, v0 + dv};
      *v++ = a, *v++ = b, *v++ = c2, *v++ = a, *v++ = c2, *v++ = d;
    }
    pen += float(FontAdvance(static_cast<unsigned char>(*c)));
  }
  g->m_pObject->m_nTextureID = kFontTextureID;
  return RGraphicFinishPrimitive(rc, g, color, nullptr, 1);
}
