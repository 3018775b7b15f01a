// problem.h: the body-space problem of one partition, what every partition
// solver receives (partition_solver.h). Not installed.
//
// Bodies 0..bodyCount-1 of the partition; rows 0..rowCount-1. Row i acts on
// body0[i] and body1[i] (-1: the world) through its Jacobian blocks
// J[i] = (lin0, ang0, lin1, ang1), and asks for impulses lambda with
//
//     A lambda - rhs = w,   A = J M^-1 J^T + diag(softness),
//     lo_i <= lambda_i <= hi_i, complementary to w_i (kea_lcp.h),
//     friction rows (friction[i] = j >= 0): |lambda_i| <= mu_i * lambda_j,
//
// where M^-1 is block diagonal: invMass[b] I and the world-frame inverse
// inertia invInertia[b] (3 x 3, row-major) of each body, and rhs = speed -
// J v* with v* the velocities predicted from the forces. The bounds are
// impulses (force bounds times h), +-MEINFINITY for none. `warm` is where a
// solver should start: last step's impulses, 0 for new rows.
// The arrays are spans into the step arena, valid during the solve.
//
// J is stored per row side in kSideValues values (linear xyz, angular xyz,
// two zeros: whole 16-byte lanes), side 0 then side 1. It holds what the
// row gave on both sides, a side without a body included: no reader takes
// a value from that side (PGS and the bounces multiply it by zeros).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "MePrecision.h"

namespace karma::mdt {

struct BodySpaceProblem {
  // Names the partition from one step to the next (its first body's
  // address; 0 for none), so that a solver may keep memory per partition
  // (solver_kea.cpp keeps a factorisation). Only a hint: two steps'
  // partitions with the same identity need not have the same rows.
  std::uintptr_t identity = 0;
  int bodyCount = 0;
  int rowCount = 0;
  // Per body.
  std::span<const MeReal> invMass;     // bodyCount
  std::span<const MeReal> invInertia;  // 9 * bodyCount
  // Per row.
  std::span<const int> body0, body1;  // body index or -1
  std::span<const MeReal> J;          // kRowValues * rowCount (see above)
  std::span<const MeReal> rhs, softness, lo, hi;
  std::span<const int> friction;  // normal row index or -1
  std::span<const MeReal> mu;
  std::span<const MeReal> warm;
  // The contact normal rows of one contact group, or of one stand-alone
  // contact, form a block: rows normalBlock[b] .. normalBlock[b+1]-1 of
  // normalRows (ascending row indices). A solver may treat a block as one
  // unit (the contacts of a face share the load symmetrically).
  std::span<const int> normalBlock;  // blockCount + 1
  std::span<const int> normalRows;
  int blockCount = 0;
  bool anyFriction = false;
  bool anyWarm = false;  // a warm value is nonzero
  // When >= 0: every J value (softness value) is finite and at most this
  // in magnitude (the caller scanned the rows: collect_rows.cpp), so the
  // operator need not scan them again (body_space_operator.h). < 0: not
  // known. The operator takes them when both are given, else scans both;
  // a NaN given is taken, and refuses the operator.
  MeReal largestJ = -1, largestSoftness = -1;
};

// Values per row side and per row in J.
inline constexpr std::size_t kSideValues = 8;
inline constexpr std::size_t kRowValues = 2 * kSideValues;

// Row `row`'s J on `side` (six values: linear, angular).
inline const MeReal *sideJ(const BodySpaceProblem &p, int row, int side) {
  return &p.J[(size_t)row * kRowValues + (size_t)side * kSideValues];
}

// M_b^-1 J^T of one row side on body b: invMass J_lin and invInertia J_ang
// (3 x 3, row-major), each component summed left to right.
inline void SideMinvJt(MeReal invMass, const MeReal invInertia[9], const MeReal J[6], MeReal out[6]) {
  for (int k = 0; k < 3; ++k) out[k] = invMass * J[k];
  for (int r = 0; r < 3; ++r)
    out[3 + r] = invInertia[r * 3] * J[3] + invInertia[r * 3 + 1] * J[4] + invInertia[r * 3 + 2] * J[5];
}

// SideMinvJt of row `row`'s `side`, which must have a body.
inline void sideMinvJt(const BodySpaceProblem &p, int row, int side, MeReal out[6]) {
  const int b = side == 0 ? p.body0[(size_t)row] : p.body1[(size_t)row];
  SideMinvJt(p.invMass[(size_t)b], &p.invInertia[(size_t)b * 9], sideJ(p, row, side), out);
}

}  // namespace karma::mdt
