// report_test.cpp: karma-tradeoff's outputs: the CSV's columns and round
// trip, the peers' table, and the plot (a real PNG of the stated size).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "builtin_scenes.h"
#include "peers.h"
#include "plot.h"
#include "report.h"

namespace {

using namespace karma::tradeoff;

ResultRow SampleRow(double us, double drift, bool held) {
  ResultRow r;
  r.scene = "stack21";
  r.precision = "single";
  r.setting.method = MdtKeaMethodPGS;
  r.setting.iterations = 10;
  r.setting.epsilon = 1e-3;
  r.setting.h = 1.0 / 120;
  r.micros = {us * 1.1, us, us * 0.9};
  r.steps = 60;
  r.drift = drift;
  r.jointError = 0;
  r.penetration = 0.004;
  r.energyError = 2.5;
  r.momentumError = 0.5;
  r.residual = 1e-3;
  r.unsolvedSteps = 3;
  r.maxSpeed = 1.25;
  r.sceneError = drift / 2;
  r.held = held;
  r.detail = "top box drift 0.00 mm, height \"6.1\" m";
  return r;
}

std::string TempPath(const char *name) { return ::testing::TempDir() + name; }

TEST(TradeoffReport, CsvHasTheDocumentedColumnsAndReadsBack) {
  const std::vector<std::string> expected = {"scene",
                                             "precision",
                                             "engine",
                                             "setting",
                                             "solver",
                                             "epsilon",
                                             "gamma",
                                             "h",
                                             "tolerance",
                                             "cap",
                                             "projection",
                                             "warm",
                                             "reuse",
                                             "repeats",
                                             "us_per_step",
                                             "us_min",
                                             "us_max",
                                             "us_per_frame",
                                             "steps",
                                             "drift_m",
                                             "joint_error_m",
                                             "penetration_m",
                                             "energy_error_J",
                                             "momentum_error_Ns",
                                             "residual",
                                             "unsolved_steps",
                                             "max_speed_mps",
                                             "scene_error",
                                             "held",
                                             "front_drift",
                                             "front_scene",
                                             "detail"};
  EXPECT_EQ(CsvColumns(), expected);
  const std::string path = TempPath("tradeoff_test.csv");
  std::vector<ResultRow> rows = {SampleRow(100, 0.01, true), SampleRow(50, 0.2, false)};
  rows[0].frontDrift = true;
  rows[1].setting.projection = 2;
  rows[1].setting.warm = 0;
  rows[1].setting.reuse = 0;
  std::FILE *f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  WriteCsv(f, rows);
  std::fclose(f);
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(SplitCsvLine(header), expected);
  std::getline(in, line);
  const std::vector<std::string> cells = SplitCsvLine(line);
  ASSERT_EQ(cells.size(), expected.size());
  EXPECT_EQ(cells[3], "iterative:10 epsilon=0.001 h=1/120");
  EXPECT_EQ(cells[10], "");     // projection: the scene's own
  EXPECT_EQ(cells[11], "");     // warm: the scene's own
  EXPECT_EQ(cells[12], "");     // reuse: the scene's own
  EXPECT_EQ(cells[14], "100");  // the median of the repetitions
  EXPECT_EQ(cells[17], "200");  // 1/60 s is two steps of 1/120 s
  EXPECT_EQ(cells[29], "1");
  EXPECT_EQ(cells[31], "top box drift 0.00 mm, height \"6.1\" m");  // quotes survive
  std::vector<ResultRow> back;
  std::string error;
  ASSERT_TRUE(ReadCsv(path, back, error)) << error;
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].setting.label(), rows[1].setting.label());
  EXPECT_EQ(back[1].setting.projection, 2);
  EXPECT_EQ(back[1].setting.warm, 0);
  EXPECT_EQ(back[1].setting.reuse, 0);
  EXPECT_DOUBLE_EQ(back[1].median(), 50);
  EXPECT_DOUBLE_EQ(back[1].drift, 0.2);
  EXPECT_FALSE(back[1].held);
  EXPECT_EQ(back[1].unsolvedSteps, 3);
}

// Reads the width and height from a PNG's IHDR chunk; false when the file
// is not a PNG.
bool PngSize(const std::string &path, unsigned &width, unsigned &height) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 33 || !std::equal(signature, signature + 8, bytes.begin())) return false;
  if (std::string(bytes.begin() + 12, bytes.begin() + 16) != "IHDR") return false;
  auto be32 = [&](size_t at) {
    return (unsigned)bytes[at] << 24 | (unsigned)bytes[at + 1] << 16 | (unsigned)bytes[at + 2] << 8 | bytes[at + 3];
  };
  width = be32(16);
  height = be32(20);
  return true;
}

