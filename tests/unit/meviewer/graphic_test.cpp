// graphic_test.cpp: the geometry data format, render lists, colours, the
// primitives' shapes (vertex counts, unit normals, extents, winding) and the
// strip conversion.
#include "viewer_test_support.h"

#include <cmath>
#include <cstdint>

using viewer_test::MakeContext;
using viewer_test::Messages;

namespace {

const float kRed[4] = {1, 0, 0, 1};

class Graphics : public ::testing::Test {
 protected:
  void SetUp() override {
    rc = MakeContext("prog -null");
    ASSERT_NE(rc, nullptr);
  }
  void TearDown() override { RRenderContextDestroy(rc); }
  int Count(bool is2D) {
    int n = 0;
    for (RGraphic *g = is2D ? rc->m_pRG_First2D : rc->m_pRG_First; g; g = g->m_pNext) ++n;
    return n;
  }
  RRender *rc = nullptr;
};

// Every vertex normal has unit length, and in every triangle that is not
// degenerate the winding's normal (b - a) x (c - a) agrees with the vertex
// normals (anticlockwise seen from outside).
void ExpectWellFormed(const RGraphic *g) {
  ASSERT_NE(g, nullptr);
  const int n = g->m_pObject->m_nNumVertices;
  ASSERT_GT(n, 0);
  ASSERT_EQ(n % 3, 0);
  ASSERT_LE(n, g->m_nMaxNumVertices);
  int checked = 0;
  for (int i = 0; i < n; i += 3) {
    const RObjectVertex *v = g->m_pVertices + i;
    for (int k = 0; k < 3; ++k) {
      const double len = std::sqrt(v[k].m_NX * v[k].m_NX + v[k].m_NY * v[k].m_NY + v[k].m_NZ * v[k].m_NZ);
      EXPECT_NEAR(len, 1, 1e-4) << "vertex " << i + k;
      EXPECT_GE(v[k].m_U, -1e-6f);
      EXPECT_LE(v[k].m_U, 1 + 1e-6f);
    }
    const double e1[3] = {v[1].m_X - v[0].m_X, v[1].m_Y - v[0].m_Y, v[1].m_Z - v[0].m_Z};
    const double e2[3] = {v[2].m_X - v[0].m_X, v[2].m_Y - v[0].m_Y, v[2].m_Z - v[0].m_Z};
    const double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double clen = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (clen < 1e-6) continue;  // degenerate (the sphere's poles)
    const double nsum[3] = {double(v[0].m_NX) + v[1].m_NX + v[2].m_NX, double(v[0].m_NY) + v[1].m_NY + v[2].m_NY,
                            double(v[0].m_NZ) + v[1].m_NZ + v[2].m_NZ};
    EXPECT_GT(c[0] * nsum[0] + c[1] * nsum[1] + c[2] * nsum[2], 0) << "triangle " << i / 3 << " winds clockwise";
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(GraphicData, CreateEmptyLaysOutHeaderThenVertices) {
  RGraphic *g = RGraphicCreateEmpty(9);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->m_nMaxNumVertices, 9);
  EXPECT_EQ(g->m_pObject->m_nNumVertices, 0);
  EXPECT_EQ(g->m_pObject->m_nTextureID, -1);
  EXPECT_EQ(g->m_pObject->m_bIsWireFrame, 0);
  EXPECT_EQ(g->m_pLWMatrix, nullptr);
  EXPECT_EQ(g->m_pObject->m_Matrix[0][0], 1);
  EXPECT_EQ(g->m_pObject->m_Matrix[3][3], 1);
  EXPECT_EQ(g->m_pObject->m_Matrix[3][0], 0);
  // The vertices follow the header (padded to 16 bytes) in the same block.
  const auto h = reinterpret_cast<std::uintptr_t>(g->m_pObject), v = reinterpret_cast<std::uintptr_t>(g->m_pVertices);
  EXPECT_GE(v, h + sizeof(RObjectHeader));
  EXPECT_LT(v, h + sizeof(RObjectHeader) + 16);
  EXPECT_EQ(v % 16, 0u);
  g->m_pVertices[8].m_X = 3;  // all nine are usable
  RGraphicDestroy(g);
  RGraphicDestroy(nullptr);
}

TEST(GraphicData, CreateEmptyRejectsNegativeCounts) {
  Messages m;
  EXPECT_EQ(RGraphicCreateEmpty(-3), nullptr);
  EXPECT_TRUE(Messages::Warned("RGraphicCreateEmpty"));
}

TEST(GraphicData, SetColorFillsAmbientAndDiffuseAndZeroesTheRest) {
  RGraphic *g = RGraphicCreateEmpty(3);
  g->m_pObject->m_ColorSpecular[0] = 0.5f;
  const float c[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  RGraphicSetColor(g, c);
  float out[4];
  RGraphicGetColor(g, out);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i], c[i]);
    EXPECT_EQ(g->m_pObject->m_ColorDiffuse[i], c[i]);
    EXPECT_EQ(g->m_pObject->m_ColorEmissive[i], 0);
    EXPECT_EQ(g->m_pObject->m_ColorSpecular[i], 0);
  }
  RGraphicSetWireframe(g, 1);
  EXPECT_EQ(g->m_pObject->m_bIsWireFrame, 1);
  MeMatrix4 tm;
  RGraphicSetTransformPtr(g, tm);
  EXPECT_EQ(g->m_pLWMatrix, tm);
  RGraphicDestroy(g);
}

