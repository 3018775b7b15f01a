// libFuzzer target: the BMP texture decoder on arbitrary bytes. Built only
// with Clang and KARMA_BUILD_FUZZERS=ON (the `fuzz` preset).
#include "viewer_internal.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  karma::viewer::Image image;
  std::string error;
  if (karma::viewer::DecodeTextureBmp(data, size, image, error)) {
    // A decoded texture is always complete.
    if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * 3) __builtin_trap();
  }
  return 0;
}
