/* GoldenCheck.h: comparing a run's output directory with a golden directory.
 *
 * The golden directory decides what is checked:
 *   - if it holds trajectory.txt, the actual directory must hold one that
 *     compares within tolerance (defaults by the golden's precision, then the
 *     overrides);
 *   - every *.png in it (not *.diff.png) must exist in the actual directory
 *     under the same name and compare within the image tolerances; diff images
 *     of failing frames are written next to the actual frames;
 *   - files only in the actual directory (extra frames) are ignored;
 *   - a golden directory with nothing to check is an error.
 * Everything that can be checked is checked, so one run reports every problem. */
#ifndef KARMA_GOLDEN_GOLDENCHECK_H
#define KARMA_GOLDEN_GOLDENCHECK_H

#include <karma/golden/Tolerances.h>

#include <filesystem>
#include <string>

namespace karma::golden {

struct CheckOptions {
  TrajectoryToleranceOverrides trajectory;
  ImageTolerances image = kDefaultImageTolerances;
};

enum class CheckStatus { Match = 0, Mismatch = 1, Error = 2 }; /* = the CLI's exit codes */

struct CheckResult {
  CheckStatus status = CheckStatus::Error;
  int itemsChecked = 0;
  int itemsFailed = 0;
  std::string report; /* every item's report, then a summary line */
};

MEPUBLIC CheckResult CheckAgainstGolden(const std::filesystem::path &goldenDir, const std::filesystem::path &actualDir,
                                        const CheckOptions &options);

}  // namespace karma::golden

#endif
