// body_space_operator.h: the body-space problem's matrix (problem.h)
//     A = J M^-1 J^T + diag(softness)
// applied to a vector without forming it, as Kea's SparseLcpOperator
// (kea_lcp.h). Not installed.
//
// A product goes through the bodies: each body gathers its rows'
//     g_b = sum over rows r on b, ascending, of J_r,b^T x_r
// (six values), takes u_b = M_b^-1 g_b (the linear part invMass g_lin,
// the angular part as SideMinvJt in problem.h multiplies I^-1 by a
// vector), and each asked-for row reads its bodies back:
//     y_r = (J_r,b0 . u_b0 + J_r,b1 . u_b1) + softness_r x_r,
// each six-term dot as (three linear terms) + (three angular terms), a
// side without a body left out. That is about 24 multiply-adds a row and
// a dozen a body, where the assembled matrix's row holds one entry per row
// sharing a body (36 in a stacked box's contact row), and it needs no
// entry of A: a solve that ends on a kept factor (Kea's stale solves)
// never assembles A. M^-1 is applied once per body and product, not once
// per row side: nothing per row is made before the first product.
//
// absTimesMax is the same computation on absolute values, (|J| (|M^-1|
// (|J|^T |x|)))_r + |softness_r x_r|: it bounds sum_j |A_ij| |x_j| (each
// |A_ij| is at most the sum over the shared bodies of |J_i,b| |M_b^-1|
// |J_j,b|^T) and the rounding of times, which rounds those same terms.
//
// Finite entries (entriesFinite, kea_lcp.h): every input is finite, and
//     12 max|J| (max|J| max_b w_b) + max softness <= half the largest MeReal,
// with w_b = max(1/m_b, 3 max|I_b^-1|): each component of M_b^-1 J^T (as
// the assembly of A forms it) is at most w_b max|J| (also kept within half
// the range), and an entry of A sums at most 12 products |J_i,b,c|
// |(M_b^-1 J_j,b^T)_c| (two shared
// bodies, six components) and the softness; the half leaves room for
// rounding. A body flung to the edge of the range breaks it, and Kea then
// assembles A and checks it.
//
// max|J| and max softness are the problem's largestJ and largestSoftness
// when it gives both (upper bounds are enough: the test is one-sided;
// a debug build checks them against the scan they spare), else the
// largest over the row sides with a body and over the rows, found with
// their finiteness in one pass.
//
// Lazy: the bodies' inverse inertia by columns and the bound are made at
// the first call that needs them, so a solve that assembles A first (no
// kept factor) pays nothing here.
//
// assemble() is the caller's: the operator does not own A's layout.
#pragma once

#include <span>

#include "arena.h"
#include "kea_lcp.h"
#include "problem.h"

namespace karma::mdt {

class BodySpaceOperator : public kea::SparseLcpOperator {
 public:
  // p must outlive the operator; its scratch comes from the arena.
  BodySpaceOperator(const BodySpaceProblem &p, StepArena &arena);

  // Values per body in the operator's sums: linear xyz, angular xyz, two
  // zeros (whole vector lanes), as a row side in the problem.
  static constexpr std::size_t kSide = kSideValues;

  void times(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const override;
  MeReal absTimesMax(const int *rows, std::size_t count, const MeReal *x) const override;
  // Both in one pass over the rows and bodies: the same bits as the two.
  MeReal timesAndAbsTimesMax(const int *rows, std::size_t count, const MeReal *x, MeReal *y) const override;
  bool entriesFinite() const override;

 protected:
  BodySpaceOperator(const BodySpaceOperator &) = default;
  ~BodySpaceOperator() = default;

 private:
  // The scratch, columns_ and entriesFinite_, once.
  void prepare() const;
  // u_ = M^-1 (the per-body sums of the rows' J^T x) when Plain, uAbs_ the
  // same of absolute values when Absolute, in one pass over the rows.
  template <bool Plain, bool Absolute>
  void gather(const MeReal *x) const;
  // Row r's (|J|) . u over its bodies, u kSide values per body (u_ or
  // uAbs_).
  template <bool Absolute>
  MeReal rowDot(int r, const MeReal *u) const;

  const BodySpaceProblem *p_;
  StepArena *arena_;
  mutable std::span<MeReal> columns_;      // per body, its I^-1 by columns, each padded to four values
  mutable std::span<MeReal> g_, u_;        // kSide per body: the sums J^T x, and M^-1 times them
  mutable std::span<MeReal> gAbs_, uAbs_;  // the same of absolute values
  mutable bool prepared_ = false, entriesFinite_ = false;
};

}  // namespace karma::mdt
