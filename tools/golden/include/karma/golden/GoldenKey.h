/* GoldenKey.h: where a golden lives.
 *
 * Goldens are keyed by program, step, platform backend and precision:
 *   <golden root>/<program>/<step>/<backend>-<precision>/
 * holding kTrajectoryFileName and the frames as FrameFileName(frame), e.g.
 *   golden/demo/main/reference-single/frame_00120.png
 * Programs without steps use step "main". Key parts must be non-empty and made
 * of letters, digits, '_', '-' and '.', and may not be "." or "..", so a key
 * always names a directory inside the golden root. */
#ifndef KARMA_GOLDEN_GOLDENKEY_H
#define KARMA_GOLDEN_GOLDENKEY_H

#include <karma/golden/Precision.h>

#include <filesystem>
#include <string>

namespace karma::golden {

inline constexpr const char *kTrajectoryFileName = "trajectory.txt";

/* "frame_00042.png": five digits, more when the frame needs them. */
MEPUBLIC std::string FrameFileName(long frame);

struct MEPUBLIC GoldenKey {
  std::string program;
  std::string step = "main";
  std::string backend = "reference";
  Precision precision = kBuildPrecision;

  /* Throws GoldenError when a part is not a valid directory name (see above). */
  void Validate() const;
  /* <program>/<step>/<backend>-<precision>; validates first. */
  std::filesystem::path RelativeDirectory() const;
  std::filesystem::path Directory(const std::filesystem::path &goldenRoot) const {
    return goldenRoot / RelativeDirectory();
  }
};

}  // namespace karma::golden

#endif
