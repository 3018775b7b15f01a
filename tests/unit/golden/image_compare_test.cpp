/* Image comparison: CompareImages metrics and CompareImageFiles' diff image. */
#include "GoldenTestSupport.h"

#include <karma/golden/Error.h>
#include <karma/golden/Image.h>
#include <karma/golden/ImageCompare.h>
#include <karma/golden/Tolerances.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace kg = karma::golden;
namespace ts = karma::golden::test_support;

namespace {

constexpr int kW = 320, kH = 240;

/* A deterministic picture with channel values in 0..149 (room for +100). */
kg::Image Picture(int w = kW, int h = kH) {
  kg::Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t *p = img.Pixel(x, y);
      p[0] = static_cast<std::uint8_t>((7 * x + 3 * y) % 150);
      p[1] = static_cast<std::uint8_t>((x * y) % 150);
      p[2] = static_cast<std::uint8_t>((x + 11 * y) % 150);
      p[3] = 255;
    }
  return img;
}

/* Adds `amount` to the red channel of the block [x0, x0+w) x [y0, y0+h). */
void Bump(kg::Image &img, int x0, int y0, int w, int h, int amount, int channel = 0) {
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x)
      img.Pixel(x, y)[channel] = static_cast<std::uint8_t>(img.Pixel(x, y)[channel] + amount);
}

}  // namespace

TEST(ImageCompare, IdenticalImagesMatch) {
  const kg::ImageComparison c = kg::CompareImages(Picture(), Picture(), kg::kDefaultImageTolerances);
  EXPECT_TRUE(c.passed);
  EXPECT_FALSE(c.sizeMismatch);
  EXPECT_EQ(c.differingPixels, 0u);
  EXPECT_EQ(c.totalPixels, static_cast<std::size_t>(kW * kH));
  EXPECT_EQ(c.maxChannelDifference, 0);
  EXPECT_TRUE(c.differingBox.Empty());
  EXPECT_NE(kg::ReportText(c, "e.png", "a.png").find("verdict: MATCH"), std::string::npos);
}

TEST(ImageCompare, FewDifferingPixelsPass) {
  kg::Image actual = Picture();
  Bump(actual, 10, 20, 1, 1, 100);
  Bump(actual, 200, 100, 1, 1, 100, 1);
  Bump(actual, 319, 239, 1, 1, 100, 2);
  const kg::ImageComparison c = kg::CompareImages(Picture(), actual, kg::kDefaultImageTolerances);
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.differingPixels, 3u);
  EXPECT_DOUBLE_EQ(c.differingFraction, 3.0 / (kW * kH));
  EXPECT_EQ(c.maxChannelDifference, 100);
  EXPECT_EQ(c.differingBox.x0, 10);
  EXPECT_EQ(c.differingBox.y0, 20);
  EXPECT_EQ(c.differingBox.x1, 319);
  EXPECT_EQ(c.differingBox.y1, 239);
  EXPECT_NE(kg::ReportText(c, "e.png", "a.png").find("verdict: PASS"), std::string::npos);
}

TEST(ImageCompare, DifferingBlockFails) {
  kg::Image actual = Picture();
  Bump(actual, 50, 60, 40, 40, 100);
  const kg::ImageComparison c = kg::CompareImages(Picture(), actual, kg::kDefaultImageTolerances);
  EXPECT_FALSE(c.passed);
  EXPECT_FALSE(c.sizeMismatch);
  EXPECT_EQ(c.differingPixels, 1600u);
  EXPECT_EQ(c.maxChannelDifference, 100);
  EXPECT_EQ(c.differingBox.x0, 50);
  EXPECT_EQ(c.differingBox.y0, 60);
  EXPECT_EQ(c.differingBox.x1, 89);
  EXPECT_EQ(c.differingBox.y1, 99);
  const std::string report = kg::ReportText(c, "e.png", "a.png");
  EXPECT_NE(report.find("verdict: FAIL"), std::string::npos) << report;
  EXPECT_NE(report.find("x 50..89, y 60..99"), std::string::npos) << report;
}

TEST(ImageCompare, ChannelToleranceIsInclusive) {
  const int tol = kg::kDefaultImageTolerances.channelTolerance;
  const kg::ImageTolerances strictFraction{tol, 0.0};

  kg::Image atTolerance = Picture();
  Bump(atTolerance, 5, 5, 1, 1, tol);     /* red */
  Bump(atTolerance, 6, 5, 1, 1, -tol, 1); /* green, downward */
  kg::ImageComparison c = kg::CompareImages(Picture(), atTolerance, strictFraction);
  EXPECT_EQ(c.differingPixels, 0u);
  EXPECT_EQ(c.maxChannelDifference, tol);
  EXPECT_TRUE(c.passed);

  kg::Image overTolerance = Picture();
  Bump(overTolerance, 5, 5, 1, 1, tol + 1);
  c = kg::CompareImages(Picture(), overTolerance, strictFraction);
  EXPECT_EQ(c.differingPixels, 1u);
  EXPECT_EQ(c.maxChannelDifference, tol + 1);
  EXPECT_FALSE(c.passed);

  /* The alpha channel counts too. */
  kg::Image alpha = Picture();
  alpha.Pixel(1, 1)[3] = static_cast<std::uint8_t>(255 - (tol + 1));
  c = kg::CompareImages(Picture(), alpha, strictFraction);
  EXPECT_EQ(c.differingPixels, 1u);
}

