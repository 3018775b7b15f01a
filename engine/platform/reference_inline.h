/* reference_inline.h: the reference arithmetic as inline functions (not
 * installed): the per-row three-vector operations of the step's assembly,
 * and the definition of the array kernels (kernels.h), from which
 * reference.cpp builds its table. Every backend's kernel gives these
 * functions' bits, so a caller may call them directly (as kernels.h's
 * dispatch does for short arrays) without changing a result. */
#ifndef KARMA_PLATFORM_REFERENCE_INLINE_H
#define KARMA_PLATFORM_REFERENCE_INLINE_H

#include "MePrecision.h"

namespace karma::platform {

/* Partial sums of every reduction (kernels.h). */
inline constexpr int kLanes = 8;

}  // namespace karma::platform

namespace karma::platform::reference {

inline void BodyMinvJt(MeReal invMass, const MeReal invInertiaWorld[3][3], const MeReal jl[3], const MeReal ja[3],
                       MeReal outLin[3], MeReal outAng[3]) {
  outLin[0] = jl[0] * invMass;
  outLin[1] = jl[1] * invMass;
  outLin[2] = jl[2] * invMass;
  for (int r = 0; r < 3; ++r) {
    const MeReal *row = invInertiaWorld[r];
    outAng[r] = row[0] * ja[0] + row[1] * ja[1] + row[2] * ja[2];
  }
}

inline MeReal RowPairEntry(const MeReal jl_i[3], const MeReal ja_i[3], const MeReal minvJtLin_j[3],
                           const MeReal minvJtAng_j[3]) {
  const MeReal lin = jl_i[0] * minvJtLin_j[0] + jl_i[1] * minvJtLin_j[1] + jl_i[2] * minvJtLin_j[2];
  const MeReal ang = ja_i[0] * minvJtAng_j[0] + ja_i[1] * minvJtAng_j[1] + ja_i[2] * minvJtAng_j[2];
  return lin + ang;
}

/* The partial sums of a reduction combined in the order kernels.h defines. */
inline MeReal LaneSum(const MeReal s[kLanes]) {
  return ((s[0] + s[4]) + (s[2] + s[6])) + ((s[1] + s[5]) + (s[3] + s[7]));
}

/* Adds the terms k = first .. n-1 of a reduction, first a multiple of
 * kLanes and n - first < kLanes, into their partial sums (term k into
 * s[k - first] = s[k mod kLanes]): the tail a vector loop leaves. */
inline void AddTail(const MeReal *a, const MeReal *b, int first, int n, MeReal s[kLanes]) {
  for (int l = 0; l < n - first; ++l) s[l] += a[first + l] * b[first + l];
}

inline void AddGatherTail(const MeReal *value, const int *index, const MeReal *x, int first, int n, MeReal s[kLanes]) {
  for (int l = 0; l < n - first; ++l) s[l] += value[first + l] * x[index[first + l]];
}

inline MeReal Dot(const MeReal *a, const MeReal *b, int n) {
  MeReal s[kLanes] = {};
  int k = 0;
  for (; k + kLanes <= n; k += kLanes)
    for (int l = 0; l < kLanes; ++l) s[l] += a[k + l] * b[k + l];
  AddTail(a, b, k, n, s);
  return LaneSum(s);
}

inline MeReal GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  MeReal s[kLanes] = {};
  int k = 0;
  for (; k + kLanes <= n; k += kLanes)
    for (int l = 0; l < kLanes; ++l) s[l] += value[k + l] * x[index[k + l]];
  AddGatherTail(value, index, x, k, n, s);
  return LaneSum(s);
}

}  // namespace karma::platform::reference

#endif