TEST_F(Graphics, ListsKeepOrderAndRemoveAndDelete) {
  RGraphic *a = RGraphicCreateEmpty(3), *b = RGraphicCreateEmpty(3), *c = RGraphicCreateEmpty(3);
  RGraphicAddToList(rc, a, 0);
  RGraphicAddToList(rc, b, 0);
  RGraphicAddToList(rc, c, 1);
  EXPECT_EQ(rc->m_pRG_First, a);
  EXPECT_EQ(a->m_pNext, b);
  EXPECT_EQ(rc->m_pRG_First2D, c);
  {
    Messages m;
    RGraphicAddToList(rc, a, 0);
    EXPECT_TRUE(Messages::Warned("already in the 3D list"));
    RGraphicRemoveFromList(rc, c, 0);
    EXPECT_TRUE(Messages::Warned("not in the 3D list"));
  }
  EXPECT_EQ(Count(false), 2);
  RGraphicRemoveFromList(rc, a, 0);
  EXPECT_EQ(rc->m_pRG_First, b);
  RGraphicDestroy(a);
  RGraphicDelete(rc, c, 1);
  EXPECT_EQ(rc->m_pRG_First2D, nullptr);
  // b stays in the list; the context frees it.
}

TEST_F(Graphics, BoxHasThirtySixVerticesWithinItsSides) {
  MeMatrix4 tm;
  MeMatrix4TMMakeIdentity(tm);
  RGraphic *g = RGraphicBoxCreate(rc, 2, 4, 6, kRed, tm);
  ExpectWellFormed(g);
  EXPECT_EQ(g->m_pObject->m_nNumVertices, 36);
  EXPECT_EQ(g->m_pLWMatrix, tm);
  for (int i = 0; i < 36; ++i) {
    EXPECT_EQ(std::fabs(g->m_pVertices[i].m_X), 1);
    EXPECT_EQ(std::fabs(g->m_pVertices[i].m_Y), 2);
    EXPECT_EQ(std::fabs(g->m_pVertices[i].m_Z), 3);
  }
  EXPECT_EQ(rc->m_pRG_First, g);
  float c[4];
  RGraphicGetColor(g, c);
  EXPECT_EQ(c[0], 1);
  EXPECT_EQ(c[1], 0);
}

TEST_F(Graphics, SphereVerticesLieOnTheSphere) {
  RGraphic *g = RGraphicSphereCreate(rc, 1.5, kRed, nullptr);
  ExpectWellFormed(g);
  for (int i = 0; i < g->m_pObject->m_nNumVertices; ++i) {
    const RObjectVertex &v = g->m_pVertices[i];
    EXPECT_NEAR(std::sqrt(v.m_X * v.m_X + v.m_Y * v.m_Y + v.m_Z * v.m_Z), 1.5, 1e-5);
  }
}

