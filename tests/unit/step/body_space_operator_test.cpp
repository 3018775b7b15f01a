// The body-space operator (body_space_operator.h) on random problems with
// the step's structure (rows on two bodies, rows on one body and the
// world): its product is the sum that header documents, bit for bit, with
// M^-1 applied to each body's sum as problem.h's SideMinvJt applies it and
// the rows' J read in problem.h's layout; absTimesMax bounds every row of
// |A| |x|, A formed entry by entry; and its
// finiteness verdict refuses a non-finite or huge J or softness on a side
// with a body, and ignores J on a side without one (no reader uses it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "arena.h"
#include "body_space_operator.h"
#include "problem.h"

namespace {

using karma::mdt::BodySpaceOperator;
using karma::mdt::BodySpaceProblem;
using karma::mdt::kRowValues;
using karma::mdt::kSideValues;
using karma::mdt::SideMinvJt;
using karma::mdt::StepArena;

// The operator's destructor is protected: Kea holds it through its base.
class Operator final : public BodySpaceOperator {
 public:
  using BodySpaceOperator::BodySpaceOperator;
  void assemble() const override {}
};

// A problem's arrays, owned; problem() views them.
struct Arrays {
  int bodies = 0, rows = 0;
  std::vector<MeReal> invMass, invInertia, J, rhs, softness, lo, hi, mu, warm;
  std::vector<int> body0, body1, friction;

  BodySpaceProblem problem() const {
    BodySpaceProblem p;
    p.bodyCount = bodies;
    p.rowCount = rows;
    p.invMass = invMass;
    p.invInertia = invInertia;
    p.body0 = body0;
    p.body1 = body1;
    p.J = J;
    p.rhs = rhs;
    p.softness = softness;
    p.lo = lo;
    p.hi = hi;
    p.friction = friction;
    p.mu = mu;
    p.warm = warm;
    return p;
  }
};

// `rows` rows on `bodies` bodies: every row on a random body, a third of
// them against the world (body1 = -1, whose J is NaN: any read of it
// shows), the rest on a second, different body.
Arrays RandomProblem(std::mt19937 &rng, int bodies, int rows) {
  std::uniform_real_distribution<double> u(-1, 1), positive(0.1, 2);
  std::uniform_int_distribution<int> body(0, bodies - 1), third(0, 2);
  Arrays a;
  a.bodies = bodies;
  a.rows = rows;
  for (int b = 0; b < bodies; ++b) {
    a.invMass.push_back((MeReal)positive(rng));
    for (int k = 0; k < 9; ++k) a.invInertia.push_back((MeReal)u(rng));
  }
  a.J.assign((size_t)rows * kRowValues, 0);
  for (int r = 0; r < rows; ++r) {
    const int b0 = body(rng);
    int b1 = third(rng) == 0 ? -1 : body(rng);
    if (b1 == b0) b1 = (b0 + 1) % bodies;
    a.body0.push_back(b0);
    a.body1.push_back(b1);
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 6; ++c)
        a.J[(size_t)r * kRowValues + (size_t)side * kSideValues + (size_t)c] =
            side == 1 && b1 < 0 ? std::numeric_limits<MeReal>::quiet_NaN() : (MeReal)u(rng);
    a.softness.push_back((MeReal)(0.01 * positive(rng)));
  }
  a.rhs.assign((size_t)rows, 0);
  a.lo.assign((size_t)rows, -1);
  a.hi.assign((size_t)rows, 1);
  a.mu.assign((size_t)rows, 0);
  a.warm.assign((size_t)rows, 0);
  a.friction.assign((size_t)rows, -1);
  return a;
}

const MeReal *SideJ(const Arrays &a, int r, int side) {
  return &a.J[(size_t)r * kRowValues + (size_t)side * kSideValues];
}

int BodyOf(const Arrays &a, int r, int side) { return side == 0 ? a.body0[(size_t)r] : a.body1[(size_t)r]; }

