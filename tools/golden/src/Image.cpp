#include <karma/golden/Image.h>

#include <karma/golden/Error.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <memory>

namespace karma::golden {

Image LoadPng(const std::filesystem::path &path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw GoldenError("cannot read image " + path.string() + ": no such file");
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void *)> pixels(stbi_load(path.string().c_str(), &w, &h, &channels, 4),
                                                    stbi_image_free);
  if (!pixels) {
    const char *reason = stbi_failure_reason();
    throw GoldenError("cannot read image " + path.string() + ": " + (reason ? reason : "unknown error"));
  }
  Image image(w, h);
  std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size());
  return image;
}

void WritePng(const std::filesystem::path &path, const Image &image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
    throw GoldenError("cannot write image " + path.string() + ": the image is empty or its size is inconsistent");
  if (!stbi_write_png(path.string().c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw GoldenError("cannot write image " + path.string());
}

}  // namespace karma::golden
