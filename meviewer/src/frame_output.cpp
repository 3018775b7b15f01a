/* frame_output.cpp: writing frames as PNG (or 24-bit BMP) through
 * stb_image_write. The implementation is compiled here with static linkage
 * so it cannot clash with another copy in the program. */
#include "viewer_internal.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#if defined(__GNUC__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#  pragma GCC diagnostic ignored "-Wsign-compare"
#  pragma GCC diagnostic ignored "-Wunused-parameter"
#  pragma GCC diagnostic ignored "-Wunused-function"
#endif
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#if defined(__GNUC__)
#  pragma GCC diagnostic pop
#endif

namespace karma::viewer {

std::string FrameFileName(long frame, bool bmp) {
  char name[64];
  std::snprintf(name, sizeof name, "frame_%05ld.%s", frame, bmp ? "bmp" : "png");
  return name;
}

bool WritePng(const std::string &path, const Image &image, std::string &error) {
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_png(path.c_str(), image.width, image.height, image.channels, image.pixels.data(),
                      image.width * image.channels)) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

bool WriteFrameImage(const std::string &dir, long frame, bool bmp, const Image &image, std::string &error) {
  const std::string path = dir + "/" + FrameFileName(frame, bmp);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels)) {
    error = "no image to write to " + path;
    return false;
  }
  errno = 0;
  const int ok = bmp ? stbi_write_bmp(path.c_str(), image.width, image.height, image.channels, image.pixels.data())
                     : stbi_write_png(path.c_str(), image.width, image.height, image.channels, image.pixels.data(),
                                      image.width * image.channels);
  if (!ok) {
    error = "cannot write " + path + (errno ? std::string(": ") + std::strerror(errno) : std::string());
    return false;
  }
  return true;
}

}  // namespace karma::viewer
