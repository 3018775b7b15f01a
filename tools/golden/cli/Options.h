/* Options.h (karma-golden): command-line options shared by the subcommands.
 *
 * Arguments are split into positional ones and options; an option takes its
 * value as the next argument or after '=' (--abs-pos 1e-3, --abs-pos=1e-3).
 * Parsing errors throw UsageError (exit code 2). */
#ifndef KARMA_GOLDEN_CLI_OPTIONS_H
#define KARMA_GOLDEN_CLI_OPTIONS_H

#include <karma/golden/Tolerances.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace karma::golden::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::vector<std::string> positional;
  TrajectoryToleranceOverrides trajectory;
  ImageTolerances image = kDefaultImageTolerances;
  std::string diffPath;  /* --diff */
  std::string goldenDir; /* --golden-dir */
  std::string actualDir; /* --actual-dir */
};

/* Which option groups a subcommand accepts. */
enum OptionGroup : unsigned { kTrajectoryOptions = 1u, kImageOptions = 2u, kDiffOption = 4u, kCheckDirs = 8u };

/* args excludes the program and subcommand names. */
Options ParseOptions(const std::vector<std::string> &args, unsigned groups);

/* Option help text for the usage message. */
std::string OptionHelp();

}  // namespace karma::golden::cli

#endif