// The product as body_space_operator.h defines it, in scalars: g_b summed
// over b's rows in ascending order, u_b = M_b^-1 g_b as SideMinvJt
// multiplies, each row's six-term dots as (linear) + (angular), side 0
// then side 1, then + softness x.
std::vector<MeReal> DocumentedProduct(const Arrays &a, const std::vector<MeReal> &x) {
  std::vector<MeReal> g((size_t)a.bodies * 6, 0), u((size_t)a.bodies * 6);
  for (int r = 0; r < a.rows; ++r)
    for (int side = 0; side < 2; ++side) {
      const int b = BodyOf(a, r, side);
      if (b < 0) continue;
      for (int c = 0; c < 6; ++c) g[(size_t)b * 6 + (size_t)c] += SideJ(a, r, side)[c] * x[(size_t)r];
    }
  for (int b = 0; b < a.bodies; ++b)
    SideMinvJt(a.invMass[(size_t)b], &a.invInertia[(size_t)b * 9], &g[(size_t)b * 6], &u[(size_t)b * 6]);
  std::vector<MeReal> y((size_t)a.rows);
  for (int r = 0; r < a.rows; ++r) {
    MeReal sum = 0;
    for (int side = 0; side < 2; ++side) {
      const int b = BodyOf(a, r, side);
      if (b < 0) continue;
      const MeReal *J = SideJ(a, r, side), *ub = &u[(size_t)b * 6];
      const MeReal d = (J[0] * ub[0] + J[1] * ub[1] + J[2] * ub[2]) + (J[3] * ub[3] + J[4] * ub[4] + J[5] * ub[5]);
      sum = side == 0 ? d : sum + d;
    }
    y[(size_t)r] = sum + a.softness[(size_t)r] * x[(size_t)r];
  }
  return y;
}

// absTimesMax as body_space_operator.h defines it, in scalars: the
// product's sums on |J|, |x|, |M^-1| (SideMinvJt on |invMass|, |I^-1|), then
// + |softness x|, the largest over the rows.
MeReal DocumentedAbsTimesMax(const Arrays &a, const std::vector<MeReal> &x) {
  std::vector<MeReal> g((size_t)a.bodies * 6, 0), u((size_t)a.bodies * 6);
  for (int r = 0; r < a.rows; ++r)
    for (int side = 0; side < 2; ++side) {
      const int b = BodyOf(a, r, side);
      if (b < 0) continue;
      for (int c = 0; c < 6; ++c)
        g[(size_t)b * 6 + (size_t)c] += std::fabs(SideJ(a, r, side)[c]) * std::fabs(x[(size_t)r]);
    }
  for (int b = 0; b < a.bodies; ++b) {
    MeReal inertia[9];
    for (int k = 0; k < 9; ++k) inertia[k] = std::fabs(a.invInertia[(size_t)b * 9 + (size_t)k]);
    SideMinvJt(std::fabs(a.invMass[(size_t)b]), inertia, &g[(size_t)b * 6], &u[(size_t)b * 6]);
  }
  MeReal largest = 0;
  for (int r = 0; r < a.rows; ++r) {
    MeReal sum = 0;
    for (int side = 0; side < 2; ++side) {
      const int b = BodyOf(a, r, side);
      if (b < 0) continue;
      MeReal t[6];
      for (int c = 0; c < 6; ++c) t[c] = std::fabs(SideJ(a, r, side)[c]) * u[(size_t)b * 6 + (size_t)c];
      const MeReal d = (t[0] + t[1] + t[2]) + (t[3] + t[4] + t[5]);
      sum = side == 0 ? d : sum + d;
    }
    largest = std::max(largest, sum + std::fabs(a.softness[(size_t)r] * x[(size_t)r]));
  }
  return largest;
}

// sum_j |A_ij| |x_j| of row i, with A = J M^-1 J^T + diag(softness) formed
// entry by entry in double precision.
double AbsProductRow(const Arrays &a, const std::vector<MeReal> &x, int i) {
  {
    double sum = std::fabs((double)a.softness[(size_t)i] * (double)x[(size_t)i]);
    for (int j = 0; j < a.rows; ++j) {
      double entry = 0;
      for (int si = 0; si < 2; ++si)
        for (int sj = 0; sj < 2; ++sj) {
          const int b = BodyOf(a, i, si);
          if (b < 0 || b != BodyOf(a, j, sj)) continue;
          MeReal mj[6];
          SideMinvJt(a.invMass[(size_t)b], &a.invInertia[(size_t)b * 9], SideJ(a, j, sj), mj);
          for (int c = 0; c < 6; ++c) entry += (double)SideJ(a, i, si)[c] * (double)mj[c];
        }
      sum += std::fabs(entry) * std::fabs((double)x[(size_t)j]);
    }
    return sum;
  }
}

bool SameBits(MeReal a, MeReal b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool EntriesFinite(const Arrays &a) {
  StepArena arena;
  const BodySpaceProblem p = a.problem();
  const Operator op(p, arena);
  return op.entriesFinite();
}

// EntriesFinite with the caller's bounds given (problem.h's largestJ,
// largestSoftness).
bool EntriesFiniteGiven(const Arrays &a, MeReal largestJ, MeReal largestSoftness) {
  StepArena arena;
  BodySpaceProblem p = a.problem();
  p.largestJ = largestJ;
  p.largestSoftness = largestSoftness;
  const Operator op(p, arena);
  return op.entriesFinite();
}

}  // namespace

