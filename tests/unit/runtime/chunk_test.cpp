// MeChunk: default size, growth by doubling, SetAuto, one user at a time,
// alignment, allocation through MeMemoryAPI and failure handling.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "MeChunk.h"
#include "runtime_test_support.h"

using karma_test::CountingAllocator;
using karma_test::MessageCapture;

namespace {

class ChunkTest : public ::testing::Test {
 protected:
  void SetUp() override { MeChunkInit(&chunk, 16); }
  void TearDown() override { MeChunkTerm(&chunk); }

  // One Get/Put cycle; returns the memory handed out.
  void *use(std::size_t bytes) {
    void *mem = MeChunkGetMem(&chunk, bytes);
    if (mem != nullptr) {
      std::memset(mem, 0x3C, bytes);  // the sanitizer build checks the size
      MeChunkPutMem(&chunk, mem);
    }
    return mem;
  }

  MeChunk chunk;
};

TEST_F(ChunkTest, StartsAt1024BytesWithoutAllocating) {
  CountingAllocator counter;
  MeChunk fresh;
  MeChunkInit(&fresh, 0);
  EXPECT_EQ(MeChunkGetSize(&fresh), 1024u);
  EXPECT_EQ(MeChunkGetGrowCount(&fresh), 0);
  EXPECT_EQ(fresh.buffer, nullptr);
  EXPECT_EQ(counter.creates(), 0);
  MeChunkTerm(&fresh);
}

TEST_F(ChunkTest, SmallRequestsUseTheDefaultSize) {
  ASSERT_NE(use(100), nullptr);
  ASSERT_NE(use(1024), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 1024u);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 0);
}

TEST_F(ChunkTest, GrowsByDoublingUntilLargeEnough) {
  CountingAllocator counter;
  ASSERT_NE(use(5000), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 8192u);  // 1024 -> 2048 -> 4096 -> 8192
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 3);
  EXPECT_EQ(counter.creates(), 1) << "one allocation, however many doublings";

  ASSERT_NE(use(8192), nullptr);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 3);
  EXPECT_EQ(counter.creates(), 1);

  ASSERT_NE(use(8193), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 16384u);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 4);
  EXPECT_EQ(counter.creates(), 2);
  EXPECT_EQ(counter.destroys(), 1);  // the old buffer went back

  ASSERT_NE(use(10), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 16384u) << "a chunk never shrinks";
  EXPECT_EQ(MeChunkGetLargestRequest(&chunk), 8193u);
}

TEST_F(ChunkTest, SetAutoRaisesTheSizeAndAllocatesAtOnce) {
  CountingAllocator counter;
  MeChunkSetAuto(&chunk, 100000);
  EXPECT_EQ(MeChunkGetSize(&chunk), 100000u);
  EXPECT_EQ(counter.creates(), 1);
  EXPECT_NE(chunk.buffer, nullptr);

  ASSERT_NE(use(50000), nullptr);
  ASSERT_NE(use(100000), nullptr);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 0);
  EXPECT_EQ(counter.creates(), 1) << "requests within the SetAuto size never allocate";

  ASSERT_NE(use(150000), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 200000u);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 1);

  MeChunkSetAuto(&chunk, 5000);  // never shrinks
  EXPECT_EQ(MeChunkGetSize(&chunk), 200000u);
  EXPECT_EQ(counter.creates(), 2);
}

TEST_F(ChunkTest, SetAutoBelowTheDefaultStillPreallocates) {
  CountingAllocator counter;
  MeChunkSetAuto(&chunk, 10);
  EXPECT_EQ(MeChunkGetSize(&chunk), 1024u);
  EXPECT_EQ(counter.creates(), 1);
  ASSERT_NE(use(1000), nullptr);
  EXPECT_EQ(counter.creates(), 1);
}

TEST_F(ChunkTest, OneUserAtATime) {
  MessageCapture capture;
  void *first = MeChunkGetMem(&chunk, 100);
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(chunk.inUse);
  EXPECT_EQ(MeChunkGetMem(&chunk, 100), nullptr);
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("already in use"), std::string::npos);

  MeChunkSetAuto(&chunk, 1 << 20);  // ignored while in use
  EXPECT_EQ(capture.warnings().size(), 2u);
  EXPECT_EQ(MeChunkGetSize(&chunk), 1024u);

  MeChunkPutMem(&chunk, first);
  EXPECT_FALSE(chunk.inUse);
  EXPECT_EQ(MeChunkGetMem(&chunk, 100), first);
  MeChunkPutMem(&chunk, first);
  EXPECT_EQ(capture.warnings().size(), 2u);
}

