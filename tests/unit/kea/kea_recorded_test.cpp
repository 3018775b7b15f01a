// kea_recorded_test.cpp: the active-set method on LCPs recorded from scenes
// (data/, single precision, release build), each the regression test of a
// fix to the method.
//
// pile1000_step15_box.txt: one cube landing on the ground in pile1000 at
// step 15 (12 rows: four contacts, a normal and two box-friction rows each;
// no warm start). Its inner pivoting reaches a new fewest count of
// infeasible rows by single pivots, takes block steps from there, and then
// single-pivots into a set it had tried before that new low. The method
// used to call that a cycle and stop (residual 0.287); from the new low the
// next sets differ, and it is solved. A set repeated within one run of
// single pivots is still a cycle (KeaSparse.CycleIsDetected,
// KeaLcp.CycleInTheActiveSetIsDetected).
//
// ballman_hq_doll_69rows.txt: the Ballman tutorial's doll with Coulomb
// (normal-force) friction (69 rows: 27 joint rows, 16 contacts, 26 friction
// rows; warm-started). Its friction fixed point flips for ten rounds, and
// the relaxed update that follows turned every infinite bound into NaN
// (inf + (inf - inf) / 2), so a contact at zero whose upper bound was NaN
// could never leave it: the method ended on a "fixed point" with residual
// 13.6 and reported its best iterate (1.02) as IterationLimit. It is now
// solved in 58 friction rounds.
//
// rainbowchain_update_48rows.txt: the RainbowChain tutorial's chain (48
// rows, no friction; warm-started). Its three pivots are served by
// Schur-complement updates of its first factorisation
// (kea_schur_update.h), whose base is ill-conditioned enough that an
// update's answer cancels digits: unrefined, the free rows' residual is
// 0.0015 and the solve ends on a consistent set it cannot call solved.
// Refined from that residual (SparseBackend::refine) it is solved. In
// single precision the test fails without the refinement; the double
// build solves the file's values without it.
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

// Solves the recorded problem as Mdt's exact partition solver does
// (solver_kea.cpp) and checks the contract: solved, Kea's residual and the
// one computed here within the threshold, no normal impulse pulling.
void ExpectSolved(const char *file, int rows, KeaResult *out = nullptr) {
  Recorded r;
  ASSERT_TRUE(Load(std::string(KEA_TEST_DATA) + "/" + file, r)) << file;
  ASSERT_EQ(r.n, rows);
  KeaOptions opt;
  opt.factorMemory = KeaFactorMemory::WhenCheaper;
  opt.trustedStructure = true;
  if (r.warm) opt.warmStart = r.warmStart;
  KeaWorkspace *workspace = KeaWorkspaceCreate();
  KeaResult result;
  KeaSolveSparse(r.problem(), opt, *workspace, result);
  KeaWorkspaceDestroy(workspace);
  EXPECT_EQ(result.status, KeaStatus::Solved) << KeaStatusName(result.status);
  const double tolerance = sizeof(MeReal) == 4 ? 1e-4 : 1e-10;
  const double threshold = tolerance * (1 + BiggestB(r));
  // The double build solves the file's (single-precision) values more
  // closely; the residual computed here in double is held to the single
  // build's threshold at worst.
  EXPECT_LE(result.residual, threshold);
  EXPECT_LE(NaturalResidual(r, result.lambda), 2 * std::max(threshold, 1e-5));
  double normalSum = 0;
  for (int i = 0; i < r.n; ++i) {
    if (r.findex[(size_t)i] >= 0 || r.lo[(size_t)i] != 0) continue;
    EXPECT_GE(result.lambda[(size_t)i], 0) << "normal row " << i;
    normalSum += result.lambda[(size_t)i];
  }
  EXPECT_GT(normalSum, 0);
  if (out) *out = result;
}

}  // namespace

TEST(KeaRecorded, ASetTriedBeforeANewFewestInfeasibleIsNotACycle) { ExpectSolved("pile1000_step15_box.txt", 12); }

TEST(KeaRecorded, RelaxedFrictionRoundsKeepInfiniteBounds) { ExpectSolved("ballman_hq_doll_69rows.txt", 69); }

TEST(KeaRecorded, AnUpdatedFactorsAnswerIsRefinedToSolved) {
  KeaResult result;
  ExpectSolved("rainbowchain_update_48rows.txt", 48, &result);
  EXPECT_GE(result.factorUpdates, 1);  // the path this problem tests
}