TEST_F(Graphics, CylinderConeFrustumTorusStayInTheirBounds) {
  RGraphic *cyl = RGraphicCylinderCreate(rc, 0.5, 2, kRed, nullptr);
  ExpectWellFormed(cyl);
  for (int i = 0; i < cyl->m_pObject->m_nNumVertices; ++i) {
    const RObjectVertex &v = cyl->m_pVertices[i];
    EXPECT_LE(std::hypot(v.m_X, v.m_Y), 0.5 + 1e-6);
    EXPECT_LE(std::fabs(v.m_Z), 1 + 1e-6);
  }
  RGraphic *cone = RGraphicConeCreate(rc, 1, 2, 0.5, kRed, nullptr);
  ExpectWellFormed(cone);
  float zmin = 1e9f, zmax = -1e9f;
  for (int i = 0; i < cone->m_pObject->m_nNumVertices; ++i)
    zmin = std::min(zmin, cone->m_pVertices[i].m_Z), zmax = std::max(zmax, cone->m_pVertices[i].m_Z);
  EXPECT_FLOAT_EQ(zmin, -0.5f);  // base at -lheight
  EXPECT_FLOAT_EQ(zmax, 2.0f);   // apex at uheight
  RGraphic *fr = RGraphicFrustumCreate(rc, 1, 0.5, -1, 1, 6, kRed, nullptr);
  ExpectWellFormed(fr);
  EXPECT_EQ(fr->m_pObject->m_nNumVertices, 6 * 12);
  RGraphic *torus = RGraphicTorusCreate(rc, 1, 2, kRed, nullptr);
  ExpectWellFormed(torus);
  for (int i = 0; i < torus->m_pObject->m_nNumVertices; ++i) {
    const RObjectVertex &v = torus->m_pVertices[i];
    const double rho = std::hypot(v.m_X, v.m_Y);  // distance from the axis
    EXPECT_GE(rho, 1 - 1e-5);
    EXPECT_LE(rho, 2 + 1e-5);
    EXPECT_NEAR(std::hypot(rho - 1.5, double(v.m_Z)), 0.5, 1e-5);  // on the tube
  }
  EXPECT_EQ(Count(false), 4);
}

TEST_F(Graphics, SquareGroundPlaneAndRectangle) {
  RGraphic *sq = RGraphicSquareCreate(rc, 2, kRed, nullptr);
  ExpectWellFormed(sq);
  EXPECT_EQ(sq->m_pObject->m_nNumVertices, 6);
  EXPECT_EQ(sq->m_pVertices[0].m_NZ, 1);
  RGraphic *gp = RGraphicGroundPlaneCreate(rc, 12, 3, kRed, -1);
  ExpectWellFormed(gp);
  EXPECT_EQ(gp->m_pObject->m_nNumVertices, 54);
  for (int i = 0; i < 54; ++i) {
    EXPECT_EQ(gp->m_pVertices[i].m_Y, -1);
    EXPECT_LE(std::fabs(gp->m_pVertices[i].m_X), 6);
    EXPECT_EQ(gp->m_pVertices[i].m_NY, 1);
  }
  RGraphic *r = RGraphic2DRectangleCreate(rc, 10, 20, 30, 40, kRed);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(rc->m_pRG_First2D, r);
  float xmin = 1e9f, xmax = -1e9f, ymin = 1e9f, ymax = -1e9f;
  for (int i = 0; i < 6; ++i) {
    xmin = std::min(xmin, r->m_pVertices[i].m_X), xmax = std::max(xmax, r->m_pVertices[i].m_X);
    ymin = std::min(ymin, r->m_pVertices[i].m_Y), ymax = std::max(ymax, r->m_pVertices[i].m_Y);
  }
  EXPECT_EQ(xmin, 10);
  EXPECT_EQ(xmax, 40);
  EXPECT_EQ(ymin, 20);
  EXPECT_EQ(ymax, 60);
}

TEST_F(Graphics, LineMovesItsEndsAndRefusesOtherGraphics) {
  AcmeReal o[3] = {0, 0, 0}, e[3] = {1, 2, 3};
  RGraphic *line = RGraphicLineCreate(rc, o, e, kRed, nullptr);
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->m_pObject->m_bIsWireFrame, 1);
  AcmeReal o2[3] = {-1, 0, 0}, e2[3] = {4, 5, 6};
  EXPECT_EQ(RGraphicLineMoveEnds(line, o2, e2), 0);
  EXPECT_EQ(line->m_pVertices[0].m_X, -1);
  EXPECT_EQ(line->m_pVertices[1].m_Z, 6);
  EXPECT_EQ(line->m_pVertices[2].m_Y, 5);
  Messages m;
  RGraphic *box = RGraphicBoxCreate(rc, 1, 1, 1, kRed, nullptr);
  EXPECT_EQ(RGraphicLineMoveEnds(box, o2, e2), 1);
  EXPECT_TRUE(Messages::Warned("not a line"));
  EXPECT_EQ(RGraphicLineMoveEnds(nullptr, o2, e2), 1);
}

