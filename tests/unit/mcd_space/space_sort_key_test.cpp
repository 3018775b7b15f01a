// Sort keys order a space's pairs and the two models inside each pair
// ("Pair order" in engine/mcd/farfield/axis_sort_space.h): by key, and only
// between equal keys by insertion.
#include "space_test_support.h"

#include <utility>

using namespace space_test;

namespace {

using KeyPair = std::pair<int, int>;  // (model1's key, model2's key)

std::vector<KeyPair> Keys(const std::vector<McdModelPair *> &pairs) {
  std::vector<KeyPair> out;
  for (McdModelPair *p : pairs) out.emplace_back(McdModelGetSortKey(p->model1), McdModelGetSortKey(p->model2));
  return out;
}

// Indices (into b.models) of model1 and model2 of each pair.
std::vector<std::pair<int, int>> Indices(const Balls &b, const std::vector<McdModelPair *> &pairs) {
  auto index = [&](McdModelID m) {
    for (std::size_t i = 0; i < b.models.size(); ++i)
      if (b.models[i] == m) return (int)i;
    return -1;
  };
  std::vector<std::pair<int, int>> out;
  for (McdModelPair *p : pairs) out.emplace_back(index(p->model1), index(p->model2));
  return out;
}

}  // namespace

TEST(McdSpaceSortKeys, PairsAndModelOrderFollowTheKeysNotTheInsertion) {
  // Three overlapping unit balls inserted in the order 0, 1, 2 with keys
  // 3, 1, 2: model1 is the lower key, the pairs ascend by (key1, key2).
  Balls b({0, (MeReal)0.5, 1}, 100, 32, false);
  const int keys[3] = {3, 1, 2};
  for (int i = 0; i < 3; ++i) {
    McdModelSetSortKey(b.models[(size_t)i], keys[i]);
    McdSpaceInsertModel(b.space, b.models[(size_t)i]);
  }
  const Events e = Step(b.space);
  EXPECT_EQ(Keys(e.hello), (std::vector<KeyPair>{{1, 2}, {1, 3}, {2, 3}}));
  const Events again = Step(b.space);
  EXPECT_EQ(Keys(again.staying), (std::vector<KeyPair>{{1, 2}, {1, 3}, {2, 3}}));
}

