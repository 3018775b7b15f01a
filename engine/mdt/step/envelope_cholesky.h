// envelope_cholesky.h: a symmetric positive definite matrix stored in its
// envelope (row i holds columns first[i] .. i), factorised in place by
// Cholesky, K = L L^T, and solved. Not installed.
//
// Invariant: first[i] <= i, and first is what the caller laid out; the
// factor L has no entry left of first[i] in row i (fill stays inside the
// envelope), so a banded or chain-ordered K costs time linear in its rows.
#pragma once

#include <span>

#include "MePrecision.h"

namespace karma::mdt {

struct EnvelopeMatrix {
  std::span<int> first;     // per row, its first stored column
  std::span<int> start;     // per row, where it starts in value; start[n] = the total
  std::span<MeReal> value;  // rows one after the other, columns first[i] .. i
  int size() const { return (int)first.size(); }
  MeReal &at(int i, int j) { return value[(size_t)(start[(size_t)i] + j - first[(size_t)i])]; }
};

// Replaces K's lower triangle by L; false if a pivot L_ii^2 is not finite
// or not above 64 eps of K_ii (rows that the ones before cancel to
// rounding, as Kea's envelope LDL^T refuses; K is then partly overwritten).
bool envelopeCholesky(EnvelopeMatrix &K);
// Solves L L^T x = b in place, with L from envelopeCholesky.
void envelopeCholeskySolve(EnvelopeMatrix &L, std::span<MeReal> b);

}  // namespace karma::mdt