TEST(TradeoffReport, AColumnIsFoundByItsNameAndAMissingNameStops) {
  const std::vector<std::string> &columns = CsvColumns();
  for (size_t i = 0; i < columns.size(); ++i) EXPECT_EQ(CsvColumn(columns[i].c_str()), i) << columns[i];
  EXPECT_DEATH(CsvColumn("us_per_stepp"), "no CSV column named \"us_per_stepp\"");
}

TEST(TradeoffReport, ThePlotIsAPngOfTheStatedSize) {
  const std::string gnuplot = FindGnuplot();
  ASSERT_FALSE(gnuplot.empty()) << "gnuplot is missing: scripts/install-deps.sh installs gnuplot-nox";
  std::vector<ResultRow> rows = {SampleRow(100, 0.01, true), SampleRow(50, 0.2, true), SampleRow(70, 0.5, true),
                                 SampleRow(30, 0.3, false)};
  MarkFronts(rows, "stack21");
  PlotRequest q;
  q.scene = "stack21";
  q.title = "test";
  q.yLabel = "drift (m)";
  q.path = TempPath("tradeoff_test_plot.png");
  q.width = 640;
  q.height = 360;
  std::remove(q.path.c_str());
  std::string error;
  ASSERT_TRUE(Plot(gnuplot, q, rows, error)) << error;
  unsigned w = 0, h = 0;
  ASSERT_TRUE(PngSize(q.path, w, h)) << q.path << " is not a PNG";
  EXPECT_EQ(w, 640u);
  EXPECT_EQ(h, 360u);
  // The data drawn, in µs per 1/60 s (two steps of 1/120 s): the front
  // (two points, by cost), the dominated setting and the failed run apart.
  std::ifstream data(q.path + ".gp");
  const std::string text((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("$front << EOD\n100 0.2 \"iterative:10 epsilon=0.001 h=1/120\"\n200 0.01 "), std::string::npos)
      << text;
  EXPECT_NE(text.find("$settings << EOD\n140 0.5 "), std::string::npos) << text;
  EXPECT_NE(text.find("$failed << EOD\n60 0.3 "), std::string::npos) << text;
}

TEST(TradeoffReport, AMissingGnuplotIsFound) {
  setenv("KARMA_GNUPLOT", "/nonexistent/gnuplot", 1);
  EXPECT_EQ(FindGnuplot(), "");
  unsetenv("KARMA_GNUPLOT");
}

TEST(TradeoffPeers, PeerBenchRowsGiveTheSceneError) {
  ResultRow r;
  ASSERT_TRUE(
      ParsePeerRow("| car (300) | ode-step | 12.2 [12.0–13.1] | 1.00 | 0.89 | yes | v 16.100 m/s (analytic "
                   "16.180), x 40.250 m (analytic 40.450), height 0.582 m | 16.10 | 1.2 |",
                   r));
  EXPECT_EQ(r.scene, "car");
  EXPECT_EQ(r.engine, "ode-step");
  EXPECT_DOUBLE_EQ(r.median(), 12.2);
  EXPECT_DOUBLE_EQ(r.low(), 12.0);
  EXPECT_DOUBLE_EQ(r.high(), 13.1);
  EXPECT_TRUE(r.held);
  EXPECT_NEAR(r.sceneError, 0.2, 1e-9);
  ASSERT_TRUE(
      ParsePeerRow("| stack21 (1200) | bullet | 1,921 [1,900–2,000] | 1.00 | 0.89 | **no**: check | top box "
                   "drift 120.00 mm, height 6.0000 m | 3.10 | 1.2 |",
                   r));
  EXPECT_DOUBLE_EQ(r.median(), 1921);
  EXPECT_FALSE(r.held);
  // The top box starts at 6.17 m; closing the 20 gaps of 1 mm takes it to
  // 6.15 m: it sank 0.15 m more, more than its 0.12 m drift.
  EXPECT_NEAR(r.sceneError, 0.15, 1e-9);
  ASSERT_TRUE(
      ParsePeerRow("| pile1000 (60 of 600) | ode-quickstep | 6,150 [6,000–6,200] | 0.16 | 1.00 | yes | lowest "
                   "centre 0.250 m, farthest 4.10 m from the middle | 5.00 | 36.0 |",
                   r));
  EXPECT_NEAR(r.sceneError, 0.036, 1e-12);
  EXPECT_FALSE(ParsePeerRow("|---|---|---|---|---|---|---|---|---|", r));
  EXPECT_FALSE(
      ParsePeerRow("| scene (steps) | engine | µs/step, median [range] | × ODE step | × ODE QuickStep | stable "
                   "| scene figures | max speed (m/s) | penetration (mm) |",
                   r));
}

TEST(TradeoffPeers, StackClosureIsTheStartingGaps) {
  EXPECT_NEAR(StackClosure(karma::scenes::Stack21Spec()), 0.020, 1e-12);  // 20 gaps of 1 mm
  EXPECT_NEAR(StackClosure(karma::scenes::ToppleSpec()), 0.005, 1e-12);   // the six-box stack
}

}  // namespace
