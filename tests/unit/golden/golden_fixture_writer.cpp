/* golden_fixture_writer DIR: writes DIR/base.txt, DIR/same.txt (identical) and
 * DIR/perturbed.txt (body 1 position y at the fourth sampled frame +0.01) for
 * the karma-golden CLI exit-code tests. */
#include "GoldenTestSupport.h"

#include <karma/golden/Error.h>
#include <karma/golden/TrajectoryWriter.h>

#include <cstdio>
#include <filesystem>

int main(int argc, char **argv) {
  namespace kg = karma::golden;
  namespace ts = karma::golden::test_support;
  if (argc != 2) {
    std::fprintf(stderr, "usage: golden_fixture_writer DIR\n");
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    kg::Trajectory t = ts::SyntheticTrajectory();
    kg::WriteTrajectoryFile(dir / "base.txt", t);
    kg::WriteTrajectoryFile(dir / "same.txt", t);
    t.frames[3].bodies[1].position[1] = ts::Real(t.frames[3].bodies[1].position[1] + 0.01);
    kg::WriteTrajectoryFile(dir / "perturbed.txt", t);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "golden_fixture_writer: %s\n", e.what());
    return 2;
  }
  return 0;
}
