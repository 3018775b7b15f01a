// body_space_operator.cpp: A = J M^-1 J^T + diag(softness) applied without
// forming it (see body_space_operator.h for the order of every sum).
#include "body_space_operator.h"

#include "lanes16.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace karma::mdt {

namespace {

template <bool Absolute>
MeReal magnitude(MeReal v) {
  return Absolute ? std::fabs(v) : v;
}

constexpr std::size_t kSide = BodySpaceOperator::kSide;

// A row side or a body, kSide values, in 16-byte lanes (lanes16.h: they
// round as the scalar operations do).
using Lanes = platform::Lanes16;
using platform::LoadLanes16;
using platform::StoreLanes16;
constexpr std::size_t kPerLanes = platform::kPerLanes16;
static_assert(kSide % kPerLanes == 0);

template <bool Absolute>
inline Lanes magnitudes(Lanes v) {
  if constexpr (Absolute) {
    for (std::size_t c = 0; c < kPerLanes; ++c) v[c] = std::fabs(v[c]);
  }
  return v;
}

// Four MeReal values in one vector (two 16-byte lanes in double precision):
// element-wise operations, rounded as the scalar ones. Kept local (loaded
// and stored through memcpy, never passed or returned), so that its width
// never reaches a function's calling convention.
using Lanes4 = MeReal __attribute__((vector_size(4 * sizeof(MeReal))));

// A body's world inverse inertia by columns, each padded to four values:
// column c is (I_0c, I_1c, I_2c, 0).
void inertiaColumns(const MeReal invInertia[9], MeReal columns[12]) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) columns[c * 4 + r] = invInertia[r * 3 + c];
    columns[c * 4 + 3] = 0;
  }
}

// M_b^-1 g for a body's gathered sum g (kSide values) into all kSide
// values of `out` (two zeros after the six): the linear part invMass g_lin,
// and the angular part as the sum of the inertia's columns weighted by
// g_ang, ((col0 g_3 + col1 g_4) + col2 g_5), element by element the order
// SideMinvJt (problem.h) sums each row of I g_ang in. With Absolute, the
// same with |invMass| and |I|.
template <bool Absolute>
void applyInverseMass(MeReal invMass, const MeReal columns[12], const MeReal g[kSide], MeReal out[kSide]) {
  Lanes4 v, c0, c1, c2;
  std::memcpy(&v, g, sizeof v);
  std::memcpy(&c0, columns, sizeof c0);
  std::memcpy(&c1, columns + 4, sizeof c1);
  std::memcpy(&c2, columns + 8, sizeof c2);
  if constexpr (Absolute) {
    for (int k = 0; k < 4; ++k) {
      c0[k] = std::fabs(c0[k]);
      c1[k] = std::fabs(c1[k]);
      c2[k] = std::fabs(c2[k]);
    }
  }
  const Lanes4 linear = v * magnitude<Absolute>(invMass);  // its fourth value is overwritten below
  std::memcpy(out, &linear, sizeof linear);
  const Lanes4 angular = (c0 * g[3] + c1 * g[4]) + c2 * g[5];
  std::memcpy(out + 3, &angular, sizeof angular);
  out[6] = out[7] = 0;
}

// The running largest |J| and whether all J seen are finite, over the
// sides with a body, in lanes: the largest and the smallest value seen
// (a side's two padding zeros change neither bound of |J|), and whether
// every value lay within the finite range.
struct LargestJ {
  using Mask = decltype(Lanes{} < Lanes{});
  Lanes top{}, bottom{};
  Mask inRange = top == top;  // all lanes true

  void note(const MeReal *J) {
    const Lanes rangeTop = Lanes{} + ME_REAL_MAX;
    for (std::size_t l = 0; l < kSide; l += kPerLanes) {
      const Lanes v = LoadLanes16(J + l);
      top = v > top ? v : top;  // a NaN leaves both as they were
      bottom = v < bottom ? v : bottom;
      inRange &= (v <= rangeTop) & (-v <= rangeTop);  // false for a NaN or an infinity
    }
  }
  MeReal largest() const {
    MeReal m = 0;
    for (std::size_t c = 0; c < kPerLanes; ++c) m = std::max(m, std::max(top[c], -bottom[c]));
    return m;
  }
  bool finite() const {
    bool all = true;
    for (std::size_t c = 0; c < kPerLanes; ++c) all = all && inRange[c] != 0;
    return all;
  }
};

