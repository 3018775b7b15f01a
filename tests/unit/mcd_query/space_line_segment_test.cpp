// Space-wide line segment queries: first hit, all hits nearest first (one
// per model), the filtered first hit, and the change-block rule.
#include "query_test_support.h"

namespace {

using mcd_query_test::Scene;
using mcd_query_test::Warnings;

// Three unit spheres along +x at 3, 6 and 9, plus a box off the line.
struct Row {
  Scene scene;
  McdSpaceID space;
  McdModelID ball[3];
  McdModelID box;
  Row() {
    space = McdSpaceAxisSortCreate(scene.fw(), McdAllAxes, 16, 64);
    McdGeometryID g = McdSphereCreate(scene.fw(), 1);
    // Inserted out of order: results must not depend on insertion order.
    ball[2] = scene.place(g, 9, 0, 0);
    ball[0] = scene.place(g, 3, 0, 0);
    ball[1] = scene.place(g, 6, 0, 0);
    box = scene.place(McdBoxCreate(scene.fw(), 1, 1, 1), 5, 5, 0);
    for (McdModelID m : {ball[2], ball[0], ball[1], box}) McdSpaceInsertModel(space, m);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
  }
  ~Row() {
    if (!McdSpaceIsChanging(space)) McdSpaceBeginChanges(space);
    for (McdModelID m : {ball[0], ball[1], ball[2], box}) McdSpaceRemoveModel(m);
    McdSpaceEndChanges(space);
    McdSpaceDestroy(space);
  }
};

int MEAPI notTheFirstBall(McdModelID m, void *data) { return m != static_cast<Row *>(data)->ball[0]; }

TEST(SpaceLineSegment, FirstAllAndFiltered) {
  Row row;
  MeVector3 a = {0, 0, 0}, b = {20, 0, 0};
  McdLineSegIntersectResult first;
  ASSERT_EQ(McdSpaceGetLineSegFirstIntersection(row.space, a, b, &first), 1);
  EXPECT_EQ(first.model, row.ball[0]);
  EXPECT_NEAR(first.distance, 2, 1e-5);

  McdLineSegIntersectResult all[8];
  ASSERT_EQ(McdSpaceGetLineSegIntersections(row.space, a, b, all, 8), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(all[i].model, row.ball[i]);
    EXPECT_NEAR(all[i].distance, 2 + 3 * i, 1e-5);
  }
  EXPECT_EQ(McdSpaceGetLineSegIntersections(row.space, a, b, all, 2), 2);  // capped
  EXPECT_EQ(all[1].model, row.ball[1]);

  McdLineSegIntersectResult filtered;
  ASSERT_EQ(McdSpaceGetLineSegFirstEnabledIntersection(row.space, a, b, notTheFirstBall, &row, &filtered), 1);
  EXPECT_EQ(filtered.model, row.ball[1]);
  EXPECT_NEAR(filtered.distance, 5, 1e-5);

  MeVector3 up = {5, 10, 0}, down = {5, -10, 0};  // through the box only
  ASSERT_EQ(McdSpaceGetLineSegFirstIntersection(row.space, up, down, &first), 1);
  EXPECT_EQ(first.model, row.box);
  EXPECT_NEAR(first.distance, 4.5, 1e-5);
  MeVector3 miss = {0, 20, 0}, miss2 = {20, 20, 0};
  EXPECT_EQ(McdSpaceGetLineSegFirstIntersection(row.space, miss, miss2, &first), 0);
}

TEST(SpaceLineSegment, InsideAChangeBlockWarnsAndReportsNothing) {
  Row row;
  McdSpaceBeginChanges(row.space);
  MeVector3 a = {0, 0, 0}, b = {20, 0, 0};
  McdLineSegIntersectResult r[4];
  Warnings w;
  EXPECT_EQ(McdSpaceGetLineSegFirstIntersection(row.space, a, b, r), 0);
  EXPECT_EQ(McdSpaceGetLineSegIntersections(row.space, a, b, r, 4), 0);
  EXPECT_EQ(w.count(), 2u);
  EXPECT_NE(w.last().find("change block"), std::string::npos);
  EXPECT_EQ(McdSpaceGetLineSegIntersections(row.space, a, b, r, -1), 0);
  EXPECT_EQ(McdSpaceGetLineSegFirstIntersection(nullptr, a, b, r), 0);
  EXPECT_EQ(w.count(), 4u);
}

}  // namespace
