// MeMemoryAPI: the defaults, aligned blocks, redirection, failure handling.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "MeChunk.h"
#include "MeCommandLineOptions.h"
#include "MeMemory.h"
#include "MePool.h"
#include "runtime_test_support.h"

using karma_test::CountingAllocator;
using karma_test::MessageCapture;

namespace {

bool isAligned(const void *p, std::size_t alignment) { return reinterpret_cast<std::uintptr_t>(p) % alignment == 0; }

TEST(MemoryTest, DefaultCreateGivesWritableBlock) {
  auto *block = static_cast<unsigned char *>(MeMemoryAPI.create(256));
  ASSERT_NE(block, nullptr);
  std::memset(block, 0xAB, 256);
  EXPECT_EQ(block[255], 0xAB);
  MeMemoryAPI.destroy(block);
  MeMemoryAPI.destroy(nullptr);  // accepted
}

TEST(MemoryTest, ZeroByteCreateGivesDistinctBlocks) {
  void *a = MeMemoryAPI.create(0);
  void *b = MeMemoryAPI.create(0);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_NE(a, b);
  MeMemoryAPI.destroy(a);
  MeMemoryAPI.destroy(b);
}

TEST(MemoryTest, CreateZeroedIsZero) {
  // Dirty some heap first so a zero result is not luck.
  void *dirty = MeMemoryAPI.create(4096);
  std::memset(dirty, 0xFF, 4096);
  MeMemoryAPI.destroy(dirty);
  auto *block = static_cast<unsigned char *>(MeMemoryAPI.createZeroed(4096));
  ASSERT_NE(block, nullptr);
  for (int i = 0; i < 4096; ++i) ASSERT_EQ(block[i], 0) << "byte " << i;
  MeMemoryAPI.destroy(block);
}

TEST(MemoryTest, ResizeKeepsContents) {
  auto *block = static_cast<char *>(MeMemoryAPI.create(16));
  ASSERT_NE(block, nullptr);
  std::memcpy(block, "0123456789abcde", 16);
  block = static_cast<char *>(MeMemoryAPI.resize(block, 100000));
  ASSERT_NE(block, nullptr);
  EXPECT_STREQ(block, "0123456789abcde");
  block = static_cast<char *>(MeMemoryAPI.resize(block, 0));  // keeps a live block
  ASSERT_NE(block, nullptr);
  MeMemoryAPI.destroy(block);
  void *fresh = MeMemoryAPI.resize(nullptr, 32);  // acts as create
  ASSERT_NE(fresh, nullptr);
  MeMemoryAPI.destroy(fresh);
}

TEST(MemoryTest, AlignedBlocksHonourEveryPowerOfTwo) {
  for (unsigned alignment = 1; alignment <= 8192; alignment *= 2) {
    for (std::size_t bytes : {std::size_t(0), std::size_t(1), std::size_t(100), std::size_t(4097)}) {
      auto *block = static_cast<unsigned char *>(MeMemoryAPI.createAligned(bytes, alignment));
      ASSERT_NE(block, nullptr) << alignment << " " << bytes;
      EXPECT_TRUE(isAligned(block, alignment)) << alignment;
      if (bytes > 0) std::memset(block, 0x5A, bytes);  // the sanitizer build checks the bounds
      MeMemoryAPI.destroyAligned(block);
    }
  }
  MeMemoryAPI.destroyAligned(nullptr);  // accepted
}

TEST(MemoryTest, BadAlignmentWarnsAndReturnsNull) {
  MessageCapture capture;
  for (unsigned alignment : {0u, 3u, 24u, 100u}) {
    EXPECT_EQ(MeMemoryAPI.createAligned(64, alignment), nullptr) << alignment;
  }
  ASSERT_EQ(capture.warnings().size(), 4u);
  EXPECT_NE(capture.warnings()[1].text.find("alignment 3 is not a power of two"), std::string::npos)
      << capture.warnings()[1].text;
}

TEST(MemoryTest, ImpossibleAlignedSizeWarnsAndReturnsNull) {
  MessageCapture capture;
  EXPECT_EQ(MeMemoryAPI.createAligned(SIZE_MAX - 4, 64), nullptr);
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("too large"), std::string::npos);
}

