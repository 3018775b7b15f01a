// ase_test.cpp: the ASE reader on a made-up pyramid (data/pyramid.ase) and
// on broken files (every kind of bad line, and random damage, which under
// AddressSanitizer is the reader's fuzz test), RGraphicLoadASE and
// RGraphicCreate's normalisation.
#include "viewer_internal.h"
#include "viewer_test_support.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

using karma::viewer::ParseAse;
using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

const std::string kPyramid = std::string(MEVIEWER_TEST_DATA) + "/pyramid.ase";

std::string ReadFile(const std::string &path) {
  std::ifstream f(path);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

TEST(Ase, ReadsThePyramid) {
  std::vector<RObjectVertex> v;
  std::string error;
  ASSERT_TRUE(ParseAse(ReadFile(kPyramid), v, error)) << error;
  ASSERT_EQ(v.size(), 18u);
  // Face 0 is (0, 1, 4): (-1,-1,0) (1,-1,0) (0,0,1.5); (2,0,0) x (1,1,1.5) = (0,-3,2), / sqrt 13.
  EXPECT_EQ(v[0].m_X, -1);
  EXPECT_EQ(v[2].m_Z, 1.5f);
  EXPECT_NEAR(v[0].m_NY, -3 / std::sqrt(13.0), 1e-6);
  EXPECT_NEAR(v[0].m_NZ, 2 / std::sqrt(13.0), 1e-6);
  // Texture corner 4 is (0.5, 0.5); corner 1 (1, 0) flips to v = 1.
  EXPECT_EQ(v[2].m_U, 0.5f);
  EXPECT_EQ(v[1].m_U, 1);
  EXPECT_EQ(v[1].m_V, 1);
  // Face 4 has given normals (one not unit): all (0, 0, -1).
  for (int k = 12; k < 15; ++k) {
    EXPECT_EQ(v[std::size_t(k)].m_NZ, -1) << k;
    EXPECT_EQ(v[std::size_t(k)].m_NX, 0) << k;
  }
}

TEST(Ase, BrokenFilesNameTheLine) {
  const std::string good = ReadFile(kPyramid);
  auto replace = [&](const std::string &from, const std::string &to) {
    std::string s = good;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  struct Case {
    std::string text;
    const char *mention;
  } cases[] = {
      {"*COMMENT nothing here\n", "no *MESH"},
      {replace("A:    0 B:    1 C:    4", "A:    0 B:    1 C:    9"), "face corner 9 is not a vertex"},
      {replace("*MESH_NUMFACES 6", "*MESH_NUMFACES 7"), "*MESH_NUMFACES says 7"},
      {replace("*MESH_NUMFACES 6", "*MESH_NUMFACES 5"), "more faces than *MESH_NUMFACES"},
      {replace("*MESH_VERTEX    4	 0.0", "*MESH_VERTEX    4	 zero"), "bad *MESH_VERTEX"},
      {replace("*MESH_VERTEX    4", "*MESH_VERTEX    7"), "index 7 out of range"},
      {replace("*MESH_TFACE 3	3	0	4", "*MESH_TFACE 3	3	0	8"), "texture corner 8"},
      {replace("*MESH_NUMVERTEX 5", "*MESH_NUMVERTEX 99999999999"), "bad *MESH_NUMVERTEX"},
      {replace("*MESH_NUMVERTEX 5", "*MESH_NUMVERTEX -5"), "bad *MESH_NUMVERTEX"},
      {replace("A:    0 B:    2 C:    1", "A    0 B    2 C    1"), "bad *MESH_FACE"},
      {replace("*MESH_VERTEXNORMAL 1	0.0	0.0	-2.0",
               "*MESH_VERTEXNORMAL 1	0.0	0.0	-2.0\n*MESH_VERTEXNORMAL 1 0 0 1"),
       "outside a face's three"},
      // Found by the libFuzzer target: a normal of a previous mesh's face.
      {good + "*MESH {\n*MESH_VERTEXNORMAL 0 0 0 1\n", "outside a face's three"},
      {replace("*MESH_NUMFACES 6", "*MESH_NUMFACES 6\n*MESH_NUMFACES 2"), "given twice"},
      {replace("*MESH_NUMVERTEX 5", "*MESH_NUMVERTEX 5\n*MESH_NUMVERTEX 9"), "given twice"}};
  for (const Case &c : cases) {
    std::vector<RObjectVertex> v;
    std::string error;
    EXPECT_FALSE(ParseAse(c.text, v, error)) << c.mention;
    EXPECT_NE(error.find(c.mention), std::string::npos) << error;
    EXPECT_TRUE(v.empty());
  }
}

TEST(Ase, RandomDamageNeverCrashes) {
  const std::string good = ReadFile(kPyramid);
  std::mt19937 rng(2024);
  const char alphabet[] = "*0123456789-. \n\tABC:MESH_VERTEXFACNUM";
  for (int round = 0; round < 1500; ++round) {
    std::string s = good.substr(0, rng() % (good.size() + 1));
    const int edits = 1 + int(rng() % 8);
    for (int e = 0; e < edits && !s.empty(); ++e) s[rng() % s.size()] = alphabet[rng() % (sizeof alphabet - 1)];
    std::vector<RObjectVertex> v;
    std::string error;
    if (ParseAse(s, v, error)) {
      EXPECT_EQ(v.size() % 3, 0u);
    } else {
      EXPECT_FALSE(error.empty());
    }
  }
}

TEST(Ase, LoadScalesAndCreateNormalises) {
  RRender *rc = MakeContext("prog -null");
  const float white[4] = {1, 1, 1, 1};
  std::string path = kPyramid;
  RGraphic *g = RGraphicLoadASE(rc, path.data(), 2, 3, 4, white, nullptr);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->m_pObject->m_nNumVertices, 18);
  EXPECT_EQ(g->m_pVertices[0].m_X, -2);
  EXPECT_EQ(g->m_pVertices[0].m_Y, -3);
  EXPECT_EQ(g->m_pVertices[2].m_Z, 6);
  EXPECT_EQ(rc->m_pRG_First, g);
  auto extent = [](const RGraphic *r, int axis, float &lo, float &hi) {
    lo = 1e9f, hi = -1e9f;
    for (int i = 0; i < r->m_pObject->m_nNumVertices; ++i) {
      const float p[3] = {r->m_pVertices[i].m_X, r->m_pVertices[i].m_Y, r->m_pVertices[i].m_Z};
      lo = std::min(lo, p[axis]), hi = std::max(hi, p[axis]);
    }
  };
  const AcmeReal c[4] = {1, 1, 1, 1};
  RGraphic *n = RGraphicCreate(rc, path.data(), 1, 1, 1, c, nullptr, 0, 0);
  ASSERT_NE(n, nullptr);
  float lo, hi;
  for (int axis = 0; axis < 3; ++axis) {
    extent(n, axis, lo, hi);
    EXPECT_NEAR(lo, -1, 1e-6) << axis;
    EXPECT_NEAR(hi, 1, 1e-6) << axis;
  }
  RGraphic *k = RGraphicCreate(rc, path.data(), 1, 1, 1, c, nullptr, 0, 1);  // keep aspect: z 1.5 of 2
  extent(k, 2, lo, hi);
  EXPECT_NEAR(hi - lo, 1.5, 1e-6);
  extent(k, 0, lo, hi);
  EXPECT_NEAR(hi - lo, 2, 1e-6);
  RRenderContextDestroy(rc);
}

TEST(Ase, MissingAndMalformedFilesGiveNull) {
  RRender *rc = MakeContext("prog -null");
  const float white[4] = {1, 1, 1, 1};
  Messages m;
  char missing[] = "no-such-model.ase";
  EXPECT_EQ(RGraphicLoadASE(rc, missing, 1, 1, 1, white, nullptr), nullptr);
  EXPECT_TRUE(Messages::Warned("cannot find 'no-such-model.ase'")) << Messages::All();
  viewer_test::TempDir dir("ase");
  std::string bad = (dir.path() / "bad.ase").string();
  std::ofstream(bad) << "*MESH {\n*MESH_NUMVERTEX 1\n*MESH_NUMFACES 1\n*MESH_FACE 0: A: 0 B: 0 C: 3\n}\n";
  EXPECT_EQ(RGraphicLoadASE(rc, bad.data(), 1, 1, 1, white, nullptr), nullptr);
  EXPECT_TRUE(Messages::Warned("line 4: face corner 3 is not a vertex")) << Messages::All();
  EXPECT_EQ(rc->m_pRG_First, nullptr);
  RRenderContextDestroy(rc);
}

}  // namespace