TEST(McdSpaceSortKeys, EqualKeysKeepInsertionOrder) {
  Balls b({0, (MeReal)0.5, 1});
  const Events e = Step(b.space);
  EXPECT_EQ(Indices(b, e.hello), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
  // Two of three keys equal: the key decides first, insertion second.
  Balls c({0, (MeReal)0.5, 1}, 100, 32, false);
  const int keys[3] = {5, 5, 1};
  for (int i = 0; i < 3; ++i) {
    McdModelSetSortKey(c.models[(size_t)i], keys[i]);
    McdSpaceInsertModel(c.space, c.models[(size_t)i]);
  }
  EXPECT_EQ(Indices(c, Step(c.space).hello), (std::vector<std::pair<int, int>>{{2, 0}, {2, 1}, {0, 1}}));
}

TEST(McdSpaceSortKeys, ReverseInsertionWithTheSameKeysGivesTheSameEvents) {
  // Five balls in a row, each overlapping its neighbours; keyed by
  // position, inserted forwards in one space and backwards in the other.
  auto run = [](bool reverse) {
    Balls b({0, (MeReal)1.5, 3, (MeReal)4.5, 6}, 100, 32, false);
    for (int k = 0; k < 5; ++k) {
      const int i = reverse ? 4 - k : k;
      McdModelSetSortKey(b.models[(size_t)i], 10 + i);
      McdSpaceInsertModel(b.space, b.models[(size_t)i]);
    }
    std::vector<std::vector<KeyPair>> trace;
    for (int step = 0; step < 4; ++step) {
      const Events e = Step(b.space);
      trace.push_back(Keys(e.goodbye));
      trace.push_back(Keys(e.hello));
      trace.push_back(Keys(e.staying));
      b.move(2, (MeReal)(3 + step));  // ball 2 moves right through ball 3
      McdSpaceUpdateAll(b.space);
    }
    return trace;
  };
  const auto forward = run(false);
  EXPECT_EQ(forward, run(true));
  EXPECT_EQ(forward[1], (std::vector<KeyPair>{{10, 11}, {11, 12}, {12, 13}, {13, 14}}));
}

TEST(McdSpaceSortKeys, AKeyChangeReordersAndSwapsAPairWithGoodbyeAndHello) {
  Balls b({0, (MeReal)0.5, 1}, 100, 32, false);
  const int keys[3] = {1, 2, 3};
  for (int i = 0; i < 3; ++i) {
    McdModelSetSortKey(b.models[(size_t)i], keys[i]);
    McdSpaceInsertModel(b.space, b.models[(size_t)i]);
  }
  const Events first = Step(b.space);
  ASSERT_EQ(Keys(first.hello), (std::vector<KeyPair>{{1, 2}, {1, 3}, {2, 3}}));
  McdModelPair *kept = first.hello[2];  // (2, 3): models 1 and 2 keep their order
  // Model 0 now ranks last: its two pairs swap their models.
  McdModelSetSortKey(b.models[0], 9);
  const Events second = Step(b.space);
  EXPECT_EQ(Keys(second.goodbye), (std::vector<KeyPair>{{9, 2}, {9, 3}}))
      << "the goodbyes name the old model order (model1 was model 0)";
  EXPECT_EQ(Keys(second.hello), (std::vector<KeyPair>{{2, 9}, {3, 9}}));
  ASSERT_EQ(second.staying.size(), 1u);
  EXPECT_EQ(second.staying[0], kept) << "a pair whose order holds keeps its identity";
}

TEST(McdSpaceSortKeys, AKeyChangeThatKeepsEachPairsModelOrderOnlyResorts) {
  // Two separate overlapping pairs: (0, 1) far from (2, 3).
  Balls b({0, (MeReal)0.5, 10, (MeReal)10.5}, 100, 32, false);
  for (int i = 0; i < 4; ++i) {
    McdModelSetSortKey(b.models[(size_t)i], i + 1);
    McdSpaceInsertModel(b.space, b.models[(size_t)i]);
  }
  const Events first = Step(b.space);
  ASSERT_EQ(Keys(first.hello), (std::vector<KeyPair>{{1, 2}, {3, 4}}));
  McdModelSetSortKey(b.models[2], 0);  // pair (2, 3) now ranks first, same model order
  const Events second = Step(b.space);
  EXPECT_TRUE(second.goodbye.empty());
  EXPECT_TRUE(second.hello.empty());
  EXPECT_EQ(Keys(second.staying), (std::vector<KeyPair>{{0, 4}, {1, 2}}));
  ASSERT_EQ(second.staying.size(), 2u);
  EXPECT_EQ(second.staying[0], first.hello[1]) << "the same pair, re-sorted";
}

TEST(McdSpaceSortKeys, OwnKeyWinsOverTheInheritedOne) {
  Balls b({0, (MeReal)0.5}, 100, 32, false);
  McdModelSetInheritedSortKey(b.models[0], 7);
  McdModelSetInheritedSortKey(b.models[1], 4);
  for (McdModelID m : b.models) McdSpaceInsertModel(b.space, m);
  Events e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  EXPECT_EQ(e.hello[0]->model1, b.models[1]) << "inherited keys order the pair";
  EXPECT_EQ(McdModelGetSortKey(b.models[1]), 0) << "the model's own key is untouched";
  EXPECT_EQ(McdModelGetInheritedSortKey(b.models[1]), 4);
  McdModelSetSortKey(b.models[1], 8);  // its own key now: 8 > 7
  e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  EXPECT_EQ(e.hello[0]->model1, b.models[0]);
  McdModelSetInheritedSortKey(b.models[1], 0);  // no effect once the own key is set
  e = Step(b.space);
  EXPECT_TRUE(e.hello.empty());
  EXPECT_EQ(e.staying.size(), 1u);
}

TEST(McdSpaceSortKeys, BadKeysWarn) {
  WarningCapture w;
  Balls b({0});
  McdModelSetSortKey(b.models[0], 40000);
  EXPECT_TRUE(w.lastMentions("McdModelSetSortKey"));
  McdModelSetInheritedSortKey(b.models[0], -1);
  EXPECT_TRUE(w.lastMentions("McdModelSetInheritedSortKey"));
  EXPECT_EQ(McdModelGetSortKey(b.models[0]), 0);
  EXPECT_EQ(McdModelGetInheritedSortKey(b.models[0]), 0);
}
