/* ImageCompare.h: comparing a rendered frame with its golden.
 *
 * Metric (Tolerances.h): a pixel differs when any of its four channels differs
 * by more than channelTolerance; the images match when
 *   differingPixels / (width * height) <= maxDifferingFraction.
 * Images of different sizes never match.
 *
 * The diff image has the expected image's size: every pixel is the expected
 * pixel turned grey and dimmed (so the scene stays recognisable), except
 * differing pixels, which are pure red (255, 0, 0, 255). */
#ifndef KARMA_GOLDEN_IMAGECOMPARE_H
#define KARMA_GOLDEN_IMAGECOMPARE_H

#include <karma/golden/Image.h>
#include <karma/golden/Tolerances.h>

#include <cstddef>
#include <filesystem>
#include <string>

namespace karma::golden {

struct PixelBox { /* inclusive bounds */
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool Empty() const noexcept { return x1 < x0 || y1 < y0; }
};

struct ImageComparison {
  bool passed = false;
  bool sizeMismatch = false;
  int expectedWidth = 0, expectedHeight = 0;
  int actualWidth = 0, actualHeight = 0;
  std::size_t differingPixels = 0;
  std::size_t totalPixels = 0;
  double differingFraction = 0.0;
  int maxChannelDifference = 0; /* over all pixels, 0..255 */
  PixelBox differingBox;        /* bounding box of differing pixels */
  ImageTolerances tolerances;
  std::filesystem::path diffImage; /* set when a diff image was written */
};

MEPUBLIC ImageComparison CompareImages(const Image &expected, const Image &actual, const ImageTolerances &tolerances);

/* Diff image as described above; requires equal sizes. */
MEPUBLIC Image MakeDiffImage(const Image &expected, const Image &actual, int channelTolerance);

/* "dir/frame_00010.png" -> "dir/frame_00010.diff.png": next to the actual output. */
MEPUBLIC std::filesystem::path DefaultDiffPath(const std::filesystem::path &actual);

/* Loads both files (GoldenError if either cannot be read) and compares them.
 * When the images have the same size but do not match, writes the diff image to
 * `diffPath`, or to DefaultDiffPath(actual) when diffPath is empty. */
MEPUBLIC ImageComparison CompareImageFiles(const std::filesystem::path &expected, const std::filesystem::path &actual,
                                           const ImageTolerances &tolerances,
                                           const std::filesystem::path &diffPath = {});

/* A few lines: sizes, counts, fraction, max channel difference, bounding box,
 * where the diff image is, and a verdict line starting with MATCH, PASS or FAIL. */
MEPUBLIC std::string ReportText(const ImageComparison &comparison, const std::string &expectedName,
                                const std::string &actualName);

}  // namespace karma::golden

#endif