TEST(BodySpaceOperator, TheProductIsTheDocumentedSumBitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 50; ++trial) {
    const Arrays a = RandomProblem(rng, 2 + trial % 7, 1 + trial % 23);
    std::vector<MeReal> x((size_t)a.rows);
    for (MeReal &v : x) v = (MeReal)u(rng);
    const std::vector<MeReal> expected = DocumentedProduct(a, x);

    StepArena arena;
    const BodySpaceProblem p = a.problem();
    const Operator op(p, arena);
    std::vector<MeReal> y((size_t)a.rows);
    op.times(nullptr, (size_t)a.rows, x.data(), y.data());
    for (int r = 0; r < a.rows; ++r)
      EXPECT_TRUE(SameBits(y[(size_t)r], expected[(size_t)r]))
          << "trial " << trial << " row " << r << ": " << y[(size_t)r] << " vs " << expected[(size_t)r];

    // Every other row, by index: the same values.
    std::vector<int> some;
    for (int r = a.rows - 1; r >= 0; r -= 2) some.push_back(r);
    std::vector<MeReal> ySome(some.size());
    op.times(some.data(), some.size(), x.data(), ySome.data());
    for (size_t k = 0; k < some.size(); ++k) EXPECT_TRUE(SameBits(ySome[k], expected[(size_t)some[k]])) << trial;

    EXPECT_TRUE(SameBits(op.absTimesMax(nullptr, (size_t)a.rows, x.data()), DocumentedAbsTimesMax(a, x))) << trial;

    // absTimesMax of each row alone bounds that row of |A| |x| (up to its
    // own rounding, a few units in the last place), hence of the product.
    for (int r = 0; r < a.rows; ++r) {
      const double bound = op.absTimesMax(&r, 1, x.data());
      EXPECT_GE(bound * (1 + 16 * (double)ME_REAL_EPSILON), AbsProductRow(a, x, r)) << trial << " row " << r;
      EXPECT_GE(bound, std::fabs(y[(size_t)r])) << trial << " row " << r;
    }
    EXPECT_TRUE(op.entriesFinite()) << trial;

    // Both in one pass: the same bits as the two calls.
    std::vector<MeReal> yBoth((size_t)a.rows);
    const MeReal both = op.timesAndAbsTimesMax(nullptr, (size_t)a.rows, x.data(), yBoth.data());
    EXPECT_TRUE(SameBits(both, op.absTimesMax(nullptr, (size_t)a.rows, x.data()))) << trial;
    for (int r = 0; r < a.rows; ++r) EXPECT_TRUE(SameBits(yBoth[(size_t)r], y[(size_t)r])) << trial << " row " << r;
    std::vector<MeReal> ySomeBoth(some.size());
    const MeReal someBoth = op.timesAndAbsTimesMax(some.data(), some.size(), x.data(), ySomeBoth.data());
    EXPECT_TRUE(SameBits(someBoth, op.absTimesMax(some.data(), some.size(), x.data()))) << trial;
    for (size_t k = 0; k < some.size(); ++k) EXPECT_TRUE(SameBits(ySomeBoth[k], ySome[k])) << trial;
  }
}

// The fused call on the values where the two computations could part: x
// with NaN, infinities and -0, and rows with no body on side 0.
TEST(BodySpaceOperator, BothInOnePassAreTheTwoCallsOnSpecialValues) {
  std::mt19937 rng(23);
  Arrays a = RandomProblem(rng, 5, 17);
  for (int r : {2, 9}) {  // side 0 without a body: its J is NaN, never read
    a.body0[(size_t)r] = -1;
    for (int c = 0; c < 6; ++c) a.J[(size_t)r * kRowValues + (size_t)c] = std::numeric_limits<MeReal>::quiet_NaN();
  }
  const MeReal inf = std::numeric_limits<MeReal>::infinity();
  const std::vector<std::vector<MeReal>> specials = {
      {-MeReal(0), MeReal(0), -MeReal(0)},  // the rest of x is random
      {std::numeric_limits<MeReal>::quiet_NaN()},
      {inf, -inf},
      {std::numeric_limits<MeReal>::max(), -std::numeric_limits<MeReal>::denorm_min()}};
  std::uniform_real_distribution<double> u(-2, 2);
  for (const std::vector<MeReal> &head : specials) {
    std::vector<MeReal> x((size_t)a.rows);
    for (MeReal &v : x) v = (MeReal)u(rng);
    for (size_t k = 0; k < head.size(); ++k) x[3 * k + 1] = head[k];
    StepArena arena;
    const BodySpaceProblem p = a.problem();
    const Operator op(p, arena);
    std::vector<MeReal> y((size_t)a.rows), yBoth((size_t)a.rows);
    op.times(nullptr, (size_t)a.rows, x.data(), y.data());
    const MeReal separate = op.absTimesMax(nullptr, (size_t)a.rows, x.data());
    const MeReal both = op.timesAndAbsTimesMax(nullptr, (size_t)a.rows, x.data(), yBoth.data());
    EXPECT_TRUE(SameBits(both, separate)) << both << " vs " << separate;
    for (int r = 0; r < a.rows; ++r) EXPECT_TRUE(SameBits(yBoth[(size_t)r], y[(size_t)r])) << "row " << r;
  }
  // With finite x, the rows without a body on side 0 read none of its NaN.
  std::vector<MeReal> x((size_t)a.rows, (MeReal)0.5), y((size_t)a.rows);
  StepArena arena;
  const BodySpaceProblem p = a.problem();
  const Operator op(p, arena);
  op.times(nullptr, (size_t)a.rows, x.data(), y.data());
  for (int r = 0; r < a.rows; ++r) EXPECT_TRUE(std::isfinite(y[(size_t)r])) << "row " << r;
  EXPECT_TRUE(std::isfinite(op.timesAndAbsTimesMax(nullptr, (size_t)a.rows, x.data(), y.data())));
}

