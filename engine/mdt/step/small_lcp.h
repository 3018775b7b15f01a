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

}  // namespace karma::mdt
