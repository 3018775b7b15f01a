// Pair life cycles through the public McdSpace API where the farfield must
// notice a change that no model's box shows: a culling table's flag changed
// while its pair overlaps, a kept frozen pair whose models swap sort-key
// rank, and a pairCount far beyond what the scene needs.
#include "../mcd_space/space_test_support.h"

#include <cstdio>
#include <memory>
#include <set>
#include <vector>

using namespace space_test;

namespace {

// Two touching balls a and c culled against each other through table
// index 0 and 1 (same culling ID), and a third ball far away.
struct CulledBalls {
  Balls b{{}, 100};
  McdCullingTable *table = McdCullingTableCreate(4);
  McdModelID a, c, far;
  explicit CulledBalls(bool culled) {
    McdCullingTableSet(table, 0, 1, culled);
    a = b.add(0, false);
    c = b.add((MeReal)0.5, false);
    far = b.add(5, false);
    McdSpaceInsertModelWithCulling(b.space, a, table, 0, 7);
    McdSpaceInsertModelWithCulling(b.space, c, table, 1, 7);
    McdSpaceInsertModel(b.space, far);
    McdSpaceUpdateAll(b.space);
  }
  ~CulledBalls() {
    McdSpaceDestroy(b.space);
    b.space = nullptr;
    McdCullingTableDestroy(table);
  }
};

}  // namespace

TEST(McdSpaceCulling, AFlagSetWhileAPairOverlapsSaysGoodbyeAtTheNextEndChanges) {
  CulledBalls s(false);
  Events e = Step(s.b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *pair = e.hello[0];
  McdCullingTableSet(s.table, 1, 0, 1);
  EXPECT_EQ(McdSpacePairIsEnabled(s.a, s.c), 0);
  McdSpaceUpdateAll(s.b.space);
  e = Step(s.b.space);
  ASSERT_EQ(e.goodbye.size(), 1u);
  EXPECT_EQ(e.goodbye[0], pair);
  EXPECT_TRUE(e.hello.empty() && e.staying.empty());
  // Culled from then on, also when an unrelated model moves.
  McdSpaceUpdateAll(s.b.space);
  e = Step(s.b.space);
  EXPECT_TRUE(e.hello.empty() && e.staying.empty() && e.goodbye.empty());
  s.b.move(2, 4);
  McdSpaceUpdateAll(s.b.space);
  e = Step(s.b.space);
  EXPECT_TRUE(e.hello.empty() && e.staying.empty() && e.goodbye.empty());
}

TEST(McdSpaceCulling, AFlagClearedWhileAPairOverlapsSaysHelloAtTheNextEndChanges) {
  CulledBalls s(true);
  Events e = Step(s.b.space);
  EXPECT_TRUE(e.hello.empty());
  McdCullingTableSet(s.table, 0, 1, 0);
  EXPECT_EQ(McdSpacePairIsEnabled(s.a, s.c), 1);
  McdSpaceUpdateAll(s.b.space);
  e = Step(s.b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *pair = e.hello[0];
  EXPECT_EQ(pair->model1, s.a);
  EXPECT_EQ(pair->model2, s.c);
  McdSpaceUpdateAll(s.b.space);
  e = Step(s.b.space);
  ASSERT_EQ(e.staying.size(), 1u);
  EXPECT_EQ(e.staying[0], pair);
  EXPECT_TRUE(e.hello.empty() && e.goodbye.empty());
}

TEST(McdSpaceSortKeys, AKeptFrozenPairWhoseModelsSwapRanksSaysGoodbyeAndHelloAgain) {
  Balls b({0, (MeReal)0.5}, 100, 32, false);
  McdModelID a = b.models[0], c = b.models[1];
  McdModelSetSortKey(a, 1);
  McdModelSetSortKey(c, 2);
  McdSpaceInsertModel(b.space, a);
  McdSpaceInsertModel(b.space, c);
  McdSpaceUpdateAll(b.space);
  Events e = Step(b.space);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *first = e.hello[0];
  McdSpaceFreezeModel(a);
  McdSpaceFreezeModel(c);
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.staying.size(), 1u);  // the keep-frozen-pairs policy
  EXPECT_EQ(e.staying[0], first);

  McdModelSetSortKey(a, 3);  // a now ranks after c
  McdSpaceUpdateAll(b.space);
  e = Step(b.space);
  ASSERT_EQ(e.goodbye.size(), 1u);
  EXPECT_EQ(e.goodbye[0], first);
  ASSERT_EQ(e.hello.size(), 1u);
  McdModelPair *second = e.hello[0];
  EXPECT_EQ(second->model1, c);
  EXPECT_EQ(second->model2, a);
  EXPECT_TRUE(e.staying.empty());

  for (int step = 0; step < 2; ++step) {
    McdSpaceUpdateAll(b.space);
    e = Step(b.space);
    ASSERT_EQ(e.staying.size(), 1u) << "step " << step;
    EXPECT_EQ(e.staying[0], second);
    EXPECT_TRUE(e.hello.empty() && e.goodbye.empty());
  }
}

namespace {

// The process's resident memory in bytes (Linux), or -1 when unknown.
long long ResidentBytes() {
  long long pages = -1, resident = -1;
  if (std::FILE *f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%lld %lld", &pages, &resident) != 2) resident = -1;
    std::fclose(f);
  }
  return resident < 0 ? -1 : resident * 4096;
}

}  // namespace

TEST(McdSpaceCapacity, AHugePairCountTakesNoMemoryUntilThePairsExist) {
  Framework fw(128, 0);
  const long long before = ResidentBytes();
  McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 128, 100000000);
  ASSERT_NE(space, nullptr);
  const long long after = ResidentBytes();
  if (before >= 0 && after >= 0) {
    EXPECT_LT(after - before, 64ll << 20) << "bytes taken by the new space";
  }

  // Its pairs are made as they come, past the first records, without the
  // warning of a space outgrowing its pairCount: 100 balls in one place
  // give 4950 pairs.
  WarningCapture w;
  McdGeometryID g = McdSphereCreate(fw, 1);
  std::vector<std::unique_ptr<TM>> tms;
  std::vector<McdModelID> models;
  for (int i = 0; i < 100; ++i) {
    tms.push_back(std::make_unique<TM>((MeReal)0.01 * (MeReal)i, 0, 0));
    models.push_back(McdModelCreate(g));
    McdModelSetTransformPtr(models.back(), *tms.back());
    McdSpaceInsertModel(space, models.back());
  }
  McdSpaceUpdateAll(space);
  Events e = Step(space);
  ASSERT_EQ(e.hello.size(), 4950u);
  std::set<McdModelPair *> distinct(e.hello.begin(), e.hello.end());
  EXPECT_EQ(distinct.size(), 4950u);
  for (McdModelPair *p : e.hello) {
    ASSERT_NE(p->model1, nullptr);
    ASSERT_NE(p->model2, nullptr);
  }
  McdSpaceUpdateAll(space);
  e = Step(space);
  EXPECT_EQ(e.staying.size(), 4950u);
  EXPECT_EQ(w.count(), 0u);
  McdSpaceDestroy(space);
  for (McdModelID m : models) McdModelDestroy(m);
  McdGeometryDestroy(g);
}