TEST(BodySpaceOperator, EntriesAreFiniteOnlyWhenEveryReadInputIsFiniteAndBounded) {
  std::mt19937 rng(5);
  const Arrays base = RandomProblem(rng, 4, 12);
  ASSERT_TRUE(EntriesFinite(base));
  int worldRow = -1, bodyRow = -1;
  for (int r = 0; r < base.rows; ++r) (base.body1[(size_t)r] < 0 ? worldRow : bodyRow) = r;
  ASSERT_GE(worldRow, 0);
  ASSERT_GE(bodyRow, 0);
  auto at = [](int r, int side, int c) { return (size_t)r * kRowValues + (size_t)side * kSideValues + (size_t)c; };
  const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
  const MeReal inf = std::numeric_limits<MeReal>::infinity();

  for (const MeReal bad : {nan, inf, -inf}) {
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 6; ++c) {
        Arrays a = base;
        a.J[at(bodyRow, side, c)] = bad;
        EXPECT_FALSE(EntriesFinite(a)) << "side " << side << " component " << c;
      }
    Arrays world = base;  // the side without a body is never read
    for (int c = 0; c < 6; ++c) world.J[at(worldRow, 1, c)] = bad;
    EXPECT_TRUE(EntriesFinite(world));
    Arrays soft = base;
    soft.softness[(size_t)bodyRow] = bad;
    EXPECT_FALSE(EntriesFinite(soft));
    Arrays mass = base;
    mass.invMass[0] = bad;
    EXPECT_FALSE(EntriesFinite(mass));
  }
  // Finite but so large that an entry of A could overflow: 12 |J|^2 w
  // beyond half the range.
  Arrays huge = base;
  huge.J[at(bodyRow, 0, 4)] = -std::sqrt(std::numeric_limits<MeReal>::max());
  EXPECT_FALSE(EntriesFinite(huge));
}

// A caller that scanned the rows gives their largest |J| and softness
// (problem.h's largestJ, largestSoftness) and the operator takes them
// instead of scanning: the same verdict at the true largest values, or at
// any larger bounds that keep the entries within range; a bound too large
// for that, or NaN, says no. (Given one and not the other, the operator
// scans both.)
TEST(BodySpaceOperator, GivenLargestValuesStandForTheScan) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    const Arrays a = RandomProblem(rng, 2 + trial % 5, 3 + trial % 11);
    MeReal largest = 0;
    for (int r = 0; r < a.rows; ++r)
      for (int side = 0; side < 2; ++side) {
        if ((side == 0 ? a.body0 : a.body1)[(size_t)r] < 0) continue;
        for (size_t c = 0; c < 6; ++c)
          largest = std::max(largest, std::fabs(a.J[(size_t)r * kRowValues + (size_t)side * kSideValues + c]));
      }
    MeReal largestSoftness = 0;
    for (MeReal s : a.softness) largestSoftness = std::max(largestSoftness, std::fabs(s));
    ASSERT_TRUE(EntriesFinite(a)) << trial;
    for (MeReal given : {largest, 2 * largest, MeReal(1e6)})
      EXPECT_TRUE(EntriesFiniteGiven(a, given, largestSoftness)) << trial << " given " << given;
    for (MeReal given : {largestSoftness, MeReal(1e6)})
      EXPECT_TRUE(EntriesFiniteGiven(a, largest, given)) << trial << " given softness " << given;
    const MeReal max = std::numeric_limits<MeReal>::max(), inf = std::numeric_limits<MeReal>::infinity();
    const MeReal nan = std::numeric_limits<MeReal>::quiet_NaN();
    for (MeReal given : {std::sqrt(max), inf, nan})
      EXPECT_FALSE(EntriesFiniteGiven(a, given, largestSoftness)) << trial << " given " << given;
    for (MeReal given : {max, inf, nan})
      EXPECT_FALSE(EntriesFiniteGiven(a, largest, given)) << trial << " given softness " << given;
  }
}
