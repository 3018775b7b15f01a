// libFuzzer target: the ASE mesh reader on arbitrary text. Built only with
// Clang and KARMA_BUILD_FUZZERS=ON (the `fuzz` preset).
#include "viewer_internal.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  std::vector<RObjectVertex> vertices;
  std::string error;
  const std::string text(reinterpret_cast<const char *>(data), size);
  if (karma::viewer::ParseAse(text, vertices, error)) {
    if (vertices.empty() || vertices.size() % 3 != 0) __builtin_trap();  // whole triangles only
  }
  return 0;
}