#if !defined(__SANITIZE_ADDRESS__)
// (AddressSanitizer treats a huge malloc as an error, so only plain builds
// exercise the real out-of-memory path.)
TEST(MemoryTest, DefaultCreateFailureWarnsAndReturnsNull) {
  MessageCapture capture;
  EXPECT_EQ(MeMemoryAPI.create(SIZE_MAX / 2), nullptr);
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("out of memory"), std::string::npos);
}
#endif

TEST(MemoryTest, AlignedAndZeroedGoThroughCreate) {
  CountingAllocator counter;
  void *aligned = MeMemoryAPI.createAligned(1000, 64);
  ASSERT_NE(aligned, nullptr);
  EXPECT_TRUE(isAligned(aligned, 64));
  EXPECT_EQ(counter.creates(), 1);
  EXPECT_GE(counter.lastCreateBytes(), 1000u);
  void *zeroed = MeMemoryAPI.createZeroed(10);
  EXPECT_EQ(counter.creates(), 2);
  MeMemoryAPI.destroyAligned(aligned);
  MeMemoryAPI.destroy(zeroed);
  EXPECT_EQ(counter.destroys(), 2);
  EXPECT_EQ(counter.liveBlocks(), 0u);
}

TEST(MemoryTest, FailingCreateMakesAlignedReturnNull) {
  CountingAllocator counter;
  counter.setFailing(true);
  EXPECT_EQ(MeMemoryAPI.createAligned(64, 16), nullptr);
  EXPECT_EQ(MeMemoryAPI.createZeroed(64), nullptr);
  EXPECT_EQ(counter.creates(), 2);
}

void *MEAPI replacementCreate(std::size_t) { return nullptr; }

TEST(MemoryTest, ResetRestoresTheDefaults) {
  const MeMemoryAPIStruct before = MeMemoryAPI;
  MeMemoryAPI.create = &replacementCreate;
  MeMemoryAPI.destroyAligned = nullptr;
  MeMemoryAPIReset();
  EXPECT_EQ(MeMemoryAPI.create, before.create);
  EXPECT_EQ(MeMemoryAPI.destroy, before.destroy);
  EXPECT_EQ(MeMemoryAPI.resize, before.resize);
  EXPECT_EQ(MeMemoryAPI.createZeroed, before.createZeroed);
  EXPECT_EQ(MeMemoryAPI.createAligned, before.createAligned);
  EXPECT_EQ(MeMemoryAPI.destroyAligned, before.destroyAligned);
}

// The guide's promise: redirect create/destroy, and everything Karma
// allocates comes through them and is given back.
TEST(MemoryTest, PoolChunkAndOptionsAllocateOnlyThroughTheAPI) {
  CountingAllocator counter;
  {
    MePool pool;
    ASSERT_TRUE(MePoolInit(&pool, 10, 48, 16));
    MeChunk chunk;
    MeChunkInit(&chunk, 16);
    ASSERT_NE(MeChunkGetMem(&chunk, 3000), nullptr);
    const char *argv[] = {"prog", "-x", "1"};
    MeCommandLineOptions *options = MeCommandLineOptionsCreate(3, argv);
    ASSERT_NE(options, nullptr);
    MeCommandLineOptions *parsed = MeCommandLineOptionsCreateFromString("prog -y 2");
    ASSERT_NE(parsed, nullptr);

    EXPECT_EQ(counter.creates(), 4);  // one block each
    EXPECT_EQ(counter.liveBlocks(), 4u);

    MeChunkPutMem(&chunk, chunk.buffer);
    MeChunkTerm(&chunk);
    MePoolDestroy(&pool);
    MeCommandLineOptionsDestroy(options);
    MeCommandLineOptionsDestroy(parsed);
  }
  EXPECT_EQ(counter.destroys(), counter.creates());
  EXPECT_EQ(counter.liveBlocks(), 0u);
}

}  // namespace