TEST(ImageCompare, DifferingFractionLimitIsInclusive) {
  /* 10x10 image: 1 differing pixel = 0.01 of the pixels. */
  kg::Image actual = Picture(10, 10);
  Bump(actual, 3, 4, 1, 1, 50);
  EXPECT_TRUE(kg::CompareImages(Picture(10, 10), actual, {8, 0.01}).passed);
  EXPECT_FALSE(kg::CompareImages(Picture(10, 10), actual, {8, 0.009}).passed);
}

TEST(ImageCompare, SizeMismatchFails) {
  const kg::ImageComparison c = kg::CompareImages(Picture(), Picture(kW, kH - 1), kg::kDefaultImageTolerances);
  EXPECT_FALSE(c.passed);
  EXPECT_TRUE(c.sizeMismatch);
  EXPECT_EQ(c.expectedHeight, kH);
  EXPECT_EQ(c.actualHeight, kH - 1);
  EXPECT_NE(kg::ReportText(c, "e.png", "a.png").find("sizes differ"), std::string::npos);
  EXPECT_THROW(kg::MakeDiffImage(Picture(), Picture(kW - 1, kH), 8), kg::GoldenError);
}

TEST(ImageCompare, PngRoundTripIsExact) {
  ts::TempDir dir("img_png");
  const kg::Image img = Picture(37, 23);
  kg::WritePng(dir.path() / "p.png", img);
  const kg::Image back = kg::LoadPng(dir.path() / "p.png");
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgba, img.rgba);
  EXPECT_THROW(kg::LoadPng(dir.path() / "missing.png"), kg::GoldenError);
}

TEST(ImageCompare, CompareImageFilesWritesRedDiffImage) {
  ts::TempDir dir("img_diff");
  const kg::Image expected = Picture();
  kg::Image actual = Picture();
  Bump(actual, 100, 30, 40, 40, 100);
  Bump(actual, 5, 200, 2, 3, 9, 2);  /* just over the tolerance */
  Bump(actual, 300, 10, 2, 2, 8, 1); /* at the tolerance: not differing */
  const auto expectedPath = dir.path() / "frame_00010.golden.png";
  const auto actualPath = dir.path() / "frame_00010.png";
  kg::WritePng(expectedPath, expected);
  kg::WritePng(actualPath, actual);

  const kg::ImageComparison c = kg::CompareImageFiles(expectedPath, actualPath, kg::kDefaultImageTolerances);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.differingPixels, 1600u + 6u);
  const auto defaultDiff = dir.path() / "frame_00010.diff.png";
  EXPECT_EQ(c.diffImage, defaultDiff);
  EXPECT_EQ(kg::DefaultDiffPath(actualPath), defaultDiff);
  ASSERT_TRUE(std::filesystem::exists(defaultDiff));
  EXPECT_NE(kg::ReportText(c, "e", "a").find(defaultDiff.string()), std::string::npos);

  const kg::Image diff = kg::LoadPng(defaultDiff);
  ASSERT_EQ(diff.width, kW);
  ASSERT_EQ(diff.height, kH);
  int red = 0, wrong = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool differs = (x >= 100 && x < 140 && y >= 30 && y < 70) || (x >= 5 && x < 7 && y >= 200 && y < 203);
      const std::uint8_t *p = diff.Pixel(x, y);
      const bool isRed = p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255;
      red += isRed;
      if (isRed != differs) ++wrong;
    }
  EXPECT_EQ(red, 1606);
  EXPECT_EQ(wrong, 0);

  /* An explicit diff path is honoured; a passing pair writes no diff image. */
  const auto explicitDiff = dir.path() / "explicit.png";
  EXPECT_EQ(kg::CompareImageFiles(expectedPath, actualPath, kg::kDefaultImageTolerances, explicitDiff).diffImage,
            explicitDiff);
  EXPECT_TRUE(std::filesystem::exists(explicitDiff));
  const auto passDiff = dir.path() / "pass.diff.png";
  const kg::ImageComparison same =
      kg::CompareImageFiles(expectedPath, expectedPath, kg::kDefaultImageTolerances, passDiff);
  EXPECT_TRUE(same.passed);
  EXPECT_TRUE(same.diffImage.empty());
  EXPECT_FALSE(std::filesystem::exists(passDiff));
}
