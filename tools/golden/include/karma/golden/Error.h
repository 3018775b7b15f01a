/* Error.h: the one exception type the golden toolkit throws.
 *
 * Every failure that is not a comparison result (a file that cannot be opened,
 * parsed or written, a writer used out of order, an invalid golden key) is
 * reported as a GoldenError whose what() is a complete sentence naming the file
 * and, for parse errors, the line. The C API and the CLI turn it into an error
 * code; nothing in the toolkit aborts. */
#ifndef KARMA_GOLDEN_ERROR_H
#define KARMA_GOLDEN_ERROR_H

#include <karma/MeCall.h>

#include <stdexcept>
#include <string>

namespace karma::golden {

class MEPUBLIC GoldenError : public std::runtime_error {
 public:
  explicit GoldenError(const std::string &message) : std::runtime_error(message) {}
};

/* A malformed trajectory file. what() reads "<source>:<line>: <problem>" like a
 * compiler diagnostic; line() is 1-based (0 when the problem is the whole file,
 * e.g. it cannot be opened). */
class MEPUBLIC TrajectoryFormatError : public GoldenError {
 public:
  TrajectoryFormatError(const std::string &source, int line, const std::string &problem);
  int line() const noexcept { return line_; }

 private:
  int line_;
};

}  // namespace karma::golden

#endif
