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
#pragma once

#include <span>

#include "MePrecision.h"

namespace karma::mdt {

struct BodySpaceProblem {
  int bodyCount = 0;
  int rowCount = 0;
  // Per body.
  std::span<const MeReal> invMass;            // bodyCount
  std::span<const MeReal> invInertia;         // 9 * bodyCount
  // Per row.
  std::span<const int> body0, body1;          // body index or -1
  std::span<const MeReal> J;                  // 12 * rowCount: lin0 ang0 lin1 ang1
  std::span<const MeReal> rhs, softness, lo, hi;
  std::span<const int> friction;              // normal row index or -1
  std::span<const MeReal> mu;
  std::span<const MeReal> warm;
  // The contact normal rows of one contact group, or of one stand-alone
  // contact, form a block: rows normalBlock[b] .. normalBlock[b+1]-1 of
  // normalRows (ascending row indices). A solver may treat a block as one
  // unit (the contacts of a face share the load symmetrically).
  std::span<const int> normalBlock;           // blockCount + 1
  std::span<const int> normalRows;
  int blockCount = 0;
  bool anyFriction = false;
  bool anyWarm = false;                       // a warm value is nonzero
};

}  // namespace karma::mdt
