// MePool: capacity, hand-out order, exhaustion, reuse, bad returns,
// iteration and determinism.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "MePool.h"
#include "runtime_test_support.h"

using karma_test::CountingAllocator;
using karma_test::MessageCapture;

namespace {

struct Body {
  double position[3];
  int id;
};

class PoolTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(MePoolInit(&pool, 5, sizeof(Body), 16)); }
  void TearDown() override { MePoolDestroy(&pool); }

  std::vector<void *> takeAll() {
    std::vector<void *> taken;
    for (void *p; (p = MePoolGetStruct(&pool)) != nullptr;) taken.push_back(p);
    return taken;
  }

  MePool pool;
};

TEST_F(PoolTest, StartsEmptyWithItsCapacity) {
  EXPECT_EQ(MePoolGetUsed(&pool), 0);
  EXPECT_EQ(MePoolGetUnused(&pool), 5);
  EXPECT_EQ(MePoolGetMaxCount(&pool), 5);
}

TEST_F(PoolTest, HandsOutDistinctAlignedStructsInAddressOrder) {
  MessageCapture capture;  // the final failing Get warns
  const std::vector<void *> taken = takeAll();
  ASSERT_EQ(taken.size(), 5u);
  for (std::size_t i = 0; i < taken.size(); ++i) {
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(taken[i]) % 16, 0u);
    if (i > 0) {
      EXPECT_GE(static_cast<char *>(taken[i]) - static_cast<char *>(taken[i - 1]),
                static_cast<std::ptrdiff_t>(sizeof(Body)));
    }
    std::memset(taken[i], int(i), sizeof(Body));  // no overlap (sanitizer build)
  }
  EXPECT_EQ(MePoolGetUsed(&pool), 5);
  EXPECT_EQ(MePoolGetUnused(&pool), 0);
}

TEST_F(PoolTest, ExhaustionReturnsNullWithOneWarning) {
  MessageCapture capture;
  MePoolSetName(&pool, "bodies");
  for (int i = 0; i < 5; ++i) ASSERT_NE(MePoolGetStruct(&pool), nullptr) << i;
  EXPECT_TRUE(capture.warnings().empty());

  EXPECT_EQ(MePoolGetStruct(&pool), nullptr);  // maxCount + 1
  ASSERT_EQ(capture.warnings().size(), 1u);
  const std::string &text = capture.warnings()[0].text;
  EXPECT_NE(text.find("\"bodies\""), std::string::npos) << text;
  EXPECT_NE(text.find("all 5 of its structs"), std::string::npos) << text;

  for (int i = 0; i < 100; ++i) EXPECT_EQ(MePoolGetStruct(&pool), nullptr);
  EXPECT_EQ(capture.warnings().size(), 1u) << "a full pool must not flood";
  EXPECT_EQ(MePoolGetUsed(&pool), 5);
}

TEST_F(PoolTest, WarningIsReArmedOnceAStructComesBack) {
  MessageCapture capture;
  std::vector<void *> taken = takeAll();
  ASSERT_EQ(capture.warnings().size(), 1u);
  MePoolPutStruct(&pool, taken[2]);
  EXPECT_EQ(MePoolGetStruct(&pool), taken[2]);
  EXPECT_EQ(MePoolGetStruct(&pool), nullptr);
  EXPECT_EQ(capture.warnings().size(), 2u);
}

TEST_F(PoolTest, ReturnedStructsAreReusedLastInFirstOut) {
  void *a = MePoolGetStruct(&pool);
  void *b = MePoolGetStruct(&pool);
  void *c = MePoolGetStruct(&pool);
  MePoolPutStruct(&pool, b);
  MePoolPutStruct(&pool, a);
  EXPECT_EQ(MePoolGetUsed(&pool), 1);
  EXPECT_EQ(MePoolGetStruct(&pool), a);
  EXPECT_EQ(MePoolGetStruct(&pool), b);
  void *d = MePoolGetStruct(&pool);
  EXPECT_NE(d, a);
  EXPECT_NE(d, b);
  EXPECT_NE(d, c);
  EXPECT_EQ(MePoolGetUsed(&pool), 4);
}

TEST_F(PoolTest, BadPutsAreIgnoredAndReportedInTheCheckBuild) {
  MessageCapture capture;
  void *a = MePoolGetStruct(&pool);
  Body outsider{};
  MePoolPutStruct(&pool, &outsider);                   // not from the pool
  MePoolPutStruct(&pool, static_cast<char *>(a) + 8);  // inside a struct
  MePoolPutStruct(&pool, a);                           // fine
  MePoolPutStruct(&pool, a);                           // twice
  MePoolPutStruct(&pool, nullptr);                     // silently ignored

  EXPECT_EQ(MePoolGetUsed(&pool), 0);
  EXPECT_EQ(MePoolGetUnused(&pool), 5);
#if KARMA_CHECK
  ASSERT_EQ(capture.warnings().size(), 3u);
  EXPECT_NE(capture.warnings()[0].text.find("is not a struct of pool"), std::string::npos);
  EXPECT_NE(capture.warnings()[2].text.find("already free"), std::string::npos);
#else
  EXPECT_TRUE(capture.warnings().empty());
#endif
  // The free list is intact: exactly 5 distinct structs come out.
  capture.clear();
  std::vector<void *> taken = takeAll();
  ASSERT_EQ(taken.size(), 5u);
  for (std::size_t i = 0; i < taken.size(); ++i)
    for (std::size_t j = i + 1; j < taken.size(); ++j) EXPECT_NE(taken[i], taken[j]);
}

