/* bmp.cpp: the texture loader. MeViewer textures are Windows BMP files:
 *
 *   offset  size  field (little-endian)
 *   0       2     "BM"
 *   10      4     offset of the pixel rows
 *   14      4     info header size (>= 40: BITMAPINFOHEADER or later)
 *   18      4     width  (128 or 256)
 *   22      4     height (128 or 256; negative = rows stored top-down)
 *   26      2     planes (1)
 *   28      2     bits per pixel (24)
 *   30      4     compression (0 = none)
 *
 * Rows are width * 3 bytes of B, G, R padded to a multiple of 4 bytes,
 * bottom row first unless the height is negative. Anything else is
 * refused with a reason; every read is bounds-checked against the file
 * size, so truncated or hostile files cannot read out of bounds. */
#include "viewer_internal.h"

#include <cstdio>
#include <fstream>
#include <iterator>

namespace karma::viewer {
namespace {

std::uint32_t U32(const std::uint8_t *p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
std::uint16_t U16(const std::uint8_t *p) { return std::uint16_t(p[0] | p[1] << 8); }

}  // namespace

bool DecodeTextureBmp(const std::uint8_t *data, std::size_t size, Image &out, std::string &error) {
  if (size < 54 || data[0] != 'B' || data[1] != 'M') {
    error =
        size < 2 || data[0] != 'B' || data[1] != 'M' ? "not a BMP file (no 'BM' signature)" : "truncated BMP header";
    return false;
  }
  const std::uint32_t offset = U32(data + 10), infoSize = U32(data + 14);
  const std::int32_t width = std::int32_t(U32(data + 18)), rawHeight = std::int32_t(U32(data + 22));
  const unsigned planes = U16(data + 26), bpp = U16(data + 28);
  const std::uint32_t compression = U32(data + 30);
  if (infoSize < 40) {
    error = "unsupported BMP header (OS/2 or older format)";
    return false;
  }
  if (planes != 1 || bpp != 24) {
    error = std::to_string(bpp) + " bits per pixel; MeViewer textures must be 24-bit";
    return false;
  }
  if (compression != 0) {
    error = "compressed BMP; MeViewer textures must be uncompressed";
    return false;
  }
  const bool topDown = rawHeight < 0;
  const std::int64_t height = topDown ? -std::int64_t(rawHeight) : rawHeight;
  if (!((width == 128 && height == 128) || (width == 256 && height == 256))) {
    error = std::to_string(width) + "x" + std::to_string(height) + "; MeViewer textures must be 128x128 or 256x256";
    return false;
  }
  const std::size_t stride = (std::size_t(width) * 3 + 3) / 4 * 4;
  const std::size_t need = std::size_t(offset) + stride * std::size_t(height);
  if (offset < 54 || need > size) {
    error = "truncated BMP: " + std::to_string(size) + " bytes, the pixels need " + std::to_string(need);
    return false;
  }
  out.width = width;
  out.height = int(height);
  out.channels = 3;
  out.pixels.resize(std::size_t(width) * std::size_t(height) * 3);
  for (std::int64_t row = 0; row < height; ++row) {
    const std::int64_t fileRow = topDown ? row : height - 1 - row;
    const std::uint8_t *src = data + offset + stride * std::size_t(fileRow);
    std::uint8_t *dst = out.pixels.data() + std::size_t(row) * std::size_t(width) * 3;
    for (int x = 0; x < width; ++x) {
      dst[3 * x + 0] = src[3 * x + 2];
      dst[3 * x + 1] = src[3 * x + 1];
      dst[3 * x + 2] = src[3 * x + 0];
    }
  }
  return true;
}

bool LoadTextureBmp(const std::string &path, Image &out, std::string &error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    error = "cannot open " + path;
    return false;
  }
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (!DecodeTextureBmp(bytes.data(), bytes.size(), out, error)) {
    error = path + ": " + error;
    return false;
  }
  return true;
}

}  // namespace karma::viewer