// The largest |J| over the row sides with a body (`finite`: whether every
// one of their values is finite) and the largest |softness| (`finite`
// cleared by a non-finite one).
struct ScannedRows {
  MeReal largestJ = 0, largestSoftness = 0;
  bool finite = true;
};

ScannedRows scanRows(const BodySpaceProblem &p) {
  ScannedRows scanned;
  LargestJ largestSideJ;
  for (int r = 0; r < p.rowCount; ++r) {
    if (p.body0[(size_t)r] >= 0) largestSideJ.note(sideJ(p, r, 0));
    if (p.body1[(size_t)r] >= 0) largestSideJ.note(sideJ(p, r, 1));
    const MeReal softness = p.softness[(size_t)r];
    scanned.finite = scanned.finite && std::isfinite(softness);
    scanned.largestSoftness = std::max(scanned.largestSoftness, std::fabs(softness));
  }
  scanned.largestJ = largestSideJ.largest();
  scanned.finite = scanned.finite && largestSideJ.finite();
  return scanned;
}

}  // namespace

BodySpaceOperator::BodySpaceOperator(const BodySpaceProblem &p, StepArena &arena) : p_(&p), arena_(&arena) {}

void BodySpaceOperator::prepare() const {
  if (prepared_) return;
  prepared_ = true;
  const BodySpaceProblem &p = *p_;
  for (std::span<MeReal> *sums : {&g_, &u_, &gAbs_, &uAbs_}) *sums = arena_->take<MeReal>((size_t)p.bodyCount * kSide);
  columns_ = arena_->take<MeReal>((size_t)p.bodyCount * 12);
  // |M_b^-1 J^T| <= w_b max|J| per component, w_b = max(1/m_b, 3 max|I_b^-1|).
  MeReal largestW = 0, largestSoftness = 0;
  bool finite = true;  // every input; std::max alone would pass a NaN over
  auto note = [&finite](MeReal &largest, MeReal v) {
    finite &= std::isfinite(v);
    largest = std::max(largest, std::fabs(v));
  };
  for (int b = 0; b < p.bodyCount; ++b) {
    note(largestW, p.invMass[(size_t)b]);
    for (int k = 0; k < 9; ++k) note(largestW, 3 * p.invInertia[(size_t)b * 9 + (size_t)k]);
    inertiaColumns(&p.invInertia[(size_t)b * 9], &columns_[(size_t)b * 12]);
  }
  MeReal largestJ = p.largestJ;
  if (p.largestJ < 0 || p.largestSoftness < 0) {  // not known: scan the rows
    const ScannedRows scanned = scanRows(p);
    largestJ = scanned.largestJ;
    largestSoftness = scanned.largestSoftness;
    finite = finite && scanned.finite;
  } else {
    largestSoftness = p.largestSoftness;
#ifndef NDEBUG
    // The caller's bounds stand for this scan: they must hold (a NaN given
    // refuses the operator below, whatever the scan says).
    const ScannedRows scanned = scanRows(p);
    assert(scanned.finite && !(scanned.largestJ > largestJ) && !(scanned.largestSoftness > largestSoftness));
#endif
  }
  const double entryBound = 12 * (double)largestJ * (double)largestJ * (double)largestW + (double)largestSoftness;
  const double factorBound = (double)largestJ * (double)largestW;  // |M^-1 J^T|
  entriesFinite_ = finite && entryBound <= (double)ME_REAL_MAX / 2 && factorBound <= (double)ME_REAL_MAX / 2;
}

bool BodySpaceOperator::entriesFinite() const {
  prepare();
  return entriesFinite_;
}

