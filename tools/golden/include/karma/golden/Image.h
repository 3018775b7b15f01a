/* Image.h: an 8-bit RGBA image and PNG input/output (stb_image, stb_image_write).
 *
 * Pixels are row-major from the top-left, 4 bytes per pixel (R, G, B, A).
 * Loading converts any PNG (grey, grey+alpha, RGB, 16-bit) to this form;
 * images without alpha get A = 255. */
#ifndef KARMA_GOLDEN_IMAGE_H
#define KARMA_GOLDEN_IMAGE_H

#include <karma/MeCall.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace karma::golden {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba; /* width * height * 4 bytes */

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0) {}
  std::uint8_t *Pixel(int x, int y) noexcept {
    return rgba.data() +
           (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  }
  const std::uint8_t *Pixel(int x, int y) const noexcept { return const_cast<Image *>(this)->Pixel(x, y); }
};

/* Throws GoldenError naming the file and stb's reason. */
MEPUBLIC Image LoadPng(const std::filesystem::path &path);
/* Throws GoldenError if the file cannot be written. */
MEPUBLIC void WritePng(const std::filesystem::path &path, const Image &image);

}  // namespace karma::golden

#endif