TEST_F(ChunkTest, WrongPutsWarnAndAreIgnored) {
  MessageCapture capture;
  MeChunkPutMem(&chunk, nullptr);  // not in use
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.lastWarning().find("not in use"), std::string::npos);

  void *mem = MeChunkGetMem(&chunk, 64);
  int other = 0;
  MeChunkPutMem(&chunk, &other);
  EXPECT_EQ(capture.warnings().size(), 2u);
  EXPECT_TRUE(chunk.inUse);
  MeChunkPutMem(&chunk, mem);
  EXPECT_FALSE(chunk.inUse);
}

TEST_F(ChunkTest, MemoryIsAlignedAsRequested) {
  MeChunk wide;
  MeChunkInit(&wide, 256);
  void *mem = MeChunkGetMem(&wide, 3000);
  ASSERT_NE(mem, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(mem) % 256, 0u);
  MeChunkPutMem(&wide, mem);
  MeChunkTerm(&wide);
}

TEST_F(ChunkTest, BadAlignmentWarnsAndUsesTheDefault) {
  MessageCapture capture;
  MeChunk odd;
  MeChunkInit(&odd, 12);
  EXPECT_EQ(capture.warnings().size(), 1u);
  void *mem = MeChunkGetMem(&odd, 10);
  ASSERT_NE(mem, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(mem) % alignof(std::max_align_t), 0u);
  MeChunkPutMem(&odd, mem);
  MeChunkTerm(&odd);
}

TEST_F(ChunkTest, TermFreesEverythingAndResets) {
  CountingAllocator counter;
  MeChunk local;
  MeChunkInit(&local, 32);
  void *mem = MeChunkGetMem(&local, 3000);
  MeChunkPutMem(&local, mem);
  MeChunkTerm(&local);
  EXPECT_EQ(counter.liveBlocks(), 0u);
  EXPECT_EQ(MeChunkGetSize(&local), 1024u);
  EXPECT_EQ(MeChunkGetGrowCount(&local), 0);
  EXPECT_EQ(local.alignment, 32);
  MeChunkTerm(nullptr);
}

TEST_F(ChunkTest, TermWhileInUseWarnsButFrees) {
  MessageCapture capture;
  CountingAllocator counter;
  MeChunk local;
  MeChunkInit(&local, 0);
  ASSERT_NE(MeChunkGetMem(&local, 10), nullptr);
  MeChunkTerm(&local);
  EXPECT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(counter.liveBlocks(), 0u);
  EXPECT_FALSE(local.inUse);
}

TEST_F(ChunkTest, AllocationFailureReturnsNullAndRecovers) {
  MessageCapture capture;
  CountingAllocator counter;
  counter.setFailing(true);
  EXPECT_EQ(MeChunkGetMem(&chunk, 5000), nullptr);
  EXPECT_FALSE(chunk.inUse);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 0);
  EXPECT_EQ(MeChunkGetSize(&chunk), 1024u);
  EXPECT_GE(capture.warnings().size(), 1u);

  counter.setFailing(false);
  ASSERT_NE(use(5000), nullptr);
  EXPECT_EQ(MeChunkGetSize(&chunk), 8192u);
  EXPECT_EQ(MeChunkGetGrowCount(&chunk), 3);
}

TEST_F(ChunkTest, ZeroFilledChunkActsAsDefault) {
  MeChunk zero{};
  void *mem = MeChunkGetMem(&zero, 2000);
  ASSERT_NE(mem, nullptr);
  EXPECT_EQ(MeChunkGetSize(&zero), 2048u);
  EXPECT_EQ(MeChunkGetGrowCount(&zero), 1);
  MeChunkPutMem(&zero, mem);
  MeChunkTerm(&zero);
}

TEST_F(ChunkTest, ImpossibleRequestWarnsAndReturnsNull) {
  MessageCapture capture;
  EXPECT_EQ(MeChunkGetMem(&chunk, SIZE_MAX), nullptr);
  EXPECT_EQ(capture.warnings().size(), 1u);
  EXPECT_FALSE(chunk.inUse);
}

}  // namespace
