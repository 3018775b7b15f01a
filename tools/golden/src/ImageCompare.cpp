#include <karma/golden/ImageCompare.h>

#include <karma/golden/Error.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace karma::golden {

namespace {

/* Largest per-channel difference of two RGBA pixels. */
int ChannelDifference(const std::uint8_t *e, const std::uint8_t *a) {
  int d = 0;
  for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(e[c]) - int(a[c])));
  return d;
}

}  // namespace

ImageComparison CompareImages(const Image &expected, const Image &actual, const ImageTolerances &tolerances) {
  ImageComparison c;
  c.tolerances = tolerances;
  c.expectedWidth = expected.width;
  c.expectedHeight = expected.height;
  c.actualWidth = actual.width;
  c.actualHeight = actual.height;
  if (expected.width != actual.width || expected.height != actual.height) {
    c.sizeMismatch = true;
    return c;
  }
  c.totalPixels = static_cast<std::size_t>(expected.width) * static_cast<std::size_t>(expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int d = ChannelDifference(expected.Pixel(x, y), actual.Pixel(x, y));
      c.maxChannelDifference = std::max(c.maxChannelDifference, d);
      if (d <= tolerances.channelTolerance) continue;
      if (c.differingPixels++ == 0) c.differingBox = {x, y, x, y};
      c.differingBox.x0 = std::min(c.differingBox.x0, x);
      c.differingBox.y0 = std::min(c.differingBox.y0, y);
      c.differingBox.x1 = std::max(c.differingBox.x1, x);
      c.differingBox.y1 = std::max(c.differingBox.y1, y);
    }
  }
  c.differingFraction = c.totalPixels ? double(c.differingPixels) / double(c.totalPixels) : 0.0;
  c.passed = c.differingFraction <= tolerances.maxDifferingFraction;
  return c;
}

Image MakeDiffImage(const Image &expected, const Image &actual, int channelTolerance) {
  if (expected.width != actual.width || expected.height != actual.height)
    throw GoldenError("cannot make a diff image of images of different sizes");
  Image diff(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t *e = expected.Pixel(x, y);
      std::uint8_t *out = diff.Pixel(x, y);
      if (ChannelDifference(e, actual.Pixel(x, y)) > channelTolerance) {
        out[0] = 255, out[1] = 0, out[2] = 0;
      } else {
        /* Grey (integer Rec. 601 luma), dimmed to 0..95 so red stands out. */
        const int luma = (299 * e[0] + 587 * e[1] + 114 * e[2]) / 1000;
        const auto grey = static_cast<std::uint8_t>(32 + luma * 64 / 255);
        out[0] = out[1] = out[2] = grey;
      }
      out[3] = 255;
    }
  }
  return diff;
}

std::filesystem::path DefaultDiffPath(const std::filesystem::path &actual) {
  std::filesystem::path p = actual;
  p.replace_filename(actual.stem().string() + ".diff.png");
  return p;
}

ImageComparison CompareImageFiles(const std::filesystem::path &expectedPath, const std::filesystem::path &actualPath,
                                  const ImageTolerances &tolerances, const std::filesystem::path &diffPath) {
  const Image expected = LoadPng(expectedPath);
  const Image actual = LoadPng(actualPath);
  ImageComparison c = CompareImages(expected, actual, tolerances);
  if (!c.passed && !c.sizeMismatch) {
    c.diffImage = diffPath.empty() ? DefaultDiffPath(actualPath) : diffPath;
    WritePng(c.diffImage, MakeDiffImage(expected, actual, tolerances.channelTolerance));
  }
  return c;
}

std::string ReportText(const ImageComparison &c, const std::string &expectedName, const std::string &actualName) {
  std::ostringstream o;
  char buffer[160];
  o << "image comparison\n";
  o << "  expected: " << expectedName << " (" << c.expectedWidth << "x" << c.expectedHeight << ")\n";
  o << "  actual:   " << actualName << " (" << c.actualWidth << "x" << c.actualHeight << ")\n";
  if (c.sizeMismatch) {
    o << "verdict: FAIL: image sizes differ: expected " << c.expectedWidth << "x" << c.expectedHeight << ", actual "
      << c.actualWidth << "x" << c.actualHeight << "\n";
    return o.str();
  }
  std::snprintf(buffer, sizeof buffer,
                "  differing pixels (a channel off by more than %d): %zu of %zu = %.4f%% (allowed %.4f%%)\n",
                c.tolerances.channelTolerance, c.differingPixels, c.totalPixels, 100.0 * c.differingFraction,
                100.0 * c.tolerances.maxDifferingFraction);
  o << buffer;
  o << "  largest channel difference: " << c.maxChannelDifference << "\n";
  if (c.differingPixels)
    o << "  differing pixels lie in x " << c.differingBox.x0 << ".." << c.differingBox.x1 << ", y " << c.differingBox.y0
      << ".." << c.differingBox.y1 << "\n";
  if (!c.diffImage.empty()) o << "  diff image (differing pixels red): " << c.diffImage.string() << "\n";
  if (!c.passed)
    o << "verdict: FAIL: " << c.differingPixels << " differing pixels exceed the allowed fraction\n";
  else if (c.maxChannelDifference == 0)
    o << "verdict: MATCH: identical pixels\n";
  else
    o << "verdict: PASS: within tolerance, but not identical\n";
  return o.str();
}

}  // namespace karma::golden
