// kea_pivoting_test.cpp: the active-set method's cycle detection on a
// problem recorded from a scene.
//
// data/pile1000_step15_box.txt is the LCP of one cube landing on the ground
// in pile1000 (12 rows: four contacts, a normal and two box-friction rows
// each; single precision; no warm start), recorded at step 15 with the
// release build. Its inner pivoting reaches a new fewest count of
// infeasible rows by single pivots, takes block steps from there, and then
// single-pivots into a set it had tried before that new low. The method
// used to call that a cycle and stop (residual 0.287); from the new low the
// next sets differ, and it is solved. A set repeated within one run of
// single pivots is still a cycle (KeaSparse.CycleIsDetected,
// KeaLcp.CycleInTheActiveSetIsDetected).
//
// File format: "n nnz warm", the n + 1 row starts, nnz lines "col value",
// then n lines "b lo hi findex mu warm"; values in C hex floats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kea_lcp.h"

using namespace karma::kea;

namespace {

struct Recorded {
  int n = 0;
  bool warm = false, friction = false;
  std::vector<int> rowStart, col, findex;
  std::vector<MeReal> val, b, lo, hi, mu, warmStart;

  SparseLcpProblem problem() const {
    SparseLcpProblem p{n, rowStart, col, val, b, lo, hi, {}, {}};
    if (friction) {
      p.findex = findex;
      p.mu = mu;
    }
    return p;
  }
};

bool Load(const std::string &path, Recorded &r) {
  FILE *f = std::fopen(path.c_str(), "r");
  if (!f) return false;
  int nnz = 0, warm = 0;
  bool ok = std::fscanf(f, "%d %d %d", &r.n, &nnz, &warm) == 3 && r.n > 0 && nnz > 0;
  r.warm = warm != 0;
  if (ok) {
    r.rowStart.resize((size_t)r.n + 1);
    for (int &s : r.rowStart) ok = ok && std::fscanf(f, "%d", &s) == 1;
  }
  for (int k = 0; ok && k < nnz; ++k) {
    int c = 0;
    double v = 0;
    ok = std::fscanf(f, "%d %la", &c, &v) == 2;
    r.col.push_back(c);
    r.val.push_back((MeReal)v);
  }
  for (int i = 0; ok && i < r.n; ++i) {
    double b, lo, hi, mu, w;
    int fi = -1;
    ok = std::fscanf(f, "%la %la %la %d %la %la", &b, &lo, &hi, &fi, &mu, &w) == 6;
    r.b.push_back((MeReal)b);
    r.lo.push_back((MeReal)lo);
    r.hi.push_back((MeReal)hi);
    r.findex.push_back(fi);
    r.mu.push_back((MeReal)mu);
    r.warmStart.push_back((MeReal)w);
    r.friction = r.friction || fi >= 0;
  }
  std::fclose(f);
  return ok;
}

// The contract's natural-map residual, max_i |lambda_i - clamp(lambda_i -
// w_i, lo_i, hi_i)|, with w = A lambda - b and the friction bounds from
// lambda itself, computed here in double from the file's data.
double NaturalResidual(const Recorded &r, const std::vector<MeReal> &lambda) {
  double worst = 0;
  for (int i = 0; i < r.n; ++i) {
    double w = -(double)r.b[(size_t)i];
    for (int k = r.rowStart[(size_t)i]; k < r.rowStart[(size_t)i + 1]; ++k)
      w += (double)r.val[(size_t)k] * (double)lambda[(size_t)r.col[(size_t)k]];
    double lo = r.lo[(size_t)i], hi = r.hi[(size_t)i];
    if (const int j = r.findex[(size_t)i]; j >= 0) {
      hi = (double)r.mu[(size_t)i] * std::max(0.0, (double)lambda[(size_t)j]);
      lo = -hi;
    }
    const double l = lambda[(size_t)i];
    worst = std::max(worst, std::fabs(l - std::clamp(l - w, lo, hi)));
  }
  return worst;
}

double BiggestB(const Recorded &r) {
  double biggest = 0;
  for (MeReal v : r.b) biggest = std::max(biggest, std::fabs((double)v));
  return biggest;
}

}  // namespace

TEST(KeaPivoting, ASetTriedBeforeANewFewestInfeasibleIsNotACycle) {
  Recorded r;
  ASSERT_TRUE(Load(std::string(KEA_TEST_DATA) + "/pile1000_step15_box.txt", r));
  ASSERT_EQ(r.n, 12);
  // As Mdt's exact partition solver calls it (solver_kea.cpp).
  KeaOptions opt;
  opt.factorMemory = KeaFactorMemory::WhenCheaper;
  opt.trustedStructure = true;
  KeaWorkspace *workspace = KeaWorkspaceCreate();
  KeaResult result;
  KeaSolveSparse(r.problem(), opt, *workspace, result);
  KeaWorkspaceDestroy(workspace);
  EXPECT_EQ(result.status, KeaStatus::Solved) << KeaStatusName(result.status);
  const double tolerance = sizeof(MeReal) == 4 ? 1e-4 : 1e-10;
  const double threshold = tolerance * (1 + BiggestB(r));
  // Kea's own residual, and the one computed here from the data: the
  // double build solves the file's (single-precision) values more closely.
  EXPECT_LE(result.residual, threshold);
  EXPECT_LE(NaturalResidual(r, result.lambda), 2 * std::max(threshold, 1e-5));
  // The ground pushes: no normal impulse pulls, and together they hold the cube.
  double normalSum = 0;
  for (int i = 0; i < r.n; ++i) {
    if (r.findex[(size_t)i] >= 0) continue;
    EXPECT_GE(result.lambda[(size_t)i], 0) << "normal row " << i;
    normalSum += result.lambda[(size_t)i];
  }
  EXPECT_GT(normalSum, 1);
}
