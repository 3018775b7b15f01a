// stable_order_test.cpp: StableOrderByKey (nearfield/stable_order.h) gives
// std::stable_sort's order, ties included, for every small candidate count.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "nearfield/stable_order.h"

namespace {

TEST(McdStableOrder, MatchesStableSortWithTies) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> level(0, 3);  // few levels: many ties
  for (int n = 0; n <= 16; ++n) {
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<float> key((std::size_t)n);
      for (float &k : key) k = 0.25f * (float)level(rng) - 0.5f;
      std::vector<int> order((std::size_t)n);
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), rng);
      std::vector<int> expected = order;
      std::stable_sort(expected.begin(), expected.end(),
                       [&](int a, int b) { return key[(std::size_t)a] < key[(std::size_t)b]; });
      karma::mcd::StableOrderByKey(order.data(), n, key.data());
      EXPECT_EQ(order, expected) << "n = " << n << ", trial " << trial;
    }
  }
}

}  // namespace