TEST_F(Graphics, NativeLinesJoinTheContext) {
  const AcmeReal s[3] = {0, 0, 0}, e[3] = {1, 1, 1}, c[4] = {1, 1, 0, 1};
  RNativeLine *l = RNLineCreate(rc, s, e, c, nullptr);
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(rc->m_pNL_First, l);
  const AcmeReal s2[3] = {2, 2, 2}, e2[3] = {3, 3, 3};
  RNLineMoveEnds(l, s2, e2);
  EXPECT_EQ(l->m_Start[0], 2);
  EXPECT_EQ(l->m_End[2], 3);
  EXPECT_EQ(l->m_Color[1], 1);
}

TEST_F(Graphics, TextMakesOneQuadPerVisibleCharacter) {
  const float white[4] = {1, 1, 1, 1};
  char text[] = "ab c\nd";
  RGraphic *t = RGraphicTextCreate(rc, text, 5, 7, white);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->m_pObject->m_nNumVertices, 4 * 6);
  EXPECT_EQ(rc->m_pRG_First2D, t);
  EXPECT_EQ(t->m_pObject->m_nTextureID, R_MAX_TEXTURES);  // the built-in font
  EXPECT_EQ(t->m_pVertices[0].m_X, 5);
  EXPECT_EQ(t->m_pVertices[0].m_Y, 7);
  const RObjectVertex &d = t->m_pVertices[18];  // 'd' starts line 2
  EXPECT_EQ(d.m_X, 5);
  EXPECT_EQ(d.m_Y, 7 + R_TEXT_CHAR_HEIGHT);
  EXPECT_GT(t->m_pVertices[6].m_X, 5);  // 'b' after 'a'
}

TEST_F(Graphics, BadSizesGiveNullWithAWarning) {
  Messages m;
  EXPECT_EQ(RGraphicSphereCreate(rc, NAN, kRed, nullptr), nullptr);
  EXPECT_EQ(RGraphicBoxCreate(rc, -1, 1, 1, kRed, nullptr), nullptr);
  EXPECT_EQ(RGraphicFrustumCreate(rc, 1, 1, 0, 1, 2, kRed, nullptr), nullptr);
  EXPECT_EQ(RGraphicTorusCreate(rc, 2, 1, kRed, nullptr), nullptr);
  EXPECT_EQ(RGraphicGroundPlaneCreate(rc, 10, 0, kRed, 0), nullptr);
  EXPECT_EQ(RGraphicCylinderCreate(nullptr, 1, 1, kRed, nullptr), nullptr);
  EXPECT_EQ(RGraphicTextCreate(rc, nullptr, 0, 0, kRed), nullptr);
  EXPECT_EQ(Count(false), 0);
  EXPECT_GE(Messages::Warnings().size(), 7u) << Messages::All();
}

RObjectVertex StripVertex(float x, float y) {
  RObjectVertex v{};
  v.m_X = x, v.m_Y = y, v.m_NZ = 1;
  return v;
}

TEST(StripConversion, KeepsTheWindingOfEveryTriangleAndGrows) {
  // Strip 0: 5 vertices zig-zagging along x (3 triangles, all facing +z);
  // strip 1: 3 vertices (1 triangle).
  RObjectVertex v[8] = {StripVertex(0, 0), StripVertex(0, 1), StripVertex(1, 0), StripVertex(1, 1),
                        StripVertex(2, 0), StripVertex(5, 0), StripVertex(6, 0), StripVertex(5, 1)};
  int size[2] = {5, 3}, start[2] = {0, 5};
  RGraphic *g = RGraphicCreateEmpty(3);
  RConvertTriStripToTriList(g, v, size, start, 2);
  ASSERT_EQ(g->m_pObject->m_nNumVertices, 12);
  EXPECT_GE(g->m_nMaxNumVertices, 12);
  // (s0 s1 s2), (s2 s1 s3), (s2 s3 s4), then (t0 t1 t2)
  const float expectX[12] = {0, 0, 1, 1, 0, 1, 1, 1, 2, 5, 6, 5};
  const float expectY[12] = {0, 1, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(g->m_pVertices[i].m_X, expectX[i]) << i;
    EXPECT_EQ(g->m_pVertices[i].m_Y, expectY[i]) << i;
  }
  // Strip 0 winds clockwise seen from +z, so all its triangles do.
  for (int t = 0; t < 3; ++t) {
    const RObjectVertex *a = g->m_pVertices + 3 * t;
    const float cz = (a[1].m_X - a[0].m_X) * (a[2].m_Y - a[0].m_Y) - (a[1].m_Y - a[0].m_Y) * (a[2].m_X - a[0].m_X);
    EXPECT_LT(cz, 0) << "triangle " << t;
  }
  RGraphicDestroy(g);
}

}  // namespace
