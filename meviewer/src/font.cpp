/* font.cpp: the "font" texture, drawn by the project at start-up from the
 * stroke font of stb_easy_font (Debian's libstb-dev).
 *
 * stb_easy_font describes each glyph as axis-aligned rectangles on a grid
 * of 1-unit "pixels", about 5 wide and up to 10 high including descenders.
 * Each printable ASCII character c (32..126) is filled at 2 texels per unit
 * into cell (c - 32) of a 256x256 RGBA texture: kFontColumns cells of
 * kFontCellW x kFontCellH texels per row, the glyph offset by (2, 2). The
 * texture is white with the glyph's coverage in alpha, so text takes the
 * colour of its graphic and blends over the scene. FontAdvance gives each
 * character's width in font units (proportional spacing, as stb_easy_font
 * prints). */
#include "viewer_internal.h"

#include <cstring>

#if defined(__GNUC__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wunused-function"
#  pragma GCC diagnostic ignored "-Wsign-compare"
#  pragma GCC diagnostic ignored "-Wconversion"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#  pragma GCC diagnostic pop
#endif

namespace karma::viewer {

Image MakeFontImage() {
  constexpr int kScale = 2, kOffset = 2; /* even: strokes land on whole pixels */
  Image img;
  img.width = img.height = kFontTextureSize;
  img.channels = 4;
  img.pixels.assign(std::size_t(kFontTextureSize) * kFontTextureSize * 4, 0);
  for (std::size_t i = 0; i < img.pixels.size(); i += 4) img.pixels[i] = img.pixels[i + 1] = img.pixels[i + 2] = 255;
  struct QuadVertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  static_assert(sizeof(QuadVertex) == 16, "stb_easy_font writes 16-byte vertices");
  QuadVertex buffer[4 * 256];
  for (int c = 32; c < 127; ++c) { /* entry 95 (127) is the table's end marker */
    char text[2] = {char(c), 0};
    const int quads = stb_easy_font_print(0, 0, text, nullptr, buffer, int(sizeof buffer));
    const int cell = c - 32, cx = (cell % kFontColumns) * kFontCellW, cy = (cell / kFontColumns) * kFontCellH;
    for (int q = 0; q < quads; ++q) {
      const QuadVertex *v = buffer + 4 * q;
      float x0 = v[0].x, x1 = v[0].x, y0 = v[0].y, y1 = v[0].y;
      for (int k = 1; k < 4; ++k) {
        x0 = v[k].x < x0 ? v[k].x : x0, x1 = v[k].x > x1 ? v[k].x : x1;
        y0 = v[k].y < y0 ? v[k].y : y0, y1 = v[k].y > y1 ? v[k].y : y1;
      }
      /* Fill the texels whose centres lie inside the scaled rectangle,
       * clipped to the cell. */
      for (int ty = 0; ty < kFontCellH; ++ty)
        for (int tx = 0; tx < kFontCellW; ++tx) {
          const float ux = (float(tx - kOffset) + 0.5f) / kScale, uy = (float(ty - kOffset) + 0.5f) / kScale;
          if (ux < x0 || ux >= x1 || uy < y0 || uy >= y1) continue;
          img.pixels[(std::size_t(cy + ty) * kFontTextureSize + std::size_t(cx + tx)) * 4 + 3] = 255;
        }
    }
  }
  return img;
}

int FontAdvance(unsigned char c) {
  if (c < 32 || c >= 127) c = '?';
  return stb_easy_font_charinfo[c - 32].advance & 15;
}

}  // namespace karma::viewer
