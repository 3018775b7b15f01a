// options.h: karma-tradeoff's command line.
#pragma once

#include <string>
#include <vector>

namespace karma::tradeoff {

struct Options {
  std::vector<std::string> scenes;  // names or library paths
  std::string sweep = "solver=exact";
  std::vector<std::string> precisions;  // empty: this build's only
  int repeat = 3;
  std::string out = "tradeoff-out";
  double seconds = 0;        // 0: each scene's own run length
  double referenceStep = 0;  // 0: min(1/60, smallest h) / 8
  std::string peers;         // peer_bench's table, or ""
  int width = 800, height = 600;
  bool plots = true;
  bool list = false;
  bool help = false;
  std::string otherBinary;  // karma-tradeoff of the other precision
};

// False with a message on a bad command line.
bool ParseOptions(int argc, char **argv, Options &o, std::string &error);
std::string Usage();
// "single" or "double": this build's MeReal.
const char *BuildPrecision();

}  // namespace karma::tradeoff
