/* golden_backend_program: a stand-in for a program under a golden test, for
 * the tests of the golden driver's backends (run_golden_backends.cmake).
 *
 *   golden_backend_program [-differ-on BACKEND] -platform NAME
 *                          -trajectory FILE -out DIR
 *
 * Writes the synthetic trajectory (GoldenTestSupport.h) with `backend NAME`
 * in its header, and one frame DIR/frame_00000.png. With -differ-on NAME
 * equal to -platform, body 1 sits 1 mm higher at every frame: the backend's
 * outputs then differ from the others'. */
#include "GoldenTestSupport.h"

#include <karma/golden/GoldenKey.h>
#include <karma/golden/Image.h>
#include <karma/golden/TrajectoryWriter.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

namespace kg = karma::golden;
namespace ts = karma::golden::test_support;

namespace {

std::string Option(int argc, char **argv, const char *name) {
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], name)) return argv[i + 1];
  return "";
}

/* A fixed 32x24 gradient. */
kg::Image Frame() {
  kg::Image img(32, 24);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::uint8_t *p = img.Pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 8);
      p[1] = static_cast<std::uint8_t>(y * 10);
      p[2] = 128;
      p[3] = 255;
    }
  return img;
}

}  // namespace

int main(int argc, char **argv) {
  const std::string backend = Option(argc, argv, "-platform");
  const std::string path = Option(argc, argv, "-trajectory");
  const std::string out = Option(argc, argv, "-out");
  if (backend.empty() || path.empty() || out.empty()) {
    std::fprintf(stderr, "usage: golden_backend_program [-differ-on B] -platform B -trajectory FILE -out DIR\n");
    return 2;
  }
  try {
    kg::Trajectory t = ts::SyntheticTrajectory();
    t.header.backend = backend;
    if (Option(argc, argv, "-differ-on") == backend)
      for (kg::TrajectoryFrame &f : t.frames) f.bodies[1].position[1] = ts::Real(f.bodies[1].position[1] + 1e-3);
    kg::WriteTrajectoryFile(path, t);
    kg::WritePng(std::filesystem::path(out) / kg::FrameFileName(0), Frame());
  } catch (const std::exception &e) {
    std::fprintf(stderr, "golden_backend_program: %s\n", e.what());
    return 1;
  }
  return 0;
}
