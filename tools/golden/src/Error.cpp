#include <karma/golden/Error.h>

namespace karma::golden {

namespace {
std::string Located(const std::string &source, int line, const std::string &problem) {
  if (line > 0) return source + ":" + std::to_string(line) + ": " + problem;
  return source + ": " + problem;
}
}  // namespace

TrajectoryFormatError::TrajectoryFormatError(const std::string &source, int line, const std::string &problem)
    : GoldenError(Located(source, line, problem)), line_(line) {}

}  // namespace karma::golden