TEST_F(PoolTest, ResetFreesEverythingAndRestoresTheOrder) {
  void *first = MePoolGetStruct(&pool);
  MePoolGetStruct(&pool);
  MePoolPutStruct(&pool, first);
  MePoolGetStruct(&pool);
  MePoolReset(&pool);
  EXPECT_EQ(MePoolGetUsed(&pool), 0);
  EXPECT_EQ(MePoolGetUnused(&pool), 5);
  EXPECT_EQ(MePoolGetStruct(&pool), first);
}

TEST_F(PoolTest, IteratesOverUsedStructsInAddressOrder) {
  MessageCapture capture;
  std::vector<void *> taken = takeAll();
  MePoolPutStruct(&pool, taken[1]);
  MePoolPutStruct(&pool, taken[3]);
  std::vector<void *> seen;
  for (void *p = MePoolGetNextUsed(&pool, nullptr); p; p = MePoolGetNextUsed(&pool, p)) seen.push_back(p);
  EXPECT_EQ(seen, (std::vector<void *>{taken[0], taken[2], taken[4]}));

  // Putting back the current struct during a pass is allowed.
  int visited = 0;
  for (void *p = MePoolGetNextUsed(&pool, nullptr); p; p = MePoolGetNextUsed(&pool, p)) {
    MePoolPutStruct(&pool, p);
    ++visited;
  }
  EXPECT_EQ(visited, 3);
  EXPECT_EQ(MePoolGetUsed(&pool), 0);
  EXPECT_EQ(MePoolGetNextUsed(&pool, nullptr), nullptr);
}

TEST(PoolStandaloneTest, HandOutOrderDependsOnlyOnTheCallSequence) {
  auto run = []() {
    MePool pool;
    EXPECT_TRUE(MePoolInit(&pool, 8, 24, 8));
    std::vector<long> indices;
    std::vector<void *> held;
    const char script[] = "gggpgpggpppgggg";
    for (char op : script) {
      if (op == 'g') {
        void *p = MePoolGetStruct(&pool);
        held.push_back(p);
        indices.push_back((static_cast<char *>(p) - static_cast<char *>(pool.memory)) / pool.stride);
      } else if (op == 'p') {
        MePoolPutStruct(&pool, held[held.size() / 2]);
        held.erase(held.begin() + long(held.size() / 2));
      }
    }
    MePoolDestroy(&pool);
    return indices;
  };
  const std::vector<long> first = run();
  EXPECT_EQ(first, run());
  EXPECT_EQ(first, (std::vector<long>{0, 1, 2, 1, 2, 3, 3, 1, 2, 4}));
}

TEST(PoolStandaloneTest, ZeroCapacityPoolAlwaysFails) {
  MessageCapture capture;
  CountingAllocator counter;
  MePool pool;
  ASSERT_TRUE(MePoolInit(&pool, 0, 16, 0));
  EXPECT_EQ(counter.creates(), 0);
  EXPECT_EQ(MePoolGetStruct(&pool), nullptr);
  EXPECT_EQ(capture.warnings().size(), 1u);
  MePoolDestroy(&pool);
}

TEST(PoolStandaloneTest, BadArgumentsFailCleanly) {
  MessageCapture capture;
  MePool pool;
  EXPECT_FALSE(MePoolInit(&pool, -1, 16, 0));
  EXPECT_FALSE(MePoolInit(&pool, 4, 0, 0));
  EXPECT_FALSE(MePoolInit(&pool, 4, 16, 3));
  EXPECT_FALSE(MePoolInit(&pool, 4, 16, -8));
  EXPECT_FALSE(MePoolInit(nullptr, 4, 16, 0));
  EXPECT_EQ(capture.warnings().size(), 5u);
  EXPECT_NE(capture.warnings()[2].text.find("MePoolInit: alignment 3"), std::string::npos);
  EXPECT_EQ(pool.memory, nullptr);
  EXPECT_EQ(MePoolGetMaxCount(&pool), 0);
  MePoolDestroy(&pool);
  MePoolDestroy(nullptr);
}

TEST(PoolStandaloneTest, AllocationFailureFailsCleanly) {
  MessageCapture capture;
  CountingAllocator counter;
  counter.setFailing(true);
  MePool pool;
  EXPECT_FALSE(MePoolInit(&pool, 10, 16, 0));
  EXPECT_EQ(pool.memory, nullptr);
  EXPECT_EQ(MePoolGetStruct(&pool), nullptr);
  EXPECT_GE(capture.warnings().size(), 1u);
  MePoolDestroy(&pool);
}

TEST(PoolStandaloneTest, ZeroFilledPoolIsSafe) {
  MessageCapture capture;
  MePool pool{};
  EXPECT_EQ(MePoolGetStruct(&pool), nullptr);
  int local = 0;
  MePoolPutStruct(&pool, &local);
  EXPECT_EQ(MePoolGetNextUsed(&pool, nullptr), nullptr);
  MePoolDestroy(&pool);
}

TEST(PoolStandaloneTest, StructSizeIsRoundedUpToTheAlignment) {
  MePool pool;
  ASSERT_TRUE(MePoolInit(&pool, 3, 20, 64));
  EXPECT_EQ(pool.stride, 64);
  void *a = MePoolGetStruct(&pool);
  void *b = MePoolGetStruct(&pool);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a) % 64, 0u);
  EXPECT_EQ(static_cast<char *>(b) - static_cast<char *>(a), 64);
  MePoolDestroy(&pool);
}

}  // namespace