// The plain sums (Plain: g_, then u_) and the absolute ones (Absolute:
// gAbs_, then uAbs_), each asked-for kind in one pass over the rows: the
// same terms added in the same order whichever kinds are asked for.
template <bool Plain, bool Absolute>
void BodySpaceOperator::gather(const MeReal *x) const {
  const BodySpaceProblem &p = *p_;
  if constexpr (Plain) std::fill(g_.begin(), g_.end(), MeReal(0));
  if constexpr (Absolute) std::fill(gAbs_.begin(), gAbs_.end(), MeReal(0));
  for (int r = 0; r < p.rowCount; ++r) {
    const MeReal xr = x[r], xrAbs = std::fabs(x[r]);
    const int body[2] = {p.body0[(size_t)r], p.body1[(size_t)r]};
    for (int side = 0; side < 2; ++side) {
      if (body[side] < 0) continue;
      MeReal *g = g_.data() + (size_t)body[side] * kSide, *gAbs = gAbs_.data() + (size_t)body[side] * kSide;
      const MeReal *J = sideJ(p, r, side);
      for (std::size_t l = 0; l < kSide; l += kPerLanes) {
        const Lanes j = LoadLanes16(J + l);
        if constexpr (Plain) StoreLanes16(g + l, LoadLanes16(g + l) + j * xr);
        if constexpr (Absolute) StoreLanes16(gAbs + l, LoadLanes16(gAbs + l) + magnitudes<true>(j) * xrAbs);
      }
    }
  }
  for (int b = 0; b < p.bodyCount; ++b) {
    const MeReal *columns = &columns_[(size_t)b * 12];
    const size_t at = (size_t)b * kSide;
    if constexpr (Plain) applyInverseMass<false>(p.invMass[(size_t)b], columns, &g_[at], &u_[at]);
    if constexpr (Absolute) applyInverseMass<true>(p.invMass[(size_t)b], columns, &gAbs_[at], &uAbs_[at]);
  }
}

// Inlined into the loops over rows that call it (a call per row cost as
// much as the row's arithmetic).
template <bool Absolute>
[[gnu::always_inline]] inline MeReal BodySpaceOperator::rowDot(int r, const MeReal *u) const {
  const BodySpaceProblem &p = *p_;
  const int body[2] = {p.body0[(size_t)r], p.body1[(size_t)r]};
  MeReal sum = 0;
  for (int side = 0; side < 2; ++side) {
    if (body[side] < 0) continue;
    const MeReal *J = sideJ(p, r, side);
    const MeReal *ub = &u[(size_t)body[side] * kSide];
    MeReal t[kSide];
    for (std::size_t l = 0; l < kSide; l += kPerLanes)
      StoreLanes16(t + l, magnitudes<Absolute>(LoadLanes16(J + l)) * LoadLanes16(ub + l));
    const MeReal d = (t[0] + t[1] + t[2]) + (t[3] + t[4] + t[5]);
    sum = side == 0 ? d : sum + d;
  }
  return sum;
}

void BodySpaceOperator::times(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const {
  prepare();
  gather<true, false>(x);
  for (std::size_t a = 0; a < count; ++a) {
    const int r = rows ? rows[a] : (int)a;
    y[a] = rowDot<false>(r, u_.data()) + p_->softness[(size_t)r] * x[r];
  }
}

MeReal BodySpaceOperator::absTimesMax(const int *rows, std::size_t count, const MeReal *x) const {
  prepare();
  gather<false, true>(x);
  MeReal largest = 0;
  for (std::size_t a = 0; a < count; ++a) {
    const int r = rows ? rows[a] : (int)a;
    largest = std::max(largest, rowDot<true>(r, uAbs_.data()) + std::fabs(p_->softness[(size_t)r] * x[r]));
  }
  return largest;
}

MeReal BodySpaceOperator::timesAndAbsTimesMax(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const {
  prepare();
  gather<true, true>(x);
  MeReal largest = 0;
  for (std::size_t a = 0; a < count; ++a) {
    const int r = rows ? rows[a] : (int)a;
    const MeReal softX = p_->softness[(size_t)r] * x[r];
    y[a] = rowDot<false>(r, u_.data()) + softX;
    largest = std::max(largest, rowDot<true>(r, uAbs_.data()) + std::fabs(softX));
  }
  return largest;
}

}  // namespace karma::mdt
