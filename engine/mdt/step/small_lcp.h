// small_lcp.h: an exact solver for a handful of rows bounded below, used
// for the rows of one contact face (PGS blocks, bounces). Not installed.
//
// Given A (k x k, symmetric positive definite, row stride kSmallLcpMax),
// q and lower bounds lo, it finds x with
//     w = A x - q >= 0,  x >= lo,  x_i > lo_i => w_i = 0,
// by trying the free sets from the largest down (a fixed order: most free
// rows first, then by bit pattern, highest first). A being positive
// definite the answer is unique, and the first set that fits is it.
// Returns false when no set fits (rounding on a near-singular A): the
// caller then falls back to one row at a time.
#pragma once

#include "MePrecision.h"

namespace karma::mdt {

inline constexpr int kSmallLcpMax = 4;

bool SolveSmallLcp(const MeReal *A, const MeReal *q, const MeReal *lo, int k, MeReal *x);

// The elimination of the set with every row free, which depends on A
// alone: made once for a block that is solved many times (a PGS sweep
// visits each contact face once), it leaves a solve whose answer has every
// row free (a face at rest) only the right-hand side's work. The arithmetic
// and its order are SolveSmallLcp's, so the answers are bit-identical.
struct SmallLcpFullSet {
  bool ok = false;                                  // every pivot positive
  MeReal m[kSmallLcpMax][kSmallLcpMax] = {};        // pivots and U above, multipliers below
  MeReal inverse[kSmallLcpMax][kSmallLcpMax] = {};  // A^-1 (when ok), column c from the elimination of e_c
};
void EliminateSmallLcpFullSet(const MeReal *A, int k, SmallLcpFullSet &full);
// SolveSmallLcp with the full set's elimination made by
// EliminateSmallLcpFullSet on the same A.
bool SolveSmallLcp(const MeReal *A, const SmallLcpFullSet &full, const MeReal *q, const MeReal *lo, int k, MeReal *x);
// SolveSmallLcp for a caller that has found the set with every row free
// not to fit: from the free set `guess` (a bit per row), a few block
// pivots (every row moved to the set its answer wants) before the fixed
// order. The answer being unique, the guess changes only how many sets are
// tried (a good one: the rows the all-free answer left above their bound).
bool SolveSmallLcpAfterFull(const MeReal *A, const MeReal *q, const MeReal *lo, int k, unsigned guess, MeReal *x);

}  // namespace karma::mdt
