// texture_test.cpp: the BMP loader on good and bad files (including every
// truncation of a good one and random byte damage), texture IDs and their
// limit, and finding texture files through the search path.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cstdlib>
#include <fstream>
#include <random>

using karma::viewer::DecodeTextureBmp;
using karma::viewer::Image;
using karma::viewer::TextureState;
using viewer_test::MakeContext;
using viewer_test::Messages;
using viewer_test::TempDir;

namespace {

void Put(std::vector<std::uint8_t> &b, std::size_t at, std::uint32_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}

// A BMP whose pixel (x, y) (y = 0 the top row) is (x, y, 7); `height`
// negative stores rows top-down.
std::vector<std::uint8_t> MakeBmp(int width, int height, int bpp = 24, std::uint32_t compression = 0) {
  const int h = height < 0 ? -height : height;
  const std::size_t stride = (std::size_t(width) * std::size_t(bpp / 8) + 3) / 4 * 4;
  std::vector<std::uint8_t> b(54 + stride * std::size_t(h), 0);
  b[0] = 'B', b[1] = 'M';
  Put(b, 2, std::uint32_t(b.size()), 4);
  Put(b, 10, 54, 4);
  Put(b, 14, 40, 4);
  Put(b, 18, std::uint32_t(width), 4);
  Put(b, 22, std::uint32_t(height), 4);
  Put(b, 26, 1, 2);
  Put(b, 28, std::uint32_t(bpp), 2);
  Put(b, 30, compression, 4);
  for (int y = 0; y < h; ++y) {
    const int fileRow = height < 0 ? y : h - 1 - y;
    for (int x = 0; x < width && bpp == 24; ++x) {
      std::uint8_t *p = b.data() + 54 + stride * std::size_t(fileRow) + 3 * std::size_t(x);
      p[0] = 7, p[1] = std::uint8_t(y), p[2] = std::uint8_t(x);  // B, G, R
    }
  }
  return b;
}

bool Decode(const std::vector<std::uint8_t> &b, Image &img, std::string &error) {
  return DecodeTextureBmp(b.data(), b.size(), img, error);
}

TEST(Bmp, Reads24Bit128And256BottomUpAndTopDown) {
  for (int size : {128, 256})
    for (int sign : {1, -1}) {
      Image img;
      std::string error;
      ASSERT_TRUE(Decode(MakeBmp(size, sign * size), img, error)) << error;
      EXPECT_EQ(img.width, size);
      EXPECT_EQ(img.height, size);
      EXPECT_EQ(img.channels, 3);
      const std::uint8_t *p = img.pixels.data() + (std::size_t(5) * std::size_t(size) + 9) * 3;  // (9, 5)
      EXPECT_EQ(p[0], 9);
      EXPECT_EQ(p[1], 5);
      EXPECT_EQ(p[2], 7);
    }
}

TEST(Bmp, RefusesWrongSizesDepthsCompressionAndNonBmp) {
  struct Case {
    std::vector<std::uint8_t> bytes;
    const char *reason;
  } cases[] = {
      {MakeBmp(64, 64), "must be 128x128 or 256x256"}, {MakeBmp(128, 256), "must be 128x128 or 256x256"},
      {MakeBmp(128, 128, 32), "must be 24-bit"},       {MakeBmp(128, 128, 8), "must be 24-bit"},
      {MakeBmp(128, 128, 24, 1), "uncompressed"},      {std::vector<std::uint8_t>{'P', 'N', 'G', 0}, "not a BMP"},
      {std::vector<std::uint8_t>{}, "not a BMP"}};
  for (const Case &c : cases) {
    Image img;
    std::string error;
    EXPECT_FALSE(Decode(c.bytes, img, error));
    EXPECT_NE(error.find(c.reason), std::string::npos) << error;
  }
}

TEST(Bmp, EveryTruncationIsRefused) {
  const std::vector<std::uint8_t> good = MakeBmp(128, 128);
  for (std::size_t n = 0; n < good.size(); n += (n < 100 ? 1 : 97)) {
    Image img;
    std::string error;
    EXPECT_FALSE(DecodeTextureBmp(good.data(), n, img, error)) << n;
    EXPECT_FALSE(error.empty());
  }
}

TEST(Bmp, RandomDamageNeverReadsOutOfBounds) {
  // Under AddressSanitizer this is the loader's fuzz test: damaged headers
  // and sizes must be refused or read within the buffer.
  const std::vector<std::uint8_t> good = MakeBmp(128, 128);
  std::mt19937 rng(12345);
  for (int round = 0; round < 2000; ++round) {
    std::vector<std::uint8_t> b(good.begin(), good.begin() + std::ptrdiff_t(rng() % good.size()));
    const int flips = 1 + int(rng() % 4);
    for (int f = 0; f < flips && !b.empty(); ++f) b[rng() % std::min<std::size_t>(b.size(), 64)] = std::uint8_t(rng());
    Image img;
    std::string error;
    if (Decode(b, img, error)) {
      EXPECT_EQ(img.pixels.size(), std::size_t(img.width) * std::size_t(img.height) * 3);
    }
  }
}

TEST(Bmp, MissingFileIsReported) {
  Image img;
  std::string error;
  EXPECT_FALSE(karma::viewer::LoadTextureBmp("/nonexistent/dir/x.bmp", img, error));
  EXPECT_NE(error.find("cannot open"), std::string::npos);
}

TEST(Textures, IdsAreSharedByNameAndLimitedTo25) {
  RRender *rc = MakeContext("prog -null");
  ASSERT_NE(rc, nullptr);
  char name[32];
  for (int i = 0; i < R_MAX_TEXTURES; ++i) {
    std::snprintf(name, sizeof name, "tex%d", i);
    EXPECT_EQ(RRenderTextureCreate(rc, name), i);
  }
  char again[] = "tex3";
  EXPECT_EQ(RRenderTextureCreate(rc, again), 3);
  Messages m;
  char extra[] = "one-too-many";
  EXPECT_EQ(RRenderTextureCreate(rc, extra), -1);
  EXPECT_TRUE(Messages::Warned("all 25 texture IDs are taken")) << Messages::All();
  RGraphic *g = RGraphicCreateEmpty(3);
  g->m_pObject->m_nTextureID = 2;
  EXPECT_EQ(RGraphicSetTexture(rc, g, extra), -1);
  EXPECT_EQ(g->m_pObject->m_nTextureID, -1);  // untextured fallback
  RGraphicDestroy(g);
  RRenderContextDestroy(rc);
}

TEST(Textures, CheckerboardIsFoundAndBadFilesFallBackToUntextured) {
  TempDir dir("textures");
  {
    std::ofstream f(dir.path() / "tiny.bmp", std::ios::binary);
    const std::vector<std::uint8_t> b = MakeBmp(64, 64);
    f.write(reinterpret_cast<const char *>(b.data()), std::streamsize(b.size()));
  }
  {
    std::ofstream f(dir.path() / "cut.bmp", std::ios::binary);
    const std::vector<std::uint8_t> b = MakeBmp(128, 128);
    f.write(reinterpret_cast<const char *>(b.data()), 1000);
  }
  ::setenv("KARMA_DATA_DIR", dir.str().c_str(), 1);
  RRender *rc = MakeContext("prog -null");
  ASSERT_NE(rc, nullptr);
  char checker[] = "checkerboard", tiny[] = "tiny", cut[] = "cut", missing[] = "no-such-texture";
  RGraphic *g = RGraphicBoxCreate(rc, 1, 1, 1, static_cast<const float *>(nullptr), nullptr);
  EXPECT_EQ(RGraphicSetTexture(rc, g, checker), 0);
  EXPECT_EQ(g->m_pObject->m_nTextureID, 0);
  EXPECT_EQ(RRenderTextureCreate(rc, tiny), 1);
  EXPECT_EQ(RRenderTextureCreate(rc, cut), 2);
  EXPECT_EQ(RRenderTextureCreate(rc, missing), 3);
  Messages m;
  karma::viewer::LoadPendingTextures(rc);
  ::unsetenv("KARMA_DATA_DIR");
  const auto &t = rc->m_pPrivate->textures;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].state, TextureState::Loaded) << Messages::All();
  EXPECT_EQ(t[0].image.width, 128);
  EXPECT_EQ(t[1].state, TextureState::Failed);
  EXPECT_EQ(t[2].state, TextureState::Failed);
  EXPECT_EQ(t[3].state, TextureState::Failed);
  EXPECT_TRUE(Messages::Warned("texture 'tiny'"));
  EXPECT_TRUE(Messages::Warned("128x128 or 256x256"));
  EXPECT_TRUE(Messages::Warned("truncated BMP"));
  EXPECT_TRUE(Messages::Warned("no no-such-texture.bmp in"));
  EXPECT_TRUE(Messages::Warned("drawing untextured"));
  // Checkerboard: 16-pixel squares, light at the top-left.
  const std::uint8_t *p = t[0].image.pixels.data();
  EXPECT_GT(p[0], 200);
  EXPECT_LT(p[16 * 3], 100);
  RRenderContextDestroy(rc);
}

TEST(Textures, SearchPathStartsWithTheWorkingDirectory) {
  const std::vector<std::string> path = karma::viewer::TextureSearchPath();
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path[0], ".");
}

}  // namespace
